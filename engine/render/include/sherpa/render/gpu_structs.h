#pragma once
// C++ twins of the GPU-visible structures of the render layer, in one place:
// shaders/include/{common,material_extra,cull_structs}.glsl (GPUMaterialData, the
// scene layer's, is in sherpa/scene/material.h). Every offset is pinned here; change
// both sides together: tests/gpu/struct_twins_test.cpp compiles the GLSL side and
// fails on any field whose name or offset differs (add a new struct to its table). The constants
// and enum values the shaders use are not copied: sherpa_glsl_constants generates them from this
// header (sherpa_constants.glsl).
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include <sherpa/gpu/bindless.h>
#include <sherpa/scene/material.h>
#include <sherpa/scene/vertex.h>

namespace sherpa::render {

inline constexpr std::uint32_t kMaxLights = 16;
inline constexpr std::uint32_t kMaxCascades = 4;    // array size in GPUFrameData
inline constexpr std::uint32_t kShadowCascades = 3; // cascades the renderer fits and draws
inline constexpr std::uint32_t kNoCascade = 0xffffffffu;

// Bindless default-texture slots (kWhiteTexture..): sherpa/gpu/bindless.h.

struct GPULight {
    glm::vec4 position_range;
    glm::vec4 direction_type;
    glm::vec4 color_intensity;
    glm::vec4 cone;
};
static_assert(sizeof(GPULight) == 64);

// std140 uniform block (set 1, binding 0): every member is 16-byte aligned.
struct GPUFrameData {
    glm::mat4 view;
    glm::mat4 proj;
    glm::mat4 view_proj;
    glm::mat4 shadow_view_proj[kMaxCascades];
    glm::vec4 camera_position;
    glm::vec4 cascade_splits;
    glm::vec4 sun_direction;
    glm::vec4 sun_radiance;
    glm::vec4 ambient;
    glm::uvec4 params; // x view, y light count, z cascade count, w shadow taps (1 or 4)
    glm::vec4 overlay; // x glyph length, y uv checks per unit, z texture LOD (< 0: derivatives)
    glm::vec4 cascade_texel; // world size of one shadow-map texel, per cascade
    GPULight lights[kMaxLights];
    glm::vec4 environment; // x intensity, y specular levels (0: none), z cos, w sin of rotation
    glm::vec4 display;     // x 2^exposure, y ToneMap, z energy compensation, w background level
    // Irradiance / pi as 9 SH coefficients (rgb; environment_sh.h), read instead of the
    // irradiance cube where irradiance_sh[0].w is 1 (IrradianceMode::Sh9);
    // irradiance_sh[1].w is FrameRequest::anisotropy_lighting (ibl.glsl).
    glm::vec4 irradiance_sh[9];
};
static_assert(offsetof(GPUFrameData, proj) == 64);
static_assert(offsetof(GPUFrameData, view_proj) == 128);
static_assert(offsetof(GPUFrameData, shadow_view_proj) == 192);
static_assert(offsetof(GPUFrameData, camera_position) == 448);
static_assert(offsetof(GPUFrameData, cascade_splits) == 464);
static_assert(offsetof(GPUFrameData, sun_direction) == 480);
static_assert(offsetof(GPUFrameData, sun_radiance) == 496);
static_assert(offsetof(GPUFrameData, ambient) == 512);
static_assert(offsetof(GPUFrameData, params) == 528);
static_assert(offsetof(GPUFrameData, overlay) == 544);
static_assert(offsetof(GPUFrameData, cascade_texel) == 560);
static_assert(offsetof(GPUFrameData, lights) == 576);
static_assert(offsetof(GPUFrameData, environment) == 576 + 64 * kMaxLights);
static_assert(offsetof(GPUFrameData, display) == 592 + 64 * kMaxLights);
static_assert(offsetof(GPUFrameData, irradiance_sh) == 608 + 64 * kMaxLights);
static_assert(sizeof(GPUFrameData) == 752 + 64 * kMaxLights);

// 128 bytes: model matrix and the CPU-computed normal matrix
// transpose(inverse(mat3(model))) as three vec4 columns (layout-independent).
struct GPUInstanceData {
    glm::mat4 model;
    glm::vec4 normal_matrix[3];
    std::uint32_t material;
    std::uint32_t mesh;
    // Moving meshes only (GPUMotionMesh): the instance's first joint matrix and first
    // morph weight in the frame's pose buffer (GPUPushConstants::pose).
    std::uint32_t joint_base;
    std::uint32_t weight_base;
};
static_assert(sizeof(GPUInstanceData) == 128);
static_assert(offsetof(GPUInstanceData, normal_matrix) == 64);
static_assert(offsetof(GPUInstanceData, material) == 112);
static_assert(offsetof(GPUInstanceData, mesh) == 116);
static_assert(offsetof(GPUInstanceData, joint_base) == 120);
static_assert(offsetof(GPUInstanceData, weight_base) == 124);

// Skinning and morphing (shaders/include/motion.glsl, scalar layout): one record per
// mesh that skins or morphs, its streams in engine-vertex order. Static meshes have
// none, and their pipelines are built without the motion code (MOTION constant).
inline constexpr std::uint32_t kMotionSkin = 1u << 0;           // joints + weights streams
inline constexpr std::uint32_t kMotionMorphPositions = 1u << 1; // target deltas present
inline constexpr std::uint32_t kMotionMorphNormals = 1u << 2;
inline constexpr std::uint32_t kMotionMorphTangents = 1u << 3;
struct GPUMotionMesh {
    VkDeviceAddress joints;          // uvec2 per vertex and set of 4: four 16-bit joint indices
    VkDeviceAddress weights;         // vec4 per vertex and set of 4
    VkDeviceAddress morph_positions; // vec3 per target and vertex, target-major
    VkDeviceAddress morph_normals;
    VkDeviceAddress morph_tangents;
    std::uint32_t vertex_count;
    std::uint32_t influence_sets; // sets of 4 joints per vertex
    std::uint32_t target_count;
    std::uint32_t flags; // kMotion*
};
static_assert(offsetof(GPUMotionMesh, weights) == 8);
static_assert(offsetof(GPUMotionMesh, morph_positions) == 16);
static_assert(offsetof(GPUMotionMesh, morph_normals) == 24);
static_assert(offsetof(GPUMotionMesh, morph_tangents) == 32);
static_assert(offsetof(GPUMotionMesh, vertex_count) == 40);
static_assert(offsetof(GPUMotionMesh, influence_sets) == 44);
static_assert(offsetof(GPUMotionMesh, target_count) == 48);
static_assert(offsetof(GPUMotionMesh, flags) == 52);
static_assert(sizeof(GPUMotionMesh) == 56);

enum TextureSlotIndex : std::uint32_t {
    kSlotBaseColor = 0,
    kSlotMetallicRoughness = 1,
    kSlotNormal = 2,
    kSlotOcclusion = 3,
    kSlotEmissive = 4,
    kSlotSpecularGlossiness = 5, // KHR_materials_pbrSpecularGlossiness's texture
    kSlotCount = 6,
};

// GPUMaterialExtra::workflow: which BRDF inputs the material gives.
inline constexpr std::uint32_t kWorkflowMetallicRoughness = 0;
inline constexpr std::uint32_t kWorkflowSpecularGlossiness = 1;

struct GPUTextureTransform {
    glm::vec4 row0; // w: TEXCOORD set
    glm::vec4 row1;
};
struct GPUMaterialExtra {
    GPUTextureTransform uv[kSlotCount];
    std::uint32_t unlit;
    std::uint32_t workflow;                // kWorkflow*
    std::uint32_t specular_glossiness_tex; // bindless slot (white when absent)
    // The material's GPUExtensionIndex in the extension buffer (16-byte words), or
    // kNoExtension: a material without drawn extensions has no block there.
    std::uint32_t extensions;
    glm::vec4 specular_glossiness; // xyz specularFactor, w glossinessFactor
};
static_assert(sizeof(GPUTextureTransform) == 32);
static_assert(offsetof(GPUMaterialExtra, unlit) == 192);
static_assert(offsetof(GPUMaterialExtra, workflow) == 196);
static_assert(offsetof(GPUMaterialExtra, specular_glossiness_tex) == 200);
static_assert(offsetof(GPUMaterialExtra, extensions) == 204);
static_assert(offsetof(GPUMaterialExtra, specular_glossiness) == 208);
static_assert(sizeof(GPUMaterialExtra) == 224);

// The material extension blocks (GPUExtensionIndex, GPU*Block) are in
// gpu_material_ext_structs.h, next to their GLSL twins' file.

// mesh_flags bits (common.glsl). Bits 0-5 are the streams (1 << VertexAttribute);
// a lines or points mesh sets one topology bit.
inline constexpr std::uint32_t kMeshLinesBit = 1u << 6;
inline constexpr std::uint32_t kMeshPointsBit = 1u << 7;
inline constexpr std::uint32_t kMeshTopologyBits = kMeshLinesBit | kMeshPointsBit;
// Points are drawn this many pixels wide where the device supports large points
// (largePoints), else at its only size, 1.
inline constexpr float kPointSizePixels = 4.0f;
// Lines (LINES, LINE_STRIP, LINE_LOOP primitives) are drawn this many pixels wide
// where the device supports wide lines (wideLines), else 1: a 1-px line is hard to
// see and to pick on a high-DPI screen.
inline constexpr float kLineWidthPixels = 2.0f;
// The selection outline's lines (wideLines devices; else 1): half of the width lies
// outside the silhouette, so a 3-px line leaves a ring of 1-2 px around it.
inline constexpr float kOutlineWidthPixels = 3.0f;
inline constexpr std::uint32_t kTangentProvenanceShift = 8;
inline constexpr std::uint32_t kNormalProvenanceShift = 10;
inline constexpr std::uint32_t kGlyphKindShift = 16;
// The mesh skins or morphs: drawn by the MOTION pipelines with its GPUMotionMesh.
inline constexpr std::uint32_t kMeshMotionBit = 1u << 12;

// Per draw. Frame data and materials are not here: they come through descriptor
// set 1 (see common.glsl for why).
struct GPUPushConstants {
    VkDeviceAddress instances;
    VkDeviceAddress positions;
    VkDeviceAddress normals;
    VkDeviceAddress tangents;
    VkDeviceAddress uv0;
    VkDeviceAddress uv1;
    VkDeviceAddress colors;
    VkDeviceAddress lines;
    std::uint32_t material_id;
    std::uint32_t mesh_flags;
    std::uint32_t cascade;
    float glyph_length;
    glm::vec4 color;
    // gl_InstanceIndex -> GPU instance: culling's compacted ids, else the identity.
    VkDeviceAddress instance_ids;
    VkDeviceAddress motion; // the drawn mesh's GPUMotionMesh (moving meshes only)
    // The frame's pose: joint matrices (mat4), then morph weights and the
    // joint-influence highlight (floats, from index highlight_base).
    VkDeviceAddress pose;
    std::uint32_t highlight_base;
    std::uint32_t pad;
};
static_assert(offsetof(GPUPushConstants, lines) == 56);
static_assert(offsetof(GPUPushConstants, material_id) == 64);
static_assert(offsetof(GPUPushConstants, cascade) == 72);
static_assert(offsetof(GPUPushConstants, color) == 80);
static_assert(offsetof(GPUPushConstants, instance_ids) == 96);
static_assert(offsetof(GPUPushConstants, motion) == 104);
static_assert(offsetof(GPUPushConstants, pose) == 112);
static_assert(offsetof(GPUPushConstants, highlight_base) == 120);
static_assert(sizeof(GPUPushConstants) == 128);
static_assert(sizeof(GPUPushConstants) <= 128,
              "Vulkan guarantees only 128 bytes of push constants");

struct GPULineVertex {
    glm::vec4 position;
    glm::vec4 color;
};
static_assert(sizeof(GPULineVertex) == 32);

// Culling (shaders/include/cull_structs.glsl, scalar layout).
struct GPUCullObject {
    glm::vec3 bmin;
    std::uint32_t batch;
    glm::vec3 bmax;
    std::uint32_t instance;
};
static_assert(sizeof(GPUCullObject) == 32);
static_assert(offsetof(GPUCullObject, batch) == 12);
static_assert(offsetof(GPUCullObject, bmax) == 16);
static_assert(offsetof(GPUCullObject, instance) == 28);

inline constexpr std::uint32_t kCullInvalidBit = 0x80000000u;
inline constexpr std::uint32_t kCullMaxSatAxes = 21;

struct GPUCullParams {
    glm::vec4 planes[6];
    glm::vec4 sat_axis[kCullMaxSatAxes];
    glm::vec2 sat_range[kCullMaxSatAxes];
    std::uint32_t plane_count, sat_count, method, object_count, empty;
};
static_assert(offsetof(GPUCullParams, sat_axis) == 96);
static_assert(offsetof(GPUCullParams, sat_range) == 432);
static_assert(offsetof(GPUCullParams, plane_count) == 600);
static_assert(offsetof(GPUCullParams, object_count) == 612);
static_assert(offsetof(GPUCullParams, empty) == 616);
static_assert(sizeof(VkDrawIndexedIndirectCommand) == 20);

// Ray tracing (shaders/include/rt_geometry.glsl, scalar layout): one record per BLAS
// geometry (a triangle primitive), found in hit shaders at
// gl_InstanceCustomIndexEXT + gl_GeometryIndexEXT. Our vertex streams are separate
// arrays, so the record reaches each one the mesh has on the GPU by device address
// (0: absent, read as the shader default), and its first index.
struct GPUGeometryInfo {
    VkDeviceAddress stream[scene::kVertexAttributeCount]; // by VertexAttribute
    VkDeviceAddress indices; // the geometry's first index (uint32 triangle list)
    std::uint32_t material;  // into the materials array
    std::uint32_t flags;     // mesh_flags (streams, provenance)
};
static_assert(scene::kVertexAttributeCount == 6);
static_assert(offsetof(GPUGeometryInfo, stream) == 0);
static_assert(offsetof(GPUGeometryInfo, indices) == 48);
static_assert(offsetof(GPUGeometryInfo, material) == 56);
static_assert(offsetof(GPUGeometryInfo, flags) == 60);
static_assert(sizeof(GPUGeometryInfo) == 64);

// Push constants of the ray-tracing debug views (shaders/include/rt_hit.glsl, scalar).
struct GPURayPushConstants {
    glm::mat4 inv_view_proj;    // NDC -> world (reverse Z)
    VkDeviceAddress geometries; // the GPUGeometryInfo array
    std::uint32_t view;         // DebugView
    float texture_lod;          // mip level of every texture (< 0: level 0)
    glm::vec4 clear_color;      // linear
    // xyz: unit direction toward the sun; w: its angular radius (radians). The
    // shadow, ao and shadow-error views only.
    glm::vec4 sun;
    std::uint32_t shadow_rays; // 0: the sun casts no shadow (facing only)
    std::uint32_t ao_rays;
    float ao_radius; // world units
    std::uint32_t reserved;
};
static_assert(offsetof(GPURayPushConstants, geometries) == 64);
static_assert(offsetof(GPURayPushConstants, view) == 72);
static_assert(offsetof(GPURayPushConstants, texture_lod) == 76);
static_assert(offsetof(GPURayPushConstants, clear_color) == 80);
static_assert(offsetof(GPURayPushConstants, sun) == 96);
static_assert(offsetof(GPURayPushConstants, shadow_rays) == 112);
static_assert(offsetof(GPURayPushConstants, ao_radius) == 120);
static_assert(sizeof(GPURayPushConstants) == 128); // Vulkan's guaranteed minimum

// Push constants of the path tracer (shaders/pt.*, PathPush in rt_hit.glsl, scalar):
// the fields the hit shaders share with GPURayPushConstants at the same offsets.
struct GPUPathPushConstants {
    glm::mat4 inv_view_proj;    // NDC -> world (reverse Z)
    VkDeviceAddress geometries; // the GPUGeometryInfo array
    std::uint32_t first_sample; // index of this launch's first sample in each pixel
    float texture_lod;          // mip level of every texture (< 0: level 0)
    glm::vec4 clear_color;      // linear: the background where it is a colour
    std::uint32_t samples;      // samples per pixel in this launch (kPathSampleCount), flags
    std::uint32_t max_bounces;  // surface interactions a path may scatter at
    std::uint32_t seed;         // PathTraceSettings::seed
    float light_inv_power;      // 1 / the emissive triangles' power; 0: no light list
    glm::uvec2 env_size;        // columns, rows of the environment distribution (0: none)
    float sun_cos_radius;       // cosine of the sun's angular radius
    float max_radiance;         // a sample's luminance is capped here (overflow guard)
};
static_assert(offsetof(GPUPathPushConstants, geometries) == 64);
static_assert(offsetof(GPUPathPushConstants, first_sample) == 72);
static_assert(offsetof(GPUPathPushConstants, texture_lod) == 76);
static_assert(offsetof(GPUPathPushConstants, clear_color) == 80);
static_assert(offsetof(GPUPathPushConstants, samples) == 96);
static_assert(offsetof(GPUPathPushConstants, env_size) == 112);
static_assert(offsetof(GPUPathPushConstants, max_radiance) == 124);
static_assert(sizeof(GPUPathPushConstants) == 128);
// GPUPathPushConstants::samples: the count in the low bits and a flag (PATH_* in
// rt_hit.glsl): one shadow ray per light at each surface instead of one in all.
inline constexpr std::uint32_t kPathSampleCount = 0xffffu;
inline constexpr std::uint32_t kPathAllLights = 0x10000u;

// Push constants of the ray tracer's posing pass (shaders/pose_vertices.comp, scalar):
// one dispatch per posed geometry (posed_geometry.cpp).
struct GPUPoseVerticesPush {
    VkDeviceAddress instance;  // its GPUInstanceData in the frame's pose buffer
    VkDeviceAddress positions; // stored streams
    VkDeviceAddress normals;
    VkDeviceAddress tangents;
    VkDeviceAddress motion; // GPUMotionMesh (a zero record for a static mesh)
    VkDeviceAddress pose;   // joint matrices, then floats
    VkDeviceAddress out_positions, out_normals, out_tangents;
    std::uint32_t mesh_flags;
    std::uint32_t highlight_base;
    std::uint32_t vertex_count;
    std::uint32_t object_space; // 1: the mesh's space, 0: world space (skinned)
};
static_assert(offsetof(GPUPoseVerticesPush, motion) == 32);
static_assert(offsetof(GPUPoseVerticesPush, out_positions) == 48);
static_assert(offsetof(GPUPoseVerticesPush, out_tangents) == 64);
static_assert(offsetof(GPUPoseVerticesPush, mesh_flags) == 72);
static_assert(offsetof(GPUPoseVerticesPush, object_space) == 84);
static_assert(sizeof(GPUPoseVerticesPush) == 88);

// Push constants of the comparison pass (shaders/include/compare.glsl, scalar).
struct GPUComparePush {
    glm::uvec2 side_size;      // both side images
    glm::uvec2 target_size;    // the composited target
    std::uint32_t mode;        // 0 side A only, 1 split, 2 difference
    std::uint32_t target_srgb; // 1: the target encodes the fragment output
    float divider_px;          // Split: the divider's x in target pixels
    float heat_max;            // Difference: full heat at this byte difference
};
static_assert(offsetof(GPUComparePush, target_size) == 8);
static_assert(offsetof(GPUComparePush, mode) == 16);
static_assert(offsetof(GPUComparePush, target_srgb) == 20);
static_assert(offsetof(GPUComparePush, divider_px) == 24);
static_assert(sizeof(GPUComparePush) == 32);

// The statistics buffer compare.comp fills: a histogram of the per-pixel largest
// byte difference and the 64-bit sum of squared R, G, B byte differences (two words).
struct GPUCompareStats {
    std::uint32_t histogram[256];
    std::uint32_t squared_lo, squared_hi;
};
static_assert(sizeof(GPUCompareStats) == 1032);

} // namespace sherpa::render
