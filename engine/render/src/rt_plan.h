#pragma once
// What the acceleration structures of a scene hold, decided on the CPU before any
// Vulkan call: pure functions over the scene and its GPU meshes (tested without a
// device, tests/gpu/rt_plan_test.cpp). Private to the render layer.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/scene/scene.h>

namespace sherpa::render {

struct BlasGeometryPlan {
    std::uint32_t mesh = 0; // engine mesh (Scene::meshes, GpuScene::meshes)
    std::uint32_t triangles = 0;
    // Opaque material whose sides need no test: double-sided, or single-sided in a BLAS
    // whose back faces the traversal culls (BlasPlan::cull_back_faces). No any-hit.
    // Other single-sided ones reach any-hit, which culls their back faces per material
    // (the instance flags cannot where a glTF mesh mixes sidedness); masked ones reach
    // it for the alpha test.
    bool opaque = true;
};

// Whether the traversal may cull this material's back faces for every ray that culls
// them (the rasterizer's single-sided rule): single-sided and not the boundary of a
// volume (KHR_materials_volume with transmission: the path tracer enters through the
// front and leaves through the back face, pt.rahit).
bool culls_back_faces(const scene::MaterialInstance& material);

// One BLAS: the triangle primitives of one glTF mesh that are on the GPU, in
// primitive order (gl_GeometryIndexEXT is the position in `geometries`).
struct BlasPlan {
    std::uint32_t group = 0; // glTF mesh (Mesh::group_id)
    std::string name;
    std::vector<BlasGeometryPlan> geometries;
    std::uint64_t triangles = 0;
    // Every geometry's material culls_back_faces(): the TLAS instances of this BLAS
    // let the traversal cull back faces (no TRIANGLE_FACING_CULL_DISABLE), and the rays
    // ask for it (gl_RayFlagsCullBackFacingTrianglesEXT), so its opaque single-sided
    // geometries need no any-hit. On lavapipe an any-hit interpolates the vertices of
    // every candidate hit: DamagedHelmet path traces 10 to 25% faster without it.
    bool cull_back_faces = false;
};

// A BLAS for every glTF mesh with at least one triangle on the GPU, by glTF mesh
// index. Lines, points and empty primitives (index_count 0: not instanced or no
// triangles) are left out.
std::vector<BlasPlan> plan_blas(const scene::Scene& scene, std::span<const GpuMesh> meshes);

// Splits builds into batches, in order, so that each batch's scratch (each size
// rounded up to `alignment`) stays within `budget`; a build that alone exceeds it
// is a batch of its own. Returns indices into `scratch`.
std::vector<std::vector<std::uint32_t>> batch_by_scratch(std::span<const std::uint64_t> scratch,
                                                         std::uint64_t budget,
                                                         std::uint64_t alignment);

// A (node, EXT_mesh_gpu_instancing row, glTF mesh) of the displayed scene with a
// triangle on the GPU, in
// scene-instance order: what the TLAS may instance. `blas` (into the combined BLAS
// list: the static ones, then the posed ones) is -1 while it has none.
struct TlasCandidate {
    std::uint32_t node = 0, group = 0;
    std::int32_t blas = -1;
    bool world_space = false; // posed in world space (skinned): the instance is the identity
    glm::mat4 world{1.0f};    // as loaded
    glm::mat4 row{1.0f};      // the instancing row's T * R * S (world = node world x row)
    std::string node_name;    // for warnings
};

// One per (node, row, glTF mesh) of `scene.instances` (its first primitive's), with
// `blas_of_group[group]` as its BLAS (-1 where the mesh has none).
std::vector<TlasCandidate> tlas_candidates(const scene::Scene& scene,
                                           std::span<const std::int32_t> blas_of_group);

struct TlasInstancePlan {
    std::uint32_t blas = 0; // index into the BLAS list
    std::uint32_t node = 0;
    glm::mat4 world{1.0f};
    bool mirrored = false; // negative determinant
};

struct TlasPlan {
    std::vector<TlasInstancePlan> instances;
    TlasStats counts; // pairs, dedup, mirrored, hidden, non_finite
    std::vector<std::string> warnings;
};

// One instance per candidate with a BLAS, at `node_world[node]` x row (the frame's pose;
// empty: the candidate's world as loaded), the identity for world-space ones.
// Excluded and counted: hidden nodes (`hidden_nodes[node]`), non-finite transforms
// (with a warning), and pairs with the same BLAS and a bitwise identical world
// transform as an earlier one.
TlasPlan plan_tlas(std::span<const TlasCandidate> candidates, const std::vector<bool>& hidden_nodes,
                   std::span<const glm::mat4> node_world = {});

// A (node, glTF mesh) instance whose mesh skins or morphs: it gets a BLAS of its own
// over posed copies of the vertices (posed_geometry.h), rewritten when the pose changes.
struct PosedGeometryPlan {
    std::uint32_t mesh = 0;         // engine mesh
    std::uint32_t gpu_instance = 0; // its GPU instance (the pose buffer's GPUInstanceData)
    bool moves = false;             // the mesh skins or morphs (a GPUMotionMesh)
    // Posed streams of its own: it moves, or the instance is posed in world space.
    bool posed = false;
};

struct PosedBlasPlan {
    std::uint32_t node = 0, group = 0;
    std::uint32_t plan = 0; // the glTF mesh's BlasPlan (geometries, opacity) in plan_blas's list
    // Some geometry is skinned by the node's skin: every posed geometry is in world
    // space (a skinned node's transform does not apply), else in the mesh's space.
    bool world_space = false;
    std::vector<PosedGeometryPlan> geometries; // as the BlasPlan's
};

// The posed BLAS of a scene: one per (node, glTF mesh) instance of `plans` where a
// geometry's engine mesh has motion streams (`meshes[m].motion`) and every geometry
// is a GPU instance of that node (`scene_instances`: scene instance per GPU
// instance). Empty for static scenes.
std::vector<PosedBlasPlan> plan_posed_blas(const scene::Scene& scene,
                                           std::span<const GpuMesh> meshes,
                                           std::span<const std::uint32_t> scene_instances,
                                           std::span<const BlasPlan> plans);

} // namespace sherpa::render
