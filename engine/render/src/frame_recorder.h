#pragma once
// How a Renderer records frames (private to the render layer): frame slots, targets,
// pipelines and the passes, in frame order in record_passes() (renderer_frame.cpp),
// over the loaded scene's SceneState (scene_state.h), which it reads. The frame sources
// (PresentedFrame, ComparisonFrame, render_comparison, the path tracer's readback, the
// material variant switch) reach it through Renderer::frames(); outside the render
// layer it is an incomplete type.
#include "comparison_pass.h"
#include "frame_slots.h"
#include "passes.h"
#include "path_trace_pass.h"
#include "render_targets.h"
#include "rt_view_pass.h"
#include "scene_changes.h"
#include "scene_state.h"
#include "transmission_pass.h"

#include <map>

namespace sherpa::gpu {

// The sun the frame is lit and shadowed by (frame_data.cpp).
struct MainSun {
    bool present = false;
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // unit, the way light travels
    glm::vec3 radiance{0.0f};
    std::int64_t placed_light = -1; // its Scene::placed_lights index; -1: default sun or none
};
MainSun main_sun(const SceneLights& lights, const FrameRequest& settings);
// Lights, sun, ambient, environment (null: none) and display transform of a lit frame:
// what the raster's frame constants and the path tracer's share (params.y: the light
// count; frame_data.cpp).
GPUFrameData lighting_constants(const SceneLights& lights, const EnvironmentMap* environment,
                                const FrameRequest& settings);

class FrameRecorder {
public:
    static constexpr VkFormat kOffscreenFormat = RenderTargets::kOffscreenFormat;
    static constexpr std::uint32_t kFramesInFlight = FrameSlots::kFramesInFlight;
    explicit FrameRecorder(SceneState& state);
    ~FrameRecorder();
    FrameRecorder(const FrameRecorder&) = delete;
    FrameRecorder& operator=(const FrameRecorder&) = delete;

    // The state's scene was loaded from `source` (culling, pose, default pose of the
    // acceleration structures), or is about to be unloaded (every frame waited for,
    // the slots' per-scene buffers freed).
    void scene_loaded(const Scene& source);
    void scene_unloading();
    // Waits for every frame in flight. Before the environment is replaced or removed,
    // `environment_goes` also frees the background kept for it.
    void wait_all(bool environment_goes = false);
    FrameStats render(const FrameRequest& settings, std::vector<std::uint8_t>* rgba);
    // Swapchain path: waits until frame slot `slot` is free, records the frame into
    // `cmd` (already begun) drawing into `target`. The caller submits `cmd` with the
    // value from `resources().begin_submission()` and passes it to slots().finish().
    void record_frame(VkCommandBuffer cmd, std::uint32_t slot, const RenderTarget& target,
                      const FrameRequest& settings);
    // The frames in flight: waiting, submission, command recorders.
    FrameSlots& slots() { return slots_; }
    // Results of the last completed frame recorded in `slot` (waits for it).
    FrameStats slot_stats(std::uint32_t slot);
    // Bytes of the recorder's images into `out`: render_target_bytes (targets, shadow
    // map, transmission background) and transmission_target_bytes.
    void count_target_bytes(ResidentStats& out) const;
    // Its images: offscreen target and readback, the presenter's reduced-resolution image.
    RenderTargets& targets() { return targets_; }

    // A comparison side or a presented ray-traced frame (renderer_side.cpp): records
    // `settings` (its width x height) with frame slot `slot` into an image of this
    // renderer that shaders can read, returned with its layout. The caller submits
    // and calls slots().finish() as for record_frame().
    SideImage record_side(VkCommandBuffer cmd, std::uint32_t slot, const FrameRequest& settings);
    // Throws GpuError for settings this renderer refuses to draw (the ray tracer's
    // views, overlays, poses), before anything is recorded.
    void check_drawable(const FrameRequest& settings) const;
    // The compositing pass (comparison_pass.h), made on first use.
    ComparisonPass& comparison();
    // The path tracer's accumulation read back (renderer_path.cpp).
    PathTraceImage path_trace_image();
    // Culling statistics of the frames read (Renderer::cull_history()).
    const RingHistory<CullFrame>& cull_history() const { return culling.history(); }
    // Between frames: animated properties, visibility, the material variant switch.
    SceneChanges& changes() { return changes_; }

private:
    SceneState& state;
    Context& context;
    ResourceManager* const resources;
    BindlessTable* const bindless;
    const RendererOptions& options;
    // The loaded scene's, as the state holds them (null: none).
    const std::unique_ptr<GpuScene>& scene;
    const std::unique_ptr<SceneAccelerationStructures>& acceleration;
    const std::unique_ptr<EnvironmentMap>& environment;
    CullingPass culling;

    // A frame, pass by pass.
    void record_passes(FrameContext& f);
    void begin_frame(FrameContext& f);
    void bind_frame(FrameContext& f);
    void begin_camera_rendering(FrameContext& f, bool background);
    void end_camera_rendering(FrameContext& f);
    void timestamp(FrameContext& f, std::uint32_t index);
    // Camera, lights, cascades and view into the slot's GPUFrameData; sets
    // f.cascades to the cascades that must be drawn this frame (frame_data.cpp).
    void write_frame_data(FrameContext& f);
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


    std::unique_ptr<RtViewPass> rt_views_;
    std::unique_ptr<PathTracePass> path_;
    std::uint64_t path_environment_ = ~0ull; // environment generation path_ samples
    std::uint64_t path_lights_ = ~0ull;      // scene generation path_'s light list is of
    std::uint64_t path_key_ = 0;             // what the accumulation is of
    std::uint32_t path_samples_ = 0;
    PathTraceFrame last_path_; // of the last presented or compared path-traced side

    PosePass pose_;
    ShadowPass shadows_;
    FloorPass floor_;
    DepthPrepass prepass_;
    ForwardPass opaque_{AlphaMode::Opaque}, mask_{AlphaMode::Mask}, blend_{AlphaMode::Blend};
    BackgroundPass background_;
    std::unique_ptr<TransmissionPass> transmission_; // made with the frame slots' set layout
    OverlayPass overlays_{pose_};
    HighlightPass highlight_;

    FrameSlots slots_; // after the passes: their resources are made first
    SceneChanges changes_{state, slots_, culling, shadows_};
    std::map<VkFormat, std::unique_ptr<Pipelines>> pipelines_;
    std::unique_ptr<ComparisonPass> comparison_;
    RenderTargets targets_;
};

} // namespace sherpa::gpu
