#version 460
#extension GL_GOOGLE_include_directive : require
// Positions only (plus the base-colour UV for alpha-tested materials): depth
// prepass, shadow cascades, wireframe and the benchmark's floor pass; moving meshes
// skinned and morphed (motion.glsl, MOTION pipelines only).
#include "common.glsl"
#include "motion.glsl"

layout(location = 0) out vec2 out_uv;

// Identical math to mesh.vert, so the depth prepass and shading agree exactly.
invariant gl_Position;

void main() {
    uint i = uint(gl_VertexIndex);
    GPUInstanceData inst = pc.instances.v[pc.instance_ids.v[gl_InstanceIndex]];
    vec3 world = deform(i, inst, false).position;
    GPUMaterialExtra extra = material_extras[pc.material_id];
    out_uv = transform_uv(extra.uv[SLOT_BASE_COLOR], fetch_uv0(i), fetch_uv1(i));
    mat4 vp = pc.cascade == NO_CASCADE ? frame.view_proj : frame.shadow_view_proj[pc.cascade];
    gl_Position = vp * vec4(world, 1.0);
}
