// Descriptor set 0: the bindless texture array; set 1 binding 3: the cascaded
// shadow map. The first three textures are the defaults (white, flat normal, black) that stand in
// for absent material textures.
#ifndef SHERPA_BINDINGS_GLSL
#define SHERPA_BINDINGS_GLSL
layout(set = 0, binding = 0) uniform sampler2D textures[];
// In the ordinary set 1, not the update-after-bind bindless set: lavapipe compiles
// sampling code specialised for a statically bound view, several times faster.
layout(set = 1, binding = 3) uniform sampler2DArrayShadow shadow_map;

// frame.overlay.z >= 0: every texture at that mip level (render --texture-lod, so
// the ray tracer's explicit LOD and ours sample the same texels); else derivatives.
// A texture through its KHR_texture_transform (and TEXCOORD set).
vec4 sample_transformed(GPUTextureTransform t, uint tex, vec2 uv0, vec2 uv1) {
    vec2 uv = transform_uv(t, uv0, uv1);
    if (frame.overlay.z >= 0.0) return textureLod(textures[tex], uv, frame.overlay.z);
    return texture(textures[tex], uv);
}

vec4 sample_slot(GPUMaterialExtra extra, uint slot, uint tex, vec2 uv0, vec2 uv1) {
    return sample_transformed(extra.uv[slot], tex, uv0, uv1);
}
#endif
