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

namespace sherpa::gpu {

struct BlasGeometryPlan {
    std::uint32_t mesh = 0; // engine mesh (Scene::meshes, GpuScene::meshes)
    std::uint32_t triangles = 0;
    // Opaque and double-sided material: no any-hit. Single-sided ones reach any-hit,
    // which culls their back faces per material (the instance flags cannot: a glTF
    // mesh mixes materials), masked ones for the alpha test.
    bool opaque = true;
};

// One BLAS: the triangle primitives of one glTF mesh that are on the GPU, in
// primitive order (gl_GeometryIndexEXT is the position in `geometries`).
struct BlasPlan {
    std::uint32_t group = 0; // glTF mesh (Mesh::group_id)
    std::string name;
    std::vector<BlasGeometryPlan> geometries;
    std::uint64_t triangles = 0;
};

// A BLAS for every glTF mesh with at least one triangle on the GPU, by glTF mesh
// index. Lines, points and empty primitives (index_count 0: not instanced or no
// triangles) are left out.
std::vector<BlasPlan> plan_blas(const Scene& scene, std::span<const GpuMesh> meshes);

// Splits builds into batches, in order, so that each batch's scratch (each size
// rounded up to `alignment`) stays within `budget`; a build that alone exceeds it
// is a batch of its own. Returns indices into `scratch`.
std::vector<std::vector<std::uint32_t>> batch_by_scratch(std::span<const std::uint64_t> scratch,
                                                         std::uint64_t budget,
                                                         std::uint64_t alignment);

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

// One instance per (node, glTF mesh) of the displayed scene whose mesh has a BLAS
// (`blas_of_group[group]` >= 0). Excluded and counted: hidden nodes
// (`hidden_nodes[node]`), non-finite transforms (with a warning), and pairs with
// the same BLAS and a bitwise identical world transform as an earlier one.
TlasPlan plan_tlas(const Scene& scene, std::span<const std::int32_t> blas_of_group,
                   const std::vector<bool>& hidden_nodes);

} // namespace sherpa::gpu
