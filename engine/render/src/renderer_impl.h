#pragma once
// The Renderer's inside (private to the render layer): frame resources, targets,
// pipelines and the passes, in frame order in record_passes() (renderer_frame.cpp).
#include "comparison_pass.h"
#include "environment_map.h"
#include "passes.h"
#include "path_trace_pass.h"
#include "rt_view_pass.h"

#include <sherpa/gpu/bindless.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_scene.h>

#include <map>

namespace sherpa::gpu {

// The sun the frame is lit and shadowed by (frame_data.cpp).
struct MainSun {
    bool present = false;
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // unit, the way light travels
    glm::vec3 radiance{0.0f};
    std::int64_t placed_light = -1; // its Scene::placed_lights index; -1: default sun or none
};
MainSun main_sun(const Scene& lighting, const FrameRequest& settings);

class Renderer::Impl {
public:
    static constexpr VkFormat kOffscreenFormat = VK_FORMAT_R8G8B8A8_SRGB;
    Impl(Context& context, const RendererOptions& options);
    ~Impl();

    void load(const Scene& scene, std::unique_ptr<GpuScene> gpu_scene, const SceneSetup& setup);
    void unload();
    FrameStats render(const FrameRequest& settings, std::vector<std::uint8_t>* rgba);
    // Swapchain path: waits until frame slot `slot` is free, records the frame into
    // `cmd` (already begun) drawing into `target`. The caller submits `cmd` with the
    // value from `resources().begin_submission()` and passes it to finish_frame().
    void record_frame(VkCommandBuffer cmd, std::uint32_t slot, const RenderTarget& target,
                      const FrameRequest& settings);
    void finish_frame(std::uint32_t slot, std::uint64_t submission);
    // Results of the last completed frame recorded in `slot` (waits for it).
    FrameStats slot_stats(std::uint32_t slot);
    std::uint64_t render_target_bytes() const;
    // The presenter's reduced-resolution image (`format`, width x height, colour
    // attachment and blit source), made or remade when the size changes.
    const Image& scaled_target(VkFormat format, std::uint32_t width, std::uint32_t height);

    // A comparison side or a presented ray-traced frame (renderer_side.cpp): records
    // `settings` (its width x height) with frame slot `slot` into an image of this
    // renderer that shaders can read, returned with its layout. The caller submits
    // and calls finish_frame() as for record_frame().
    SideImage record_side(VkCommandBuffer cmd, std::uint32_t slot, const FrameRequest& settings);
    // Throws GpuError for settings this renderer refuses to draw (the ray tracer's
    // views, overlays, poses), before anything is recorded.
    void check_drawable(const FrameRequest& settings) const;
    // The compositing pass (comparison_pass.h), made on first use.
    ComparisonPass& comparison();
    // Offscreen comparisons (comparison.cpp): frame slot `slot`'s command recorder,
    // the offscreen target of that size (left in TRANSFER_SRC layout by the frame),
    // its copy into the readback buffer, and the rows read back once complete.
    CommandRecorder& recorder(std::uint32_t slot) { return slots_.at(slot)->recorder; }
    RenderTarget offscreen_target(std::uint32_t width, std::uint32_t height);
    void record_readback(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height);
    void read_offscreen(std::vector<std::uint8_t>& rgba, std::uint32_t width,
                        std::uint32_t height) const;

    Context& context;
    RendererOptions options;
    SceneSetup setup; // of the scene loaded (or to be loaded)
    std::unique_ptr<ResourceManager> resources;
    std::unique_ptr<BindlessTable> bindless;
    std::unique_ptr<GpuScene> scene;
    // With RendererOptions::ray_tracing: the scene's BLAS/TLAS and the ray-traced views.
    std::unique_ptr<SceneAccelerationStructures> acceleration;
    CullingPass culling;
    std::unique_ptr<EnvironmentMap> environment; // null: none (set_environment)
    void set_environment(const EnvironmentImage* image);
    // The path tracer's accumulation read back (renderer_path.cpp).
    PathTraceImage path_trace_image();

private:
    // A frame, pass by pass.
    void record_passes(FrameContext& f);
    void begin_frame(FrameContext& f);
    void bind_frame(FrameContext& f);
    void begin_camera_rendering(FrameContext& f);
    void end_camera_rendering(FrameContext& f);
    void timestamp(FrameContext& f, std::uint32_t index);
    // Camera, lights, cascades and view into the slot's GPUFrameData; sets
    // f.cascades to the cascades that must be drawn this frame (frame_data.cpp).
    void write_frame_data(FrameContext& f);
    GPUFrameData lighting_constants(const FrameRequest& settings) const;
    Aabb shadow_bounds(const FrameContext& f) const;
    void create_frame_sets();
    void bind_frame_set(FrameSlot& slot);
    void wait_slot(FrameSlot& slot);
    // Keeps `image` a colour attachment and transfer source of this format and size;
    // true when it was (re)made.
    bool ensure_color_target(ImageHandle& image, VkFormat format, std::uint32_t width,
                             std::uint32_t height, const char* name);
    void ensure_offscreen(std::uint32_t width, std::uint32_t height);
    void ensure_depth(std::uint32_t width, std::uint32_t height);
    Pipelines& pipelines_for(VkFormat format);
    FrameStats read_stats(FrameSlot& slot);
    // A ray-traced side (renderer_side.cpp): its timestamps and statistics.
    void begin_rt_side(VkCommandBuffer cmd, FrameSlot& slot);
    void end_rt_side(VkCommandBuffer cmd, FrameSlot& slot);
    FrameStats read_rt_stats(FrameSlot& slot);
    // FrameRequest::renderer = RayTraced (renderer_rt.cpp).
    FrameStats render_rt(const FrameRequest& settings, std::vector<std::uint8_t>* rgba);
    // Writes the pose of `settings` into `slot` (not in flight) and, when the
    // acceleration structures hold another pose, poses them; true when it did.
    bool pose_acceleration(FrameSlot& slot, const FrameRequest& settings);
    void check_rt(const FrameRequest& settings) const;
    // The ray tracer's frame of `settings` (the TLAS must exist).
    RayTracedFrame rt_frame(const FrameRequest& settings, const FrameSlot& data_slot) const;
    SideImage record_rt_side(VkCommandBuffer cmd, FrameSlot& slot, const FrameRequest& settings);
    // The path tracer's samples of `settings` (view lit) into `cmd`, its constants into
    // `slot` (no frame in flight): continues the accumulation or starts it over.
    PathTraceFrame record_path(VkCommandBuffer cmd, FrameSlot& slot, const FrameRequest& settings,
                               bool readback);

    // SceneSetup::hidden_nodes into the culling (and, with `rt`, the TLAS: every
    // slot must be idle) when it differs from the mask applied last
    // (renderer_visibility.cpp).
    void apply_visibility(bool rt);
    void load_visibility(const Scene& source); // a scene was loaded

    std::unique_ptr<RtViewPass> rt_views_;
    std::unique_ptr<PathTracePass> path_;
    std::unique_ptr<EnvironmentDistribution> environment_distribution_;
    std::uint64_t path_environment_ = ~0ull; // environment generation path_ samples
    std::uint64_t path_key_ = 0;             // what the accumulation is of
    std::uint32_t path_samples_ = 0;
    PathTraceFrame last_path_; // of the last presented or compared path-traced side
    // Visibility: the loaded scene's nodes (the subtree rule), the node of each GPU
    // instance, the mask last applied (as given) and its subtree-expanded form, and
    // whether the TLAS holds that form.
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> instance_node_;
    std::vector<bool> hidden_given_, hidden_nodes_;
    std::uint64_t visibility_version_ = 0;
    bool tlas_visibility_ = true;
    // The pose the acceleration structures hold (FrameSlot::pose_key, of this scene load).
    std::uint64_t rt_pose_key_ = 0, rt_pose_generation_ = 0;

    PosePass pose_;
    ShadowPass shadows_;
    FloorPass floor_;
    DepthPrepass prepass_;
    ForwardPass opaque_{AlphaMode::Opaque}, mask_{AlphaMode::Mask}, blend_{AlphaMode::Blend};
    BackgroundPass background_;
    OverlayPass overlays_{pose_};
    HighlightPass highlight_;

    UniqueDescriptorSetLayout frame_layout_;
    UniqueDescriptorPool frame_pool_;
    BufferHandle no_materials_; // bound while no scene is loaded
    std::map<VkFormat, std::unique_ptr<Pipelines>> pipelines_;
    // Only bounds, lights and cameras (what camera and light resolution needs).
    Scene lighting_;
    std::uint64_t scene_generation_ = 0;
    std::uint64_t environment_generation_ = 0; // counts set_environment()
    std::vector<std::unique_ptr<FrameSlot>> slots_;
    std::uint32_t next_slot_ = 0;
    std::unique_ptr<ComparisonPass> comparison_;
    ImageHandle color_, depth_, scaled_;
    ImageHandle side_; // record_side's raster image (sampled by the comparison pass)
    BufferHandle readback_;
};

} // namespace sherpa::gpu
