#version 460
#extension GL_GOOGLE_include_directive : require
// Alpha test for MASK materials in depth-only passes (depth prepass, shadow cascades).
// The alpha is forward.frag's, from the same function and inputs (base colour factor x
// vertex colour x texel through its transform, at the frame's texture LOD when one is
// set): a texel that shading discards must not write depth here, or the prepass would
// hide what is behind it and leave the clear colour (and the ray tracer's any-hit,
// which tests the same alpha, would see through where the raster does not).
#include "common.glsl"
#include "bindings.glsl"
#include "material_sampling.glsl"

layout(location = 0) in vec2 in_uv0;
layout(location = 1) in vec2 in_uv1;
layout(location = 2) in vec4 in_color;

void main() {
    GPUMaterialData m = materials[pc.material_id];
    float alpha = base_color(m, material_extras[pc.material_id], in_color, in_uv0, in_uv1).a;
    if (alpha < m.alpha_cutoff) discard;
}
