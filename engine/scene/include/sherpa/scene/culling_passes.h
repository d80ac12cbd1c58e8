#pragma once
// Culling passes over a Scene: the camera pass and shadow-cascade passes, their
// visible lists, draw groups and statistics.
#include <cstdint>
#include <string>
#include <vector>

#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/scene.h>

namespace sherpa::scene {

// One instanced draw: consecutive visible instances sharing mesh, alpha mode and
// double-sidedness (the renderer's pipeline/culling-mode key).
struct DrawGroup {
    std::uint32_t mesh_id = 0;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    bool double_sided = false;
    std::uint32_t first = 0, count = 0; // range in PassResult::draw_order
};

struct CullStats {
    std::string pass;
    glm::mat4 view_projection{1.0f}; // the volume culled against (set by the caller)
    CullMethod method = CullMethod::PVertex;
    core::SimdLevel simd = core::SimdLevel::Scalar;
    std::uint64_t total = 0, tested = 0, visible = 0, culled = 0, invalid = 0;
    // Instances of `total` whose node (or an ancestor) is hidden: never tested nor
    // drawn, neither visible nor culled (tested = total - hidden when culling runs).
    std::uint64_t hidden = 0;
    // Kept by this method although the exact test rejects them (-1: not measured).
    std::int64_t false_positives = -1;
    std::uint64_t draw_calls = 0, triangles = 0;
    double cpu_ms = 0.0;
    // GPU-driven path: compute time from timestamps (-1: CPU path or no timestamps)
    // and the objects whose visibility differs from the CPU path's (-1: not checked).
    bool gpu = false;
    double gpu_ms = -1.0;
    std::int64_t cpu_gpu_differences = -1;
};

struct PassResult {
    std::vector<std::uint32_t> visible_opaque;      // instance indices (opaque and mask)
    std::vector<std::uint32_t> visible_transparent; // blend, sorted back to front
    std::vector<std::uint32_t> draw_order;          // opaque instances sorted by group key
    std::vector<DrawGroup> groups;                  // over draw_order, then one per transparent
    CullStats stats;
};

struct CullOptions {
    CullMethod method = CullMethod::PVertex;
    core::SimdLevel simd = core::SimdLevel::Avx512; // clamped to the CPU's best
    int threads = 1;
    bool count_false_positives = false; // also run the exact test to count them
    // Shadow pass: only shadow casters (not alpha-blended) are in the pass; the
    // others are neither tested nor counted.
    bool casters_only = false;
};

// World AABBs of the scene's instances, as the batch kernels want them.
BoxesSoA instance_boxes(const Scene& scene);

// Per-scene data the passes reuse every frame: boxes, and each instance's draw
// group (dense id of its (mesh, alpha mode, double sided) key) so that a pass
// buckets visible instances in linear time instead of sorting them.
struct CullInput {
    BoxesSoA boxes;
    std::vector<std::uint32_t> group_of;        // per instance
    std::vector<std::uint8_t> transparent;      // per instance: alpha mode BLEND
    std::vector<DrawGroup> group_keys;          // per group id: mesh, alpha, double sided
    std::vector<std::uint32_t> group_triangles; // per group id: triangles per instance
};
CullInput prepare_cull_input(const Scene& scene);

PassResult cull_pass(const CullInput& input, const Frustum& frustum, glm::vec3 eye,
                     const CullOptions& options, std::string pass_name);

// Fixed-capacity history of per-frame statistics, oldest overwritten first.
template <typename T> class RingHistory {
public:
    explicit RingHistory(std::size_t capacity) : items_(capacity) {}
    void push(T v) {
        items_[(start_ + size_) % items_.size()] = std::move(v);
        if (size_ < items_.size())
            ++size_;
        else
            start_ = (start_ + 1) % items_.size();
    }
    std::size_t size() const { return size_; }
    const T& operator[](std::size_t i) const {
        return items_[(start_ + i) % items_.size()];
    } // 0 = oldest
    // The newest item, for results that arrive after it was pushed; size() > 0.
    T& back() { return items_[(start_ + size_ - 1) % items_.size()]; }

private:
    std::vector<T> items_;
    std::size_t start_ = 0, size_ = 0;
};

} // namespace sherpa::scene
