// KHR_materials_iridescence: a thin dielectric film over the base, whose interference
// colours the base's specular Fresnel; shared by the rasterizer (forward.frag) and the
// path tracer (pt.rchit). The film's Fresnel is the specification's, after Belcour and
// Barla 2017 ("A Practical Extension to Microfacet Theory for the Modeling of Varying
// Iridescence"): the Airy summation over the film's first two inner reflections with
// Schlick's Fresnel at both interfaces, integrated against the CIE colour matching
// functions through their Gaussian fit's Fourier transform, then XYZ -> linear Rec. 709.
// The film's result replaces Schlick's Fresnel in proportion to the iridescence factor,
// evaluated at n . v for every light and for the environment (as the specification's
// sample implementation, three.js and the Khronos Sample Viewer do); the environment's
// split-sum uses the F0 that gives that Fresnel at n . v (Surface::iridescence,
// brdf.glsl's iridescent_f0). Needs brdf.glsl (PI, pow5) included first.
//
// Stable functions:
//   vec3 iridescence_fresnel(float outside_ior, float film_ior, float cos_theta,
//                            float thickness_nm, vec3 base_f0)   the film's Fresnel
//   GPUIridescenceBlock iridescence_block(uint word)            (with material_ext.glsl)
//   vec3 material_iridescence(GPUExtensionIndex e, uv0, uv1)
//        x the factor x texture.r (0 without the extension), y the film's ior, z the
//        thickness in nm
//   vec4 surface_iridescence(GPUExtensionIndex e, uv0, uv1, vec3 base_f0, float n_dot_v)
//        for Surface::iridescence: rgb the film's Fresnel at n . v, a the factor
#ifndef SHERPA_IRIDESCENCE_GLSL
#define SHERPA_IRIDESCENCE_GLSL

// CIE XYZ -> linear Rec. 709 (sRGB primaries, D65), column-major.
const mat3 IRIDESCENCE_XYZ_TO_REC709 = mat3(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259,
                                            -0.4985314, 0.0415560, 1.0572252);

vec3 iridescence_sq(vec3 x) { return x * x; }

// Fresnel at normal incidence between media of indices a and b.
float interface_f0(float a, float b) {
    float r = (a - b) / (a + b);
    return r * r;
}

vec3 interface_f0(vec3 a, float b) {
    return iridescence_sq((a - b) / (a + b));
}

// The index whose F0 against air is f0 (f0 < 1).
vec3 f0_to_ior(vec3 f0) {
    vec3 r = sqrt(clamp(f0, 0.0, 0.9999));
    return (1.0 + r) / (1.0 - r);
}

// The spectral sensitivity's Fourier transform at optical path difference `opd` (nm)
// with phase shift `shift`: the three CIE matching functions as Gaussians (x with a
// second lobe), in XYZ, normalized, then in linear Rec. 709.
vec3 iridescence_sensitivity(float opd, vec3 shift) {
    const float TWO_PI = 6.28318530717959;
    float phase = TWO_PI * opd * 1.0e-9;
    const vec3 amplitude = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const vec3 centre = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const vec3 variance = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
    vec3 xyz = amplitude * sqrt(TWO_PI * variance) * cos(centre * phase + shift) * exp(-phase * phase * variance);
    xyz.x += 9.7470e-14 * sqrt(TWO_PI * 4.5282e+09) * cos(2.2399e+06 * phase + shift.x) *
             exp(-4.5282e+09 * phase * phase);
    return IRIDESCENCE_XYZ_TO_REC709 * (xyz / 1.0685e-7);
}

vec3 iridescence_fresnel(float outside_ior, float film_ior, float cos_theta, float thickness_nm, vec3 base_f0) {
    // A vanishing film fades to no film (its index to the outside's), so thickness 0
    // is the base's own Fresnel.
    float film = mix(outside_ior, film_ior, smoothstep(0.0, 0.03, thickness_nm));
    float sin2_film = (outside_ior / film) * (outside_ior / film) * (1.0 - cos_theta * cos_theta);
    if (sin2_film >= 1.0) return vec3(1.0); // total internal reflection in the film
    float cos_film = sqrt(1.0 - sin2_film);

    // Outside -> film: Schlick's reflectance, its transmittance, and the phase change
    // on reflection (pi where the film is the denser side, seen from inside).
    float r12 = interface_f0(film, outside_ior);
    r12 = r12 + (1.0 - r12) * pow5(clamp(1.0 - cos_theta, 0.0, 1.0));
    float t121 = 1.0 - r12;
    float phi12 = film < outside_ior ? PI : 0.0;
    float phi21 = PI - phi12;

    // Film -> base: the base's index from its F0 (per channel), Schlick at the film's
    // angle, and its phase change.
    vec3 base_ior = f0_to_ior(base_f0);
    vec3 r1 = interface_f0(base_ior, film);
    vec3 r23 = r1 + (1.0 - r1) * pow5(clamp(1.0 - cos_film, 0.0, 1.0));
    vec3 phi23 = vec3(base_ior.x < film ? PI : 0.0, base_ior.y < film ? PI : 0.0, base_ior.z < film ? PI : 0.0);

    // The Airy sum: the direct reflection, then the terms of the first two round trips
    // through the film, each a cosine of its optical path in the spectral sensitivity.
    float opd = 2.0 * film * thickness_nm * cos_film;
    vec3 phi = vec3(phi21) + phi23;
    vec3 r123 = clamp(r12 * r23, 1e-5, 0.9999);
    vec3 r123_root = sqrt(r123);
    vec3 rs = t121 * t121 * r23 / (1.0 - r123);
    vec3 result = r12 + rs;
    vec3 cm = rs - t121;
    for (int m = 1; m <= 2; ++m) {
        cm *= r123_root;
        result += cm * 2.0 * iridescence_sensitivity(float(m) * opd, float(m) * phi);
    }
    return max(result, vec3(0.0));
}

#ifdef SHERPA_MATERIAL_EXT_GLSL
GPUIridescenceBlock iridescence_block(uint word) {
    uvec4 t = material_ext[word + 1u];
    return GPUIridescenceBlock(uintBitsToFloat(material_ext[word]), t.x, t.y, t.z, t.w, transform_words(word + 2u),
                               transform_words(word + 4u));
}

vec3 material_iridescence(GPUExtensionIndex e, vec2 uv0, vec2 uv1) {
    if (e.iridescence == NO_EXTENSION) return vec3(0.0, 1.3, 0.0);
    GPUIridescenceBlock k = iridescence_block(e.iridescence);
    float factor = k.factors.x;
    if (k.texture != TEX_WHITE) factor *= sample_transformed(k.uv, k.texture, uv0, uv1).r;
    float thickness = k.factors.w;
    if (k.thickness_tex != TEX_WHITE)
        thickness = mix(k.factors.z, k.factors.w, sample_transformed(k.thickness_uv, k.thickness_tex, uv0, uv1).g);
    return vec3(factor, k.factors.y, thickness);
}

vec4 surface_iridescence(GPUExtensionIndex e, vec2 uv0, vec2 uv1, vec3 base_f0, float n_dot_v) {
    vec3 i = material_iridescence(e, uv0, uv1);
    // No film (thickness 0) is no iridescence (the specification's and three.js's rule).
    if (i.x <= 0.0 || i.z <= 0.0) return vec4(0.0);
    return vec4(iridescence_fresnel(1.0, i.y, clamp(n_dot_v, 0.0, 1.0), i.z, base_f0), clamp(i.x, 0.0, 1.0));
}
#endif

#endif
