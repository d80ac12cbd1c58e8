// Shared declarations: per-frame data and materials (descriptor set 1), instances
// and vertex streams (buffer device addresses passed in push constants). C++ twins live in
// engine/render/include/sherpa/render/gpu_structs.h with static_asserts on every offset.
#ifndef SHERPA_COMMON_GLSL
#define SHERPA_COMMON_GLSL

#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_nonuniform_qualifier : require

#include "material.glsl"
#include "material_extra.glsl"

#include "frame_block.glsl" // FrameBlock frame (set 1, binding 0)

#include "instance_data.glsl" // GPUInstanceData, InstanceRef, MotionMeshRef

layout(set = 1, binding = 1, std430) readonly buffer MaterialBlock {
    GPUMaterialData materials[]; // the 80-byte records, one SSBO
};
layout(set = 1, binding = 2, std430) readonly buffer MaterialExtraBlock {
    GPUMaterialExtra material_extras[];
};
struct LineVertex {
    vec4 position;
    vec4 color;
};
layout(buffer_reference, scalar, buffer_reference_align = 16) readonly buffer LineRef {
    LineVertex v[];
};

// Which GPU instance each drawn instance is: culling compacts the visible ones here
// (CPU-written or by shaders/cull.comp); without culling it is the identity.
layout(buffer_reference, scalar, buffer_reference_align = 4) readonly buffer InstanceIdRef {
    uint v[];
};

layout(push_constant, scalar) uniform Push {
    InstanceRef instances;          // 0
    Vec3Ref positions;              // 8
    Vec3Ref normals;                // 16
    Vec4Ref tangents;               // 24
    Vec2Ref uv0;                    // 32
    Vec2Ref uv1;                    // 40
    Vec4Ref colors;                 // 48
    LineRef lines;                  // 56
    uint material_id;               // 64
    uint mesh_flags;                // 68
    uint cascade;                   // 72: shadow cascade, or NO_CASCADE for the camera
    float glyph_length;             // 76
    vec4 color;                     // 80: flat colour of overlays
    InstanceIdRef instance_ids;     // 96: gl_InstanceIndex -> GPU instance
    MotionMeshRef motion;           // 104: the drawn mesh's motion streams (moving meshes)
    Vec4Ref pose;                   // 112: joint matrices (4 vec4 each), then floats
    uint highlight_base;            // 120: float index of the joint-influence highlights
    uint pad;                       // 124
} pc;

#include "sherpa_mesh_flags.glsl" // mesh_flags: HAS_* stream bits, *_SHIFT, NO_CASCADE
#include "sherpa_views.glsl"      // VIEW_*: sherpa::render::kDebugViews

bool has(uint bit) { return (pc.mesh_flags & bit) != 0u; }

// Default values of absent streams, as glTF defines them.
vec3 fetch_normal(uint i) { return has(HAS_NORMAL) ? pc.normals.v[i] : vec3(0.0, 0.0, 1.0); }
vec4 fetch_tangent(uint i) { return has(HAS_TANGENT) ? pc.tangents.v[i] : vec4(1.0, 0.0, 0.0, 1.0); }
vec2 fetch_uv0(uint i) { return has(HAS_UV0) ? pc.uv0.v[i] : vec2(0.0); }
vec2 fetch_uv1(uint i) { return has(HAS_UV1) ? pc.uv1.v[i] : vec2(0.0); }
vec4 fetch_color(uint i) { return has(HAS_COLOR) ? pc.colors.v[i] : vec4(1.0); }

#endif
