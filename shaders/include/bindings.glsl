// Descriptor set 0: the bindless texture array; set 1 binding 3: the cascaded
// shadow map. The first three textures are the defaults (white, flat normal, black) that stand in
// for absent material textures.
#ifndef SHERPA_BINDINGS_GLSL
#define SHERPA_BINDINGS_GLSL
layout(set = 0, binding = 0) uniform sampler2D textures[];
// In the ordinary set 1, not the update-after-bind bindless set: lavapipe compiles
// sampling code specialised for a statically bound view, several times faster.
layout(set = 1, binding = 3) uniform sampler2DArrayShadow shadow_map;

vec4 sample_slot(GPUMaterialExtra extra, uint slot, uint tex, vec2 uv0, vec2 uv1) {
    return texture(textures[tex], transform_uv(extra.uv[slot], uv0, uv1));
}
#endif
