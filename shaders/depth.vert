#version 460
#extension GL_GOOGLE_include_directive : require
// Positions only (plus the UVs and vertex colour for alpha-tested materials): depth
// prepass, shadow cascades, wireframe and the benchmark's floor pass; moving meshes
// skinned and morphed (motion.glsl, MOTION pipelines only).
#include "common.glsl"
#include "motion.glsl"

// depth_mask.frag's inputs: forward.frag's alpha from the same inputs.
layout(location = 0) out vec2 out_uv0;
layout(location = 1) out vec2 out_uv1;
layout(location = 2) out vec4 out_color;

// Identical math to mesh.vert, so the depth prepass and shading agree exactly.
invariant gl_Position;

void main() {
    uint i = uint(gl_VertexIndex);
    GPUInstanceData inst = pc.instances.v[pc.instance_ids.v[gl_InstanceIndex]];
    vec3 world = deform(i, inst, false).position;
    out_uv0 = fetch_uv0(i);
    out_uv1 = fetch_uv1(i);
    out_color = fetch_color(i);
    mat4 vp = pc.cascade == NO_CASCADE ? frame.view_proj : frame.shadow_view_proj[pc.cascade];
    gl_Position = vp * vec4(world, 1.0);
}
