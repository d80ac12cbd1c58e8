#pragma once
// The renderer: owns the pipelines, the bindless table, the shadow map and the
// per-frame resources, holds at most one GpuScene, and records frames either into
// its own offscreen target (render()) or into a caller's image (record_frame(),
// used by the swapchain presenter).
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/gpu/bindless.h>
#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/gpu_structs.h>
#include "pipelines.h"
#include <sherpa/render/render_settings.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/shadow_cascades.h>

namespace sherpa::gpu {

struct PassTiming {
    std::string name;
    double ms = 0.0;
};

// GPU-side measurements of one frame (timestamps and pipeline statistics of the
// camera passes; shadow cascades are timed but not in the statistics).
struct FrameStats {
    std::vector<PassTiming> passes;
    double gpu_ms = 0.0;
    bool shadows_rendered = false; // false when the cached cascades were reused
    std::uint64_t input_primitives = 0, vertex_invocations = 0, clipping_invocations = 0,
                  clipping_primitives = 0, fragment_invocations = 0;
    std::uint64_t draw_calls = 0;
    // Per pass: [0] "camera", then "cascade0".. for each shadow cascade. The camera
    // pass counts the shading draws (opaque, mask, blend) once; the depth prepass
    // repeats its opaque and mask draws and is counted in `prepass`. Cascade
    // statistics come from the last frame that rendered the cascades when they were
    // reused (`shadows_rendered` false). With culling off every instance is visible
    // and nothing is tested.
    std::vector<CullStats> culling;
    CullStats prepass; // depth prepass: draw_calls and triangles only
    const CullStats* pass(std::string_view name) const {
        for (const CullStats& c : culling)
            if (c.pass == name) return &c;
        return nullptr;
    }
};

// One frame's culling statistics, for the renderer's history.
struct CullFrame {
    CullPath path = CullPath::None;
    std::vector<CullStats> passes;
    bool shadows_rendered = false;
};

struct RendererOptions {
    std::uint32_t shadow_resolution = kDefaultShadowResolution;
    // How load(scene) prepares textures; default: no disk cache, BC where supported.
    TextureSettings textures;
};

// A colour image the caller owns, in `layout` before the frame and left in
// `final_layout` after it.
struct RenderTarget {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t width = 0, height = 0;
    VkImageLayout final_layout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
};

class Renderer {
public:
    static constexpr std::uint32_t kFramesInFlight = 2;
    static constexpr VkFormat kOffscreenFormat = VK_FORMAT_R8G8B8A8_SRGB;

    explicit Renderer(Context& context, const RendererOptions& options = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Uploads `scene`, replacing the current one (freed once frames using it finish).
    // Prepares its textures first, on this thread, with texture_settings().
    void load(const Scene& scene, StreamPolicy policy = StreamPolicy::UsedByMaterials);
    // The same with textures already prepared for `scene` (prepare_scene_textures()
    // with context().info(), e.g. on a loader thread); only the upload happens here.
    void load(const Scene& scene, std::shared_ptr<const tex::PreparedTextureSet> textures,
              StreamPolicy policy = StreamPolicy::UsedByMaterials);
    const TextureSettings& texture_settings() const { return options_.textures; }
    void set_texture_settings(const TextureSettings& settings) { options_.textures = settings; }
    void unload();
    const GpuScene* scene() const { return scene_.get(); }

    // Renders one frame offscreen and waits for it. With `rgba` set, reads the
    // image back as tightly packed sRGB-encoded RGBA8 rows, top row first.
    FrameStats render(const RenderSettings& settings, std::vector<std::uint8_t>* rgba = nullptr);

    // Swapchain path: waits until frame slot `slot` is free, records the frame into
    // `cmd` (already begun) drawing into `target`. The caller submits `cmd` with the
    // value from `resources().begin_submission()` and passes it to finish_frame().
    void record_frame(VkCommandBuffer cmd, std::uint32_t slot, const RenderTarget& target,
                      const RenderSettings& settings);
    void finish_frame(std::uint32_t slot, std::uint64_t submission);
    // Waits until the last frame recorded in `slot` has completed on the GPU.
    void wait_for_slot(std::uint32_t slot);
    // Results of the last completed frame recorded in `slot` (waits for it).
    FrameStats slot_stats(std::uint32_t slot);

    // Culling statistics of the last frames whose results were read (render(),
    // slot_stats()), oldest first: what the editor's culling dock charts.
    static constexpr std::size_t kCullHistory = 240;
    const RingHistory<CullFrame>& cull_history() const { return cull_history_; }

    ResourceManager& resources() { return *resources_; }
    Context& context() { return context_; }
    // Bytes of the renderer's own images (offscreen target, depth, shadow map).
    std::uint64_t render_target_bytes() const;

private:
    struct FrameSlot;
    struct Lighting;
    struct Culling;
    void adopt(const Scene& scene);
    void build_culling();
    void build_gpu_culling();
    // Culls the camera and (when `cascades` > 0) each shadow cascade.
    void cull_frame(VkCommandBuffer cmd, FrameSlot& slot, const RenderSettings& settings,
                    float aspect, std::uint32_t cascades);
    void cull_pass_cpu(FrameSlot& slot, std::uint32_t pass, CullMethod method, bool blended_only);
    void read_cull_stats(FrameSlot& slot, FrameStats& out);
    // Draw of one group in pass `pass` (0 camera, 1 + c cascade c) with the frame's
    // culling, tallied into `tally`; false: nothing to draw.
    bool draw_culled(VkCommandBuffer cmd, FrameSlot& slot, VkPipelineLayout layout,
                     std::size_t group, std::uint32_t pass, GPUPushConstants& pc, CullStats& tally);
    void draw_cull_overlay(VkCommandBuffer cmd, FrameSlot& slot, const Pipelines& p);
    void draw_highlight(VkCommandBuffer cmd, FrameSlot& slot, const Pipelines& p,
                        const RenderSettings& s);
    void draw_lines(VkCommandBuffer cmd, FrameSlot& slot, const Pipelines& p,
                    const std::vector<GPULineVertex>& lines);
    void wait_slot(FrameSlot& slot);
    void ensure_offscreen(std::uint32_t width, std::uint32_t height);
    void ensure_depth(std::uint32_t width, std::uint32_t height);
    void init_shadow_map();
    Pipelines& pipelines_for(VkFormat format);
    void create_frame_sets();
    void bind_frame_set(FrameSlot& slot);
    void fill_frame_data(FrameSlot& slot, const RenderSettings& settings, float aspect,
                         bool& shadows, std::uint32_t& cascades);
    void record_passes(VkCommandBuffer cmd, FrameSlot& slot, const RenderTarget& target,
                       const RenderSettings& settings);
    void record_shadows(VkCommandBuffer cmd, FrameSlot& slot, Pipelines& p, std::uint32_t cascades);
    void draw_groups(VkCommandBuffer cmd, FrameSlot& slot, Pipelines& p, DrawPipeline pipeline,
                     AlphaMode alpha, std::uint32_t cascade, bool cull, CullStats& tally);
    // Blended instances back to front, one draw each; draws and triangles go to `tally`.
    void draw_blended(VkCommandBuffer cmd, FrameSlot& slot, Pipelines& p, DrawPipeline pipeline,
                      CullStats& tally);
    void draw_overlays(VkCommandBuffer cmd, FrameSlot& slot, const Pipelines& p,
                       const RenderSettings& s);
    FrameStats read_stats(FrameSlot& slot);

    Context& context_;
    RendererOptions options_;
    std::unique_ptr<ResourceManager> resources_;
    std::unique_ptr<BindlessTable> bindless_;
    UniqueDescriptorSetLayout frame_layout_;
    UniqueDescriptorPool frame_pool_;
    BufferHandle no_materials_; // bound while no scene is loaded
    std::map<VkFormat, std::unique_ptr<Pipelines>> pipelines_;
    std::unique_ptr<GpuScene> scene_;
    std::unique_ptr<Lighting> lighting_; // lights, cameras and bounds of the loaded scene
    std::unique_ptr<Culling> culling_;   // per loaded scene
    std::uint64_t scene_generation_ = 0;
    std::vector<std::unique_ptr<FrameSlot>> slots_;
    std::uint32_t next_slot_ = 0;
    ImageHandle color_, depth_, shadow_map_;
    SamplerHandle shadow_sampler_;
    BufferHandle readback_;
    bool shadow_map_valid_ = false;
    std::vector<std::uint8_t> shadow_key_; // inputs of the cached cascades
    std::vector<CullStats> cascade_stats_; // of the last frame that rendered the cascades
    RingHistory<CullFrame> cull_history_{kCullHistory};
};

} // namespace sherpa::gpu
