// Material inputs of one fragment. Each texture is sampled only when the view needs
// it, and never when the slot holds a default texture: the branch is uniform per
// draw (the material comes from push constants), so a CPU rasterizer such as
// lavapipe skips the sampling entirely instead of paying for a filtered fetch.
#ifndef SHERPA_MATERIAL_SAMPLING_GLSL
#define SHERPA_MATERIAL_SAMPLING_GLSL
#include "sherpa_default_textures.glsl" // TEX_WHITE, TEX_FLAT_NORMAL, TEX_BLACK (generated)

vec4 base_color(GPUMaterialData m, GPUMaterialExtra x, vec4 vertex_color, vec2 uv0, vec2 uv1) {
    vec4 c = m.base_color_factor * vertex_color;
    if (m.base_color_tex != TEX_WHITE) c *= sample_slot(x, SLOT_BASE_COLOR, m.base_color_tex, uv0, uv1);
    return c;
}

// The metallic-roughness texel (white when the slot holds the default).
vec4 metallic_roughness_texel(GPUMaterialData m, GPUMaterialExtra x, vec2 uv0, vec2 uv1) {
    if (m.metallic_roughness_tex == TEX_WHITE) return vec4(1.0);
    return sample_slot(x, SLOT_METALLIC_ROUGHNESS, m.metallic_roughness_tex, uv0, uv1);
}

// x: metallic, y: roughness.
vec2 metallic_roughness(GPUMaterialData m, vec4 mr_texel) {
    return clamp(vec2(m.metallic_factor, m.roughness_factor) * mr_texel.bg, 0.0, 1.0);
}

// KHR_materials_pbrSpecularGlossiness: rgb specular (its texture is sampled through
// an sRGB format, as the extension stores it), a glossiness.
vec4 specular_glossiness(GPUMaterialExtra x, vec2 uv0, vec2 uv1) {
    vec4 sg = x.specular_glossiness;
    if (x.specular_glossiness_tex != TEX_WHITE)
        sg *= sample_slot(x, SLOT_SPECULAR_GLOSSINESS, x.specular_glossiness_tex, uv0, uv1);
    return clamp(sg, 0.0, 1.0);
}

bool same_transform(GPUTextureTransform a, GPUTextureTransform b) {
    return a.row0 == b.row0 && a.row1 == b.row1;
}

float occlusion(GPUMaterialData m, GPUMaterialExtra x, vec2 uv0, vec2 uv1) {
    if (m.occlusion_tex == TEX_WHITE) return 1.0;
    float ao = sample_slot(x, SLOT_OCCLUSION, m.occlusion_tex, uv0, uv1).r;
    return 1.0 + m.occlusion_strength * (ao - 1.0);
}

// The same, given the metallic-roughness texel already sampled for this pixel:
// packed occlusion-roughness-metallic textures (the same image and UV transform in
// both slots, as many exporters write them) are sampled once.
float occlusion(GPUMaterialData m, GPUMaterialExtra x, vec2 uv0, vec2 uv1, vec4 mr_texel) {
    if (m.occlusion_tex == m.metallic_roughness_tex && m.occlusion_tex != TEX_WHITE &&
        same_transform(x.uv[SLOT_OCCLUSION], x.uv[SLOT_METALLIC_ROUGHNESS]))
        return 1.0 + m.occlusion_strength * (mr_texel.r - 1.0);
    return occlusion(m, x, uv0, uv1);
}

vec3 emission(GPUMaterialData m, GPUMaterialExtra x, vec2 uv0, vec2 uv1) {
    if (m.emissive_tex == TEX_BLACK) return vec3(0.0);
    vec3 e = m.emissive_factor.rgb * m.emissive_factor.w;
    if (m.emissive_tex != TEX_WHITE) e *= sample_slot(x, SLOT_EMISSIVE, m.emissive_tex, uv0, uv1).rgb;
    return e;
}

// Normal after normal mapping, in the frame (t, b, n).
vec3 mapped_normal(GPUMaterialData m, GPUMaterialExtra x, vec3 t, vec3 b, vec3 n, vec2 uv0, vec2 uv1) {
    if (m.normal_tex == TEX_FLAT_NORMAL) return n;
    // BC5 normal maps hold x and y only: z comes from unit length (RGBA8 maps are
    // read the same way, so both formats shade alike). glTF's scale applies to x, y.
    // The only GLSL copy of sherpa::tex::bc5_normal_z (sherpa/texture/bc5_normal.h).
    vec2 xy = sample_slot(x, SLOT_NORMAL, m.normal_tex, uv0, uv1).xy * 2.0 - 1.0;
    vec3 tn = vec3(xy * m.normal_scale, sqrt(max(0.0, 1.0 - dot(xy, xy))));
    return normalize(mat3(t, b, n) * tn);
}
#endif
