#pragma once
// How a Renderer records frames (private to the render layer): the raster frame's
// pipelines and passes, in frame order in record_passes() (renderer_frame.cpp), over
// the loaded scene's SceneState (scene_state.h), which it reads; and the parts it
// owns, each reached on its own: the frames in flight (FrameSlots, frame_slots.h),
// the recorder's images (RenderTargets), what changes in the scene between frames
// (SceneChanges, scene_changes.h), the ray-traced frames (RayTracedFrames,
// ray_traced_frames.h, with the path tracer) and the comparison pass. The frame
// sources (render_offscreen, PresentedFrame, ComparisonFrame, render_comparison, the
// path tracer's readback, the material variant switch) reach it through
// Renderer::frames(); outside the render layer it is an incomplete type.
#include "comparison_pass.h"
#include "frame_slots.h"
#include "passes.h"
#include "ray_traced_frames.h"
#include "render_targets.h"
#include "scene_changes.h"
#include "scene_state.h"
#include "transmission_pass.h"

#include <map>

namespace sherpa::render {

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

class FrameRecorder : private SceneStateRefs {
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
    void scene_loaded(const scene::Scene& source);
    void scene_unloading();
    // Waits for every frame in flight. Before the environment is replaced or removed,
    // `environment_goes` also frees the background kept for it.
    void wait_all(bool environment_goes = false);
    // Swapchain path: waits until frame slot `slot` is free, records the frame into
    // `cmd` (already begun) drawing into `target`. The caller submits `cmd` with the
    // value from `resources().begin_submission()` and passes it to slots().finish().
    void record_frame(VkCommandBuffer cmd, std::uint32_t slot, const gpu::RenderTarget& target,
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

    // The compositing pass (comparison_pass.h), made on first use.
    ComparisonPass& comparison();
    // The ray-traced frames (FrameRequest::renderer = RayTraced) and the path tracer;
    // rays().check_drawable() refuses, before anything is recorded, what a presented or
    // compared frame cannot draw.
    RayTracedFrames& rays() { return rays_; }
    // Culling statistics of the frames read (Renderer::cull_history()).
    const scene::RingHistory<CullFrame>& cull_history() const { return culling.history(); }
    // Between frames: animated properties, visibility, the material variant switch.
    SceneChanges& changes() { return changes_; }

private:
    const RendererOptions& options;
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
    // Results of the completed raster frame in `slot` (a ray-traced one: the rays').
    FrameStats read_stats(FrameSlot& slot);

    PosePass pose_;
    ShadowPass shadows_;
    FloorPass floor_;
    DepthPrepass prepass_;
    ForwardPass opaque_{scene::AlphaMode::Opaque}, mask_{scene::AlphaMode::Mask},
        blend_{scene::AlphaMode::Blend};
    BackgroundPass background_;
    std::unique_ptr<TransmissionPass> transmission_; // made with the frame slots' set layout
    OverlayPass overlays_{pose_};
    HighlightPass highlight_;

    FrameSlots slots_; // after the passes: their resources are made first
    SceneChanges changes_{state, slots_, culling, shadows_};
    RayTracedFrames rays_{state, slots_, changes_, pose_, shadows_};
    std::map<VkFormat, std::unique_ptr<Pipelines>> pipelines_;
    std::unique_ptr<ComparisonPass> comparison_;
    RenderTargets targets_;
};

// An offscreen frame of `settings` (FrameRequest::renderer picks the raster or the ray
// tracer) into the recorder's offscreen target, submitted and waited for; with `rgba`,
// read back as tightly packed sRGB-encoded RGBA8 rows, top row first (Renderer::render()).
FrameStats render_offscreen(FrameRecorder& frames, gpu::ResourceManager& resources,
                            const FrameRequest& settings, std::vector<std::uint8_t>* rgba);

// A comparison side or a presented ray-traced frame (renderer_side.cpp): records
// `settings` (its width x height) with frame slot `slot` into an image of `frames`'
// renderer that shaders can read, returned with its layout. The caller submits and
// calls slots().finish() as for FrameRecorder::record_frame().
SideImage record_side(FrameRecorder& frames, VkCommandBuffer cmd, std::uint32_t slot,
                      const FrameRequest& settings);

} // namespace sherpa::render
