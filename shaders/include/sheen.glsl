// KHR_materials_sheen: a retro-reflective "cloth" layer over the material, shared by the
// rasterizer (forward.frag) and the path tracer (pt.rchit, pt.rgen). As the
// extension's specification: the Charlie distribution (Estevez and Kulla 2017) with its
// fitted Smith visibility, and the material under the sheen scaled by
// 1 - max(sheenColor) * E(n . v) (the Khronos Sample Viewer's form of the
// specification's albedo scaling), E the Charlie directional albedo from the analytic
// fit three.js uses (sheen_albedo: one formula for the rasterizer, with or without an
// environment, and the path tracer, which has no lookup table). The environment lights
// the sheen through the Charlie-prefiltered cube and the Charlie table (ibl_sheen).
//
// Stable functions (the first two with material_ext.glsl included first):
//   GPUSheenBlock sheen_block(uint word)
//   Sheen material_sheen(GPUExtensionIndex e, uv0, uv1)   colour (0 without it), roughness
//   vec3 sheen_times_cos(Sheen s, vec3 n, vec3 v, vec3 l)  the sheen BRDF x cos
//   float sheen_albedo(float roughness, float n_dot_v)     E, the directional albedo
//   vec3 sheen_over(Sheen s, vec3 n, vec3 v, vec3 under, vec3 sheen)  the layering
//   vec3 sheen_environment(Sheen s, vec3 n, vec3 v)        (with ibl.glsl)
// Needs brdf.glsl.
#ifndef SHERPA_SHEEN_GLSL
#define SHERPA_SHEEN_GLSL
#include "brdf.glsl"
#include "charlie.glsl" // ibl_d_charlie, ibl_v_charlie

struct Sheen {
    vec3 color;      // sheenColorFactor x sheenColorTexture.rgb; black: no sheen
    float roughness; // sheenRoughnessFactor x sheenRoughnessTexture.a (perceptual)
};

float max3(vec3 c) { return max(max(c.r, c.g), c.b); }

#ifdef SHERPA_MATERIAL_EXT_GLSL
GPUSheenBlock sheen_block(uint word) {
    uvec4 t = material_ext[word + 1u];
    return GPUSheenBlock(uintBitsToFloat(material_ext[word]), t.x, t.y, t.z, t.w, transform_words(word + 2u),
                         transform_words(word + 4u));
}

Sheen material_sheen(GPUExtensionIndex e, vec2 uv0, vec2 uv1) {
    Sheen s = Sheen(vec3(0.0), 0.0);
    if (e.sheen == NO_EXTENSION) return s;
    GPUSheenBlock k = sheen_block(e.sheen);
    s.color = k.factors.rgb;
    if (k.color_tex != TEX_WHITE) s.color *= sample_transformed(k.color_uv, k.color_tex, uv0, uv1).rgb;
    s.roughness = k.factors.a;
    if (k.roughness_tex != TEX_WHITE) s.roughness *= sample_transformed(k.roughness_uv, k.roughness_tex, uv0, uv1).a;
    return s;
}
#endif

vec3 sheen_times_cos(Sheen s, vec3 n, vec3 v, vec3 l) {
    float n_dot_l = dot(n, l);
    if (max3(s.color) <= 0.0 || n_dot_l <= 0.0) return vec3(0.0);
    float n_dot_v = clamp(abs(dot(n, v)), 1e-4, 1.0);
    float n_dot_h = clamp(dot(n, normalize(l + v)), 0.0, 1.0);
    float a = max(s.roughness * s.roughness, 1e-4);
    return s.color * ibl_d_charlie(n_dot_h, a) * ibl_v_charlie(n_dot_l, n_dot_v, a) * n_dot_l;
}

// The Charlie sheen's directional albedo at n . v: the fit of three.js's IBLSheenBRDF.
float sheen_albedo(float roughness, float n_dot_v) {
    float r = clamp(roughness, 0.0, 1.0), r2 = r * r, x = clamp(n_dot_v, 0.0, 1.0);
    float a = r < 0.25 ? -339.2 * r2 + 161.4 * r - 25.9 : -8.48 * r2 + 14.3 * r - 9.95;
    float b = r < 0.25 ? 44.0 * r2 - 23.7 * r + 3.26 : 1.97 * r2 - 3.27 * r + 0.72;
    float dg = exp(a * x + b) + (r < 0.25 ? 0.0 : 0.1 * (r - 0.25));
    return clamp(dg / PI, 0.0, 1.0);
}

// `under`: the light of the material below the sheen; `sheen`: the sheen's own.
vec3 sheen_over(Sheen s, vec3 n, vec3 v, vec3 under, vec3 sheen) {
    if (max3(s.color) <= 0.0) return under;
    return under * (1.0 - max3(s.color) * sheen_albedo(s.roughness, dot(n, v))) + sheen;
}

#ifdef SHERPA_IBL_GLSL
vec3 sheen_environment(Sheen s, vec3 n, vec3 v) {
    return ibl_sheen(n, v, s.color, clamp(s.roughness, 0.0, 1.0), float(textureQueryLevels(ibl_sheen_cube)));
}
#endif
#endif
