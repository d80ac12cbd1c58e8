#version 460
#extension GL_GOOGLE_include_directive : require
// The ray tracer's posed vertices: one thread per vertex of one moving mesh on one
// instance deforms it with the rasterizer's own skinning and morph code
// (motion.glsl, MOTION specialised on) from the frame's pose buffer (PosePass), and
// writes position, normal and tangent into that instance's posed streams, which its
// BLAS is built from and the hit shaders read (GPUGeometryInfo). Skinned instances
// are written in world space (their TLAS instance is the identity, as the skinned
// node's transform does not apply), the others in the mesh's space (object_space:
// the instance's transform stays in the TLAS). C++ twin of the push constants:
// GPUPoseVerticesPush (gpu_structs.h).
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require

#include "instance_data.glsl"
#include "sherpa_mesh_flags.glsl"

layout(local_size_x = 64) in;

layout(buffer_reference, scalar, buffer_reference_align = 4) writeonly buffer PosedVec3 { vec3 v[]; };
layout(buffer_reference, scalar, buffer_reference_align = 4) writeonly buffer PosedVec4 { vec4 v[]; };

layout(push_constant, scalar) uniform Push {
    InstanceRef instance;    // 0: this instance's GPUInstanceData in the frame's pose buffer
    Vec3Ref positions;       // 8: the stored streams
    Vec3Ref normals;         // 16
    Vec4Ref tangents;        // 24
    MotionMeshRef motion;    // 32: the mesh's motion streams (a zero record for static meshes)
    Vec4Ref pose;            // 40: joint matrices, then floats (motion.glsl)
    PosedVec3 out_positions; // 48
    PosedVec3 out_normals;   // 56: written when HAS_NORMAL
    PosedVec4 out_tangents;  // 64: written when HAS_TANGENT
    uint mesh_flags;         // 72
    uint highlight_base;     // 76
    uint vertex_count;       // 80
    uint object_space;       // 84
} pc;

bool has(uint bit) { return (pc.mesh_flags & bit) != 0u; }
vec3 fetch_normal(uint i) { return has(HAS_NORMAL) ? pc.normals.v[i] : vec3(0.0, 0.0, 1.0); }
vec4 fetch_tangent(uint i) { return has(HAS_TANGENT) ? pc.tangents.v[i] : vec4(1.0, 0.0, 0.0, 1.0); }

#include "motion.glsl"

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= pc.vertex_count) return;
    GPUInstanceData inst = pc.instance.v[0];
    if (pc.object_space != 0u) {
        inst.model = mat4(1.0);
        inst.normal_matrix[0] = vec4(1.0, 0.0, 0.0, 0.0);
        inst.normal_matrix[1] = vec4(0.0, 1.0, 0.0, 0.0);
        inst.normal_matrix[2] = vec4(0.0, 0.0, 1.0, 0.0);
    }
    const Deformed d = deform(i, inst, true);
    pc.out_positions.v[i] = d.position;
    if (has(HAS_NORMAL)) pc.out_normals.v[i] = d.normal;
    if (has(HAS_TANGENT)) pc.out_tangents.v[i] = d.tangent;
}
