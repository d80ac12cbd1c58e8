// Descriptor set 0: the cascaded shadow map and the bindless texture array. The
// first three textures are the defaults (white, flat normal, black) that stand in
// for absent material textures.
#ifndef SHERPA_BINDINGS_GLSL
#define SHERPA_BINDINGS_GLSL
layout(set = 0, binding = 0) uniform sampler2DArrayShadow shadow_map;
layout(set = 0, binding = 1) uniform sampler2D textures[];

vec4 sample_slot(GPUMaterialExtra extra, uint slot, uint tex, vec2 uv0, vec2 uv1) {
    return texture(textures[tex], transform_uv(extra.uv[slot], uv0, uv1));
}
#endif
