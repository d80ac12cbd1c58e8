// Image-based lighting in the raster shaders: the environment's prefiltered cubes and
// lookup tables (set 1, bindings 4-7, written by EnvironmentMap, environment_map.cpp;
// partially bound: nothing is bound, and nothing read, without an environment).
// Split-sum specular (GGX), Lambertian irradiance, and multiple-scattering energy
// compensation (Fdez-Aguera 2019, as three.js's computeMultiscattering), switchable.
// Material extensions read the same maps: ibl_sheen() (Charlie) for sheen, ibl_specular()
// at a roughness for clearcoat and transmission.
#ifndef SHERPA_IBL_GLSL
#define SHERPA_IBL_GLSL
layout(set = 1, binding = 4) uniform samplerCube ibl_specular_cube;
layout(set = 1, binding = 5) uniform samplerCube ibl_irradiance_cube;
layout(set = 1, binding = 6) uniform sampler2D ibl_lut; // r, g GGX scale, bias; b Charlie albedo
layout(set = 1, binding = 7) uniform samplerCube ibl_sheen_cube;
// KHR_materials_anisotropy's table (ibl_lut_anisotropic.comp): bound only while the scene
// has an anisotropic material, so read only for surfaces with an anisotropy strength.
layout(set = 1, binding = 10) uniform sampler2DArray ibl_anisotropic_lut;

bool has_environment() { return frame.environment.y > 0.0; }

// World direction -> the environment's own (its rotation about +Y undone).
vec3 env_direction(vec3 d) {
    float c = frame.environment.z, s = frame.environment.w;
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

// Radiance arriving along -dir, prefiltered for GGX at perceptual `roughness`.
vec3 ibl_specular(vec3 dir, float roughness) {
    float lod = clamp(roughness, 0.0, 1.0) * (frame.environment.y - 1.0);
    return textureLod(ibl_specular_cube, env_direction(dir), lod).rgb * frame.environment.x;
}

// Irradiance / pi from 9 SH coefficients (environment_sh.h's basis and order) at the
// environment's own direction d.
vec3 sh9_irradiance(vec3 d) {
    vec3 e = frame.irradiance_sh[0].rgb * 0.282095;
    e += frame.irradiance_sh[1].rgb * (0.488603 * d.y);
    e += frame.irradiance_sh[2].rgb * (0.488603 * d.z);
    e += frame.irradiance_sh[3].rgb * (0.488603 * d.x);
    e += frame.irradiance_sh[4].rgb * (1.092548 * d.x * d.y);
    e += frame.irradiance_sh[5].rgb * (1.092548 * d.y * d.z);
    e += frame.irradiance_sh[6].rgb * (0.315392 * (3.0 * d.z * d.z - 1.0));
    e += frame.irradiance_sh[7].rgb * (1.092548 * d.x * d.z);
    e += frame.irradiance_sh[8].rgb * (0.546274 * (d.x * d.x - d.y * d.y));
    return max(e, vec3(0.0)); // ringing below zero is no light
}

// Cosine-weighted mean radiance about n (irradiance / pi): the irradiance cube, or the
// SH9 coefficients where the environment was made with them (IrradianceMode::Sh9).
vec3 ibl_irradiance(vec3 n) {
    vec3 d = env_direction(n);
    if (frame.irradiance_sh[0].w > 0.5) return sh9_irradiance(d) * frame.environment.x;
    return textureLod(ibl_irradiance_cube, d, 0.0).rgb * frame.environment.x;
}

// (GGX scale, GGX bias, Charlie directional albedo) at n.v and perceptual roughness.
vec3 ibl_brdf_lut(float n_dot_v, float roughness) {
    return textureLod(ibl_lut, vec2(n_dot_v, roughness), 0.0).rgb;
}

// The anisotropic GGX's (scale, bias) at n.v, perceptual roughness (alpha_b), strength
// and |cos| of the view's azimuth from the direction: bilinear in (n.v, roughness) by
// the sampler, linear in strength^2 and |cos| between the table's layers (its nodes).
vec2 ibl_brdf_lut_anisotropic(float n_dot_v, float roughness, float strength, float cos_phi) {
    const float STRENGTHS = 8.0, AZIMUTHS = 6.0; // ibl_lut_anisotropic.comp's
    float si = clamp(strength * strength, 0.0, 1.0) * (STRENGTHS - 1.0);
    float ai = clamp(abs(cos_phi), 0.0, 1.0) * (AZIMUTHS - 1.0);
    float s0 = min(floor(si), STRENGTHS - 2.0), a0 = min(floor(ai), AZIMUTHS - 2.0);
    float layer = s0 * AZIMUTHS + a0;
    vec2 uv = vec2(n_dot_v, roughness);
    vec2 e00 = textureLod(ibl_anisotropic_lut, vec3(uv, layer), 0.0).rg;
    vec2 e01 = textureLod(ibl_anisotropic_lut, vec3(uv, layer + 1.0), 0.0).rg;
    vec2 e10 = textureLod(ibl_anisotropic_lut, vec3(uv, layer + AZIMUTHS), 0.0).rg;
    vec2 e11 = textureLod(ibl_anisotropic_lut, vec3(uv, layer + AZIMUTHS + 1.0), 0.0).rg;
    return mix(mix(e00, e01, ai - a0), mix(e10, e11, ai - a0), si - s0);
}

// KHR_materials_anisotropy under the environment (frame.irradiance_sh[1].w, C++
// AnisotropyLighting): 0 the isotropic split-sum along the bent normal (three.js's and
// the Sample Viewer's form), 1 the anisotropic lobe's own albedo with that read, 2 that
// albedo with the radiance of taps spread along the direction.
const float ANISOTROPY_ISOTROPIC = 0.0, ANISOTROPY_ALBEDO = 1.0, ANISOTROPY_LOBE = 2.0;
float anisotropy_lighting() { return frame.irradiance_sh[1].w; }

// The split-sum (scale, bias) of s's GGX: the isotropic table's `iso`, or for
// KHR_materials_anisotropy the anisotropic table's at the view's azimuth.
vec2 ibl_specular_albedo(Surface s, float n_dot_v, float roughness, vec2 iso) {
    if (s.anisotropy.w <= 0.0 || anisotropy_lighting() == ANISOTROPY_ISOTROPIC) return iso;
    vec3 across = s.v - s.n * dot(s.n, s.v); // the view in the tangent plane
    float len = length(across);
    float cos_phi = len > 1e-6 ? dot(anisotropy_direction(s), across) / len : 1.0;
    return ibl_brdf_lut_anisotropic(n_dot_v, roughness, s.anisotropy.w, cos_phi);
}

// The prefiltered radiance s's specular lobe gathers. Isotropic: one read along the
// reflection (for anisotropy about the bent normal, specular_direction). With
// ANISOTROPY_LOBE, four reads along the reflections about half vectors tilted along the
// direction by the quartiles' midpoints (1/8, 3/8, 5/8, 7/8) of GGX's slope distribution
// along one axis (x / a = u / sqrt(1 - u^2), u = 2 F - 1), at the width alpha_t less the
// alpha_b each read's prefilter already spreads; reads below the horizon are left out.
vec3 ibl_specular_radiance(Surface s, float roughness) {
    if (s.anisotropy.w <= 0.0 || anisotropy_lighting() != ANISOTROPY_LOBE)
        return ibl_specular(specular_direction(s), roughness);
    vec3 t = anisotropy_direction(s);
    vec2 a = anisotropic_alpha(s.roughness, s.anisotropy.w);
    const float SLOPES[4] = float[](-1.1339, -0.2582, 0.2582, 1.1339);
    vec3 sum = vec3(0.0);
    float taps = 0.0;
    for (int k = 0; k < 4; ++k) {
        vec3 l = reflect(-s.v, normalize(s.n + (SLOPES[k] * (a.x - a.y)) * t));
        if (dot(l, s.n) <= 0.0) continue;
        sum += ibl_specular(l, roughness);
        taps += 1.0;
    }
    return taps > 0.0 ? sum / taps : ibl_specular(reflect(-s.v, s.n), roughness);
}

// Sheen (KHR_materials_sheen) lit by the environment: Charlie-prefiltered radiance
// times the Charlie directional albedo; `sheen_levels` are ibl_sheen_cube's levels.
vec3 ibl_sheen(vec3 n, vec3 v, vec3 sheen_color, float sheen_roughness, float sheen_levels) {
    float n_dot_v = clamp(dot(n, v), 1e-4, 1.0);
    float lod = clamp(sheen_roughness, 0.0, 1.0) * (sheen_levels - 1.0);
    vec3 radiance = textureLod(ibl_sheen_cube, env_direction(n), lod).rgb * frame.environment.x;
    return sheen_color * ibl_brdf_lut(n_dot_v, sheen_roughness).b * radiance;
}

// Diffuse and specular light from the environment on a metallic-roughness or
// specular-glossiness surface (brdf.glsl's Surface): F0 scales the table's first
// term and F90 its second (KHR_materials_specular's dielectrics have F90 < 1).
vec3 environment_light(Surface s) {
    float n_dot_v = clamp(dot(s.n, s.v), 1e-4, 1.0);
    float roughness = clamp(s.roughness, 0.0, 1.0);
    // KHR_materials_anisotropy: the anisotropic lobe's own albedo (the isotropic
    // table's without it).
    vec2 lut = ibl_specular_albedo(s, n_dot_v, roughness, ibl_brdf_lut(n_dot_v, roughness).rg);
    // KHR_materials_iridescence: the film's equivalent F0 (s.f0 without it).
    vec3 f0 = iridescent_f0(s, n_dot_v);
    vec3 fss_ess = f0 * lut.r + s.f90 * lut.g; // single-scattering specular albedo
    vec3 radiance = ibl_specular_radiance(s, roughness);
    vec3 irradiance = ibl_irradiance(s.n);
    vec3 multi = vec3(0.0);
    if (frame.display.z > 0.0) {
        // The energy GGX loses to single scattering (1 - E_ss) comes back, tinted by the
        // average Fresnel over its bounces, lit by the irradiance.
        float ess = lut.r + lut.g;
        float ems = 1.0 - ess;
        vec3 f_avg = f0 + (1.0 - f0) * 0.047619; // 1/21
        vec3 fms = fss_ess * f_avg / (1.0 - ems * f_avg);
        multi = fms * ems;
    }
    vec3 total = fss_ess + multi;
    vec3 diffuse = s.diffuse * (1.0 - max(max(total.r, total.g), total.b));
    return fss_ess * radiance + (multi + diffuse) * irradiance;
}
#endif
