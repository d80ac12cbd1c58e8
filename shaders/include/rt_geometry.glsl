// GLSL twin of sherpa::render::GPUGeometryInfo (engine/render/include/sherpa/render/
// gpu_structs.h pins every offset). Scalar layout; needs GL_EXT_buffer_reference and
// GL_EXT_shader_explicit_arithmetic_types_int64 (uint64_t addresses).
#ifndef SHERPA_RT_GEOMETRY_GLSL
#define SHERPA_RT_GEOMETRY_GLSL

// One record per BLAS geometry: gl_InstanceCustomIndexEXT + gl_GeometryIndexEXT.
struct GeometryInfo {
    uint64_t stream[6]; // 0: by VertexAttribute (position, normal, tangent, uv0, uv1, colour)
    uint64_t indices;   // 48: the geometry's first index
    uint material;      // 56
    uint flags;         // 60: mesh_flags
};

layout(buffer_reference, scalar, buffer_reference_align = 8) readonly buffer GeometryInfos {
    GeometryInfo g[];
};

#endif
