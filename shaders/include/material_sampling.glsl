// Material inputs of one fragment. Each texture is sampled only when the view needs
// it, and never when the slot holds a default texture: the branch is uniform per
// draw (the material comes from push constants), so a CPU rasterizer such as
// lavapipe skips the sampling entirely instead of paying for a filtered fetch.
#ifndef SHERPA_MATERIAL_SAMPLING_GLSL
#define SHERPA_MATERIAL_SAMPLING_GLSL
const uint TEX_WHITE = 0u;
const uint TEX_FLAT_NORMAL = 1u;
const uint TEX_BLACK = 2u;

vec4 base_color(GPUMaterialData m, GPUMaterialExtra x, vec4 vertex_color, vec2 uv0, vec2 uv1) {
    vec4 c = m.base_color_factor * vertex_color;
    if (m.base_color_tex != TEX_WHITE) c *= sample_slot(x, SLOT_BASE_COLOR, m.base_color_tex, uv0, uv1);
    return c;
}

// x: metallic, y: roughness.
vec2 metallic_roughness(GPUMaterialData m, GPUMaterialExtra x, vec2 uv0, vec2 uv1) {
    vec2 mr = vec2(m.metallic_factor, m.roughness_factor);
    if (m.metallic_roughness_tex != TEX_WHITE)
        mr *= sample_slot(x, SLOT_METALLIC_ROUGHNESS, m.metallic_roughness_tex, uv0, uv1).bg;
    return clamp(mr, 0.0, 1.0);
}

float occlusion(GPUMaterialData m, GPUMaterialExtra x, vec2 uv0, vec2 uv1) {
    if (m.occlusion_tex == TEX_WHITE) return 1.0;
    float ao = sample_slot(x, SLOT_OCCLUSION, m.occlusion_tex, uv0, uv1).r;
    return 1.0 + m.occlusion_strength * (ao - 1.0);
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
    vec2 xy = sample_slot(x, SLOT_NORMAL, m.normal_tex, uv0, uv1).xy * 2.0 - 1.0;
    vec3 tn = vec3(xy * m.normal_scale, sqrt(max(0.0, 1.0 - dot(xy, xy))));
    return normalize(mat3(t, b, n) * tn);
}
#endif
