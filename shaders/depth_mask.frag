#version 460
#extension GL_GOOGLE_include_directive : require
// Alpha test for MASK materials in depth-only passes.
#include "common.glsl"
#include "bindings.glsl"

layout(location = 0) in vec2 in_uv;

void main() {
    GPUMaterialData m = materials[pc.material_id];
    float alpha = m.base_color_factor.a * texture(textures[m.base_color_tex], in_uv).a;
    if (alpha < m.alpha_cutoff) discard;
}
