// GLSL twins of sherpa::render::GPUCullObject / GPUCullParams / VkDrawIndexedIndirectCommand
// (engine/render/include/sherpa/render/gpu_structs.h pins every offset). Scalar layout.
#ifndef SHERPA_CULL_STRUCTS_GLSL
#define SHERPA_CULL_STRUCTS_GLSL

// CULL_SPHERE, CULL_PVERTEX, CULL_EXACT, CULL_INVALID_BIT, CULL_MAX_SAT_AXES.
#include "sherpa_cull.glsl" // generated from the C++ definitions

struct CullObject {
    vec3 bmin;     // 0
    uint batch;    // 12: indirect batch, CULL_INVALID_BIT for non-finite/inverted boxes
    vec3 bmax;     // 16
    uint instance; // 28: GPU instance index written to the compacted id array
};

struct CullParams {
    vec4 planes[6];                     // 0: inward, normalised (xyz normal, w distance)
    vec4 sat_axis[CULL_MAX_SAT_AXES];   // 96
    vec2 sat_range[CULL_MAX_SAT_AXES];  // 432: frustum interval on each axis
    uint plane_count;                   // 600
    uint sat_count;                     // 604
    uint method;                        // 608
    uint object_count;                  // 612
    uint empty;                         // 616
};

struct DrawCommand {
    uint index_count;
    uint instance_count;
    uint first_index;
    int vertex_offset;
    uint first_instance;
};

layout(buffer_reference, scalar, buffer_reference_align = 16) readonly buffer CullObjectRef {
    CullObject v[];
};
layout(buffer_reference, scalar, buffer_reference_align = 4) buffer DrawCommandRef {
    DrawCommand v[];
};
layout(buffer_reference, scalar, buffer_reference_align = 4) buffer UintRef { uint v[]; };

#endif
