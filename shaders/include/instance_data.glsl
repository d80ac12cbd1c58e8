// The per-instance record and the motion streams a moving mesh's vertices are
// deformed with (motion.glsl): shared by the rasterizer's vertex stages (common.glsl)
// and the ray tracer's posing pass (pose_vertices.comp). C++ twins: GPUInstanceData,
// GPUMotionMesh (gpu_structs.h).
#ifndef SHERPA_INSTANCE_DATA_GLSL
#define SHERPA_INSTANCE_DATA_GLSL
#include "stream_refs.glsl" // Vec2Ref, Vec3Ref, Vec4Ref

struct GPUInstanceData {
    mat4 model;              // 0
    vec4 normal_matrix[3];   // 64: columns of transpose(inverse(mat3(model)))
    uint material;           // 112
    uint mesh;               // 116
    uint joint_base;         // 120: moving meshes: first joint matrix in the pose buffer
    uint weight_base;        // 124: first morph weight (a float index into the pose buffer)
};

layout(buffer_reference, scalar, buffer_reference_align = 16) readonly buffer InstanceRef {
    GPUInstanceData v[];
};

// Skinning and morphing streams of one moving mesh (GPUMotionMesh; motion.glsl uses it).
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer JointRef { uvec2 v[]; };
struct GPUMotionMesh {
    JointRef joints;         // 0: four 16-bit joint indices per vertex and set
    Vec4Ref weights;         // 8
    Vec3Ref morph_positions; // 16: per target and vertex, target-major
    Vec3Ref morph_normals;   // 24
    Vec3Ref morph_tangents;  // 32
    uint vertex_count;       // 40
    uint influence_sets;     // 44
    uint target_count;       // 48
    uint flags;              // 52: MOTION_*
};
// The record is read whole (one scalar load of 56 bytes) where a moving vertex is posed.
layout(buffer_reference, scalar, buffer_reference_align = 8) readonly buffer MotionMeshRef {
    GPUMotionMesh m;
};

mat3 normal_matrix(GPUInstanceData inst) {
    return mat3(inst.normal_matrix[0].xyz, inst.normal_matrix[1].xyz, inst.normal_matrix[2].xyz);
}
#endif
