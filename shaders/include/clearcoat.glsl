// KHR_materials_clearcoat: a clear dielectric coat (F0 0.04, F90 1) over the material,
// shared by the rasterizer (forward.frag) and the path tracer (pt.rchit, pt.rgen).
// Layering as the extension's specification, in the form three.js and the Khronos
// Sample Viewer evaluate it: everything under the coat (the base's light and its
// emission) is weighted by 1 - clearcoat * Fc(n_c . v), Fc the coat's Schlick Fresnel
// at the view, and the coat's own GGX specular (its roughness, its normal) is added
// times clearcoat.
//
// Stable functions (the first two with material_ext.glsl included first):
//   GPUClearcoatBlock clearcoat_block(uint word)
//   Clearcoat material_clearcoat(GPUExtensionIndex e, t, b, n, uv0, uv1)
//        the coat at a point: factor (0 without the extension), roughness, normal (the
//        geometry's n, or its own normal map in the frame t, b, n)
//   float clearcoat_fresnel(Clearcoat c, vec3 v)          Fc at n_c . v
//   float clearcoat_times_cos(Clearcoat c, vec3 v, vec3 l) the coat's specular BRDF x cos
//   vec3 clearcoat_over(Clearcoat c, vec3 v, vec3 under, vec3 coat)  the layering
//   vec3 clearcoat_environment(Clearcoat c, vec3 v)        the coat lit by the environment
//        (split-sum GGX at the coat's roughness; with ibl.glsl included first)
//   vec3 clearcoat_ambient(Clearcoat c, vec3 v, vec3 radiance)  ... by the sky/ground term
// The path tracer's layered BSDF (evaluation, density, sampling) is layered_bsdf.glsl.
// Needs brdf.glsl.
#ifndef SHERPA_CLEARCOAT_GLSL
#define SHERPA_CLEARCOAT_GLSL
#include "brdf.glsl"

const float CLEARCOAT_F0 = 0.04; // the coat's ior, 1.5, against air

struct Clearcoat {
    float factor;    // clearcoatFactor x clearcoatTexture.r; 0: no coat
    float roughness; // perceptual: clearcoatRoughnessFactor x clearcoatRoughnessTexture.g
    vec3 n;          // the coat's shading normal, unit
};

#ifdef SHERPA_MATERIAL_EXT_GLSL
GPUClearcoatBlock clearcoat_block(uint word) {
    uvec4 t = material_ext[word + 1u];
    return GPUClearcoatBlock(uintBitsToFloat(material_ext[word]), t.x, t.y, t.z, t.w, transform_words(word + 2u),
                             transform_words(word + 4u), transform_words(word + 6u));
}

// `n` is the shading frame's normal before the base's normal map: the spec's coat
// without clearcoatNormalTexture is not normal-mapped.
Clearcoat material_clearcoat(GPUExtensionIndex e, vec3 t, vec3 b, vec3 n, vec2 uv0, vec2 uv1) {
    Clearcoat c = Clearcoat(0.0, 0.0, n);
    if (e.clearcoat == NO_EXTENSION) return c;
    GPUClearcoatBlock k = clearcoat_block(e.clearcoat);
    c.factor = k.factors.x;
    if (k.clearcoat_tex != TEX_WHITE) c.factor *= sample_transformed(k.clearcoat_uv, k.clearcoat_tex, uv0, uv1).r;
    c.roughness = k.factors.y;
    if (k.roughness_tex != TEX_WHITE)
        c.roughness *= sample_transformed(k.roughness_uv, k.roughness_tex, uv0, uv1).g;
    if (k.normal_tex != TEX_FLAT_NORMAL) {
        // As mapped_normal (material_sampling.glsl): z from unit length, scale on x, y.
        vec2 xy = sample_transformed(k.normal_uv, k.normal_tex, uv0, uv1).xy * 2.0 - 1.0;
        vec3 tn = vec3(xy * k.factors.z, sqrt(max(0.0, 1.0 - dot(xy, xy))));
        c.n = normalize(mat3(t, b, n) * tn);
    }
    return c;
}
#endif

float clearcoat_fresnel(Clearcoat c, vec3 v) {
    return CLEARCOAT_F0 + (1.0 - CLEARCOAT_F0) * pow5(1.0 - clamp(dot(c.n, v), 0.0, 1.0));
}

// GGX with the coat's Fresnel at v . h, for unit radiance from l.
float clearcoat_times_cos(Clearcoat c, vec3 v, vec3 l) {
    float n_dot_l = dot(c.n, l);
    if (c.factor <= 0.0 || n_dot_l <= 0.0) return 0.0;
    vec3 h = normalize(l + v);
    float n_dot_v = clamp(abs(dot(c.n, v)), 1e-4, 1.0);
    float n_dot_h = clamp(dot(c.n, h), 0.0, 1.0);
    float v_dot_h = clamp(dot(v, h), 0.0, 1.0);
    float a = max(c.roughness * c.roughness, 1e-3);
    float f = CLEARCOAT_F0 + (1.0 - CLEARCOAT_F0) * pow5(1.0 - v_dot_h);
    return f * d_ggx(n_dot_h, a) * v_smith_ggx(n_dot_l, n_dot_v, a) * n_dot_l;
}

// `under`: the light leaving the material below the coat (its emission included);
// `coat`: the light the coat reflects (clearcoat_times_cos, clearcoat_environment).
vec3 clearcoat_over(Clearcoat c, vec3 v, vec3 under, vec3 coat) {
    if (c.factor <= 0.0) return under;
    return under * (1.0 - c.factor * clearcoat_fresnel(c, v)) + c.factor * coat;
}

vec3 clearcoat_ambient(Clearcoat c, vec3 v, vec3 radiance) {
    vec3 r = reflect(-v, c.n);
    return clearcoat_fresnel(c, v) * hemisphere(normalize(mix(r, c.n, c.roughness * c.roughness)), radiance);
}

#ifdef SHERPA_IBL_GLSL
vec3 clearcoat_environment(Clearcoat c, vec3 v) {
    float n_dot_v = clamp(dot(c.n, v), 1e-4, 1.0);
    float roughness = clamp(c.roughness, 0.0, 1.0);
    vec3 lut = ibl_brdf_lut(n_dot_v, roughness);
    return (CLEARCOAT_F0 * lut.r + lut.g) * ibl_specular(reflect(-v, c.n), roughness);
}
#endif

#endif
