#pragma once
// One class per pass of a frame. Each records into FrameContext::cmd; the Renderer
// (renderer_impl.h) owns them and calls them in frame order. A new pass is a class
// here (with `void record(FrameContext&)`) and one line in Renderer::Impl::record_passes.
#include "frame_context.h"

#include <memory>
#include <vector>

namespace sherpa::gpu {

// Culling of the camera and of each shadow cascade re-rendered this frame, on the
// CPU or with shaders/cull.comp (culling_pass.cpp); its statistics once the frame
// completed (culling_stats.cpp). Owns the loaded scene's culling data.
class CullingPass {
public:
    static constexpr std::size_t kHistory = 240;
    CullingPass(Context& context, ResourceManager& resources);
    ~CullingPass();
    void build(const GpuScene& scene); // a scene was loaded
    void reset();                      // the scene is unloaded
    SceneCulling* scene_culling() { return culling_.get(); }
    void record(FrameContext& f);
    // Statistics of the completed frame in `slot` into `out`; pushes it to history().
    void read_stats(FrameSlot& slot, const GpuScene* scene, FrameStats& out);
    const RingHistory<CullFrame>& history() const { return history_; }

private:
    void build_gpu(const GpuScene& scene);
    void test_cpu(FrameContext& f, PassCull& view, bool caster_view, bool blended_only);
    void prepare_buffers(FrameContext& f, std::uint32_t instances);
    Context& context_;
    ResourceManager& resources_;
    std::unique_ptr<SceneCulling> culling_;
    std::vector<CullStats> cascade_stats_; // of the last frame that rendered the cascades
    RingHistory<CullFrame> history_{kHistory};
};

// The shadow cascades of the main directional light, depth only, into one layered
// map that every camera pass samples; re-rendered only when their inputs change.
class ShadowPass {
public:
    ShadowPass(Context& context, ResourceManager& resources, std::uint32_t resolution);
    ~ShadowPass();
    // Whether cascades `c` must be drawn this frame (not `cache` or their inputs
    // changed since the map was last drawn); remembers the inputs when so.
    bool needs_render(const ShadowCascades& c, std::uint64_t scene_generation, bool cache);
    void invalidate() { key_.clear(); } // the scene changed
    VkDescriptorImageInfo descriptor() const;
    std::uint64_t bytes() const;
    std::uint32_t resolution() const { return resolution_; }
    void record(FrameContext& f);

private:
    Context& context_;
    ResourceManager& resources_;
    std::uint32_t resolution_;
    ImageHandle map_;
    SamplerHandle sampler_;
    bool valid_ = false;            // drawn at least once
    std::vector<std::uint8_t> key_; // inputs of the cached cascades
};

// RenderSettings::floor_only: every triangle in one constant colour (what the
// rasterizer costs by itself), instead of the prepass and shading.
class FloorPass {
public:
    void record(FrameContext& f);
};

// Depth of the opaque, then alpha-tested masked, surfaces (FrameContext::prepass).
class DepthPrepass {
public:
    void record(FrameContext& f);
};

// Shading of the draw groups of one alpha mode in the frame's debug view; blended
// instances sorted back to front.
class ForwardPass {
public:
    explicit ForwardPass(AlphaMode alpha) : alpha_(alpha) {}
    void record(FrameContext& f);

private:
    AlphaMode alpha_;
};

// RenderSettings::overlays: wireframe, normal/tangent/bitangent glyphs, instance
// bounds, the culling boxes and the skeleton.
class OverlayPass {
public:
    void record(FrameContext& f);

private:
    void draw_cull_boxes(FrameContext& f);
    void draw_skeleton(FrameContext& f);
};

// The selection (RenderSettings::highlight_*), over everything else.
class HighlightPass {
public:
    void record(FrameContext& f);
};

} // namespace sherpa::gpu
