#pragma once
// The renderer's ray-traced frames (FrameRequest::renderer = RayTraced; private to the
// render layer): primary rays through the loaded scene's acceleration structures
// drawing the surface-data debug views (RtViewPass, rt_view_pass.h), or the
// path-traced lit view (PathTracer, path_tracer.h); offscreen (renderer_rt.cpp) or as
// a comparison side or presented frame (renderer_side.cpp). What the ray tracer has no
// formula for is refused, never drawn as something else. It records into the
// renderer's frame slots, applies the scene's changes before a frame as the raster
// does, and poses the acceleration structures with the raster's pose pass.
#include "path_tracer.h"
#include "rt_view_pass.h"
#include "scene_changes.h"

namespace sherpa::render {

class RayTracedFrames : private SceneStateRefs {
public:
    RayTracedFrames(SceneState& state, FrameSlots& slots, SceneChanges& changes, PosePass& pose,
                    const ShadowPass& shadows);
    RayTracedFrames(const RayTracedFrames&) = delete;
    RayTracedFrames& operator=(const RayTracedFrames&) = delete;

    // Throws GpuError for settings the ray tracer refuses to draw (no acceleration
    // structures, views without a ray formula, another material variant than loaded,
    // overlays and highlights).
    void check_rt(const FrameRequest& settings) const;
    // Throws GpuError for settings this renderer refuses to draw in a presented or
    // compared frame (the ray tracer's refusals, the shadow-error view), before
    // anything is recorded; raster settings pass.
    void check_drawable(const FrameRequest& settings) const;
    // Whether there is anything to trace (a TLAS over triangles); without, every ray misses.
    bool traces() const;
    // An offscreen frame of `settings`, waited for; with `rgba`, read back. The
    // shadow-error view reads the raster frame recorded last in `raster_slot`.
    FrameStats render_rt(const FrameRequest& settings, std::vector<std::uint8_t>* rgba,
                         std::uint32_t raster_slot);
    // A comparison side or presented frame (traces() must hold): the rays' or the path
    // tracer's image of `settings` recorded into `cmd` with `slot`, in GENERAL layout.
    SideImage record_rt_side(VkCommandBuffer cmd, FrameSlot& slot, const FrameRequest& settings);
    // A ray-traced side's two timestamps around what it records.
    void begin_rt_side(VkCommandBuffer cmd, FrameSlot& slot);
    void end_rt_side(VkCommandBuffer cmd, FrameSlot& slot);
    // Results of the completed ray-traced side in `slot`: its time, its accumulation.
    FrameStats read_rt_stats(FrameSlot& slot);
    // Writes the pose of `settings` into `slot` (not in flight) and, when the
    // acceleration structures hold another pose, poses them; true when it did.
    bool pose_acceleration(FrameSlot& slot, const FrameRequest& settings);
    // The path tracer's accumulation (read_path_trace()).
    PathTracer& path() { return path_; }

private:
    // The ray tracer's frame of `settings` (the TLAS must exist).
    RayTracedFrame rt_frame(const FrameRequest& settings, const FrameSlot& data_slot) const;

    FrameSlots& slots_;
    SceneChanges& changes_;
    PosePass& pose_;
    const ShadowPass& shadows_; // the cascades the shadow-error view compares with

    std::unique_ptr<RtViewPass> rt_views_;
    PathTracer path_;
    PathTraceFrame last_path_; // of the last presented or compared path-traced side
};

} // namespace sherpa::render
