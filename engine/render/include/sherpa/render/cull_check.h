#pragma once
// The GPU culling shader (shaders/cull.comp) checked against the CPU culling of the
// same frustum: what `sherpa-cli cull --method gpu` reports and what the editor's
// culling dock shows. One culler over every instance (the camera's view) and one
// over the shadow casters (a cascade's view), built for one scene.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <sherpa/scene/culling_passes.h>

namespace sherpa::gpu {
class Context;
class ResourceManager;
} // namespace sherpa::gpu

namespace sherpa::render {

class GpuCuller;
class GpuCullPipeline;

// One GPU run against the CPU's visible flags of the same view.
struct GpuCullComparison {
    double gpu_ms = 0.0;
    std::uint32_t objects = 0;          // instances the view tests
    std::uint32_t batches = 0;          // indirect draws (one per batch)
    std::vector<std::uint32_t> visible; // scene instances the GPU kept
    std::int64_t differences = 0;       // instances where GPU and CPU disagree
};

class GpuCullChecker {
public:
    // Builds the camera culler for `scene` (which must outlive this); the casters'
    // culler is built on first use.
    GpuCullChecker(gpu::Context& context, gpu::ResourceManager& resources,
                   const scene::Scene& scene);
    ~GpuCullChecker();
    GpuCullChecker(const GpuCullChecker&) = delete;
    GpuCullChecker& operator=(const GpuCullChecker&) = delete;

    const scene::Scene& scene() const { return scene_; }
    // Runs `frustum` over every instance (camera) or the shadow casters (`casters`)
    // and compares with `cpu_visible` (per scene instance, 1 = kept; missing
    // entries count as culled).
    GpuCullComparison compare(const scene::Frustum& frustum, scene::CullMethod method,
                              std::span<const std::uint8_t> cpu_visible, bool casters = false);

private:
    GpuCuller& culler(bool casters);
    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    const scene::Scene& scene_;
    std::shared_ptr<const GpuCullPipeline> pipeline_; // one compile for both cullers
    std::unique_ptr<GpuCuller> camera_, casters_;
};

// Culls each named frustum on the GPU (p-vertex test; the first over every
// instance, the rest over the shadow casters, as the renderer's camera and
// cascades) and checks each against the CPU p-vertex result `cpu` of the same
// pass, into `out` (one PassResult per frustum). Returns false with `error` set
// when no Vulkan device can be used.
bool gpu_cull_passes(const scene::Scene& scene,
                     const std::vector<std::pair<std::string, scene::Frustum>>& frusta,
                     const std::vector<scene::PassResult>& cpu, std::vector<scene::PassResult>& out,
                     std::string& error);

} // namespace sherpa::render
