#pragma once
// Mesh passes for GPU-driven rendering (vkguide's MeshPass design), as pure CPU
// bookkeeping the GPU layer uploads: per-pass objects in flat arrays, flat batches
// sorted by a sort key, instanced indirect batches (one per mesh and pipeline),
// and multi-batches (runs of indirect batches sharing a pipeline, drawn with one
// vkCmdDrawIndexedIndirectCount). Adding or removing objects updates the sorted
// arrays incrementally (merge, no full re-sort); moving an object only marks it
// dirty so that just its data is re-uploaded.
#include <cstdint>
#include <span>
#include <vector>

#include <sherpa/scene/scene.h>

namespace sherpa::scene {

enum class MeshPassKind : std::uint8_t { Forward, Transparent, Shadow };

// Pipeline state of a draw: alpha mode, double-sidedness (cull mode) and mirrored
// winding (a world transform with negative determinant flips the front face).
std::uint32_t pipeline_key(AlphaMode mode, bool double_sided, bool mirrored);
struct PipelineState {
    AlphaMode alpha_mode;
    bool double_sided, mirrored;
};
PipelineState pipeline_state(std::uint32_t key);
// The key of a scene instance (its material's alpha mode and sidedness, its
// transform's handedness).
std::uint32_t instance_pipeline_key(const Scene& scene, std::uint32_t instance);

struct FlatBatch {
    std::uint64_t sort_key = 0; // pipeline key << 32 | mesh id
    std::uint32_t object = 0;   // index into MeshPass::objects()
};

struct IndirectBatch {
    std::uint32_t mesh_id = 0;
    std::uint32_t pipeline = 0;
    std::uint32_t first = 0, count = 0; // range of flat batches
};

struct MultiBatch {
    std::uint32_t first = 0, count = 0; // range of indirect batches sharing a pipeline
};

struct PassObject {
    std::uint32_t instance = 0; // index into Scene::instances
    std::uint64_t sort_key = 0;
    bool alive = false;
};

class MeshPass {
public:
    explicit MeshPass(MeshPassKind kind) : kind_(kind) {}
    MeshPassKind kind() const { return kind_; }

    // Queues an object; returns its stable handle (index into objects()). Freed
    // handles are reused.
    std::uint32_t add(std::uint32_t instance, std::uint32_t mesh_id, std::uint32_t pipeline);
    // Queues the removal of a live handle (a dead or unknown handle is ignored and
    // reported by the return value).
    bool remove(std::uint32_t handle);
    // The object's transform/bounds changed: only its data needs re-uploading.
    void mark_dirty(std::uint32_t handle);
    // Applies queued adds/removes: removed entries are dropped, new ones sorted and
    // merged into the sorted flat batches, then batches and multi-batches rebuilt.
    void update();

    std::span<const PassObject> objects() const { return objects_; }
    std::span<const FlatBatch> flat_batches() const { return flat_; }
    std::span<const IndirectBatch> batches() const { return batches_; }
    std::span<const MultiBatch> multi_batches() const { return multi_; }
    std::span<const std::uint32_t> dirty() const { return dirty_; }
    // After the GPU layer uploaded the dirty objects' data.
    void clear_dirty() {
        for (std::uint32_t h : dirty_) is_dirty_[h] = 0;
        dirty_.clear();
    }
    std::uint32_t live_count() const { return live_; }

private:
    MeshPassKind kind_;
    std::vector<PassObject> objects_;
    std::vector<std::uint32_t> free_handles_;
    std::vector<FlatBatch> flat_, pending_add_;
    std::vector<std::uint32_t> pending_remove_, dirty_;
    std::vector<std::uint8_t> is_dirty_;
    std::vector<IndirectBatch> batches_;
    std::vector<MultiBatch> multi_;
    std::uint32_t live_ = 0;
};

// The forward (opaque and masked), transparent (blended) and shadow (every
// non-blended caster) passes of a scene's instances; PassObject::instance maps
// each pass object back to its Scene::instances entry.
struct ScenePasses {
    MeshPass forward{MeshPassKind::Forward};
    MeshPass transparent{MeshPassKind::Transparent};
    MeshPass shadow{MeshPassKind::Shadow};
};
ScenePasses build_mesh_passes(const Scene& scene);

} // namespace sherpa::scene
