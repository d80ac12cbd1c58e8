#version 460
#extension GL_GOOGLE_include_directive : require
// Full vertex pulling for shading: every stream the GPU holds, defaults for the rest;
// moving meshes are skinned and morphed first (motion.glsl, MOTION pipelines only).
#include "common.glsl"
#include "motion.glsl"

layout(location = 0) out vec3 out_world_pos;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec4 out_tangent;
layout(location = 3) out vec2 out_uv0;
layout(location = 4) out vec2 out_uv1;
layout(location = 5) out vec4 out_color;
layout(location = 6) out float out_joint_weight; // the joint-influence view
layout(location = 7) flat out vec3 out_model_scale; // refraction through a volume
// Outputs the fragment shader does not read (absent streams are constants there,
// see forward.frag) are removed when the pipeline links the two stages.

// Points (MESH_POINTS meshes, point-list pipelines) are this many pixels wide: a
// specialization constant, 1 on devices without largePoints (pipelines.cpp).
layout(constant_id = 0) const float POINT_SIZE = 1.0;

// Identical math to depth.vert, so the depth prepass and shading agree exactly.
invariant gl_Position;

void main() {
    uint i = uint(gl_VertexIndex);
    GPUInstanceData inst = pc.instances.v[pc.instance_ids.v[gl_InstanceIndex]];
    Deformed d = deform(i, inst, true);
    out_world_pos = d.position;
    out_normal = d.normal;
    out_tangent = d.tangent;
    out_uv0 = fetch_uv0(i);
    out_uv1 = fetch_uv1(i);
    out_color = fetch_color(i);
    out_joint_weight = d.highlight;
    out_model_scale = vec3(length(inst.model[0].xyz), length(inst.model[1].xyz), length(inst.model[2].xyz));
    gl_Position = frame.view_proj * vec4(d.position, 1.0);
    gl_PointSize = POINT_SIZE; // read only by point-list pipelines
}
