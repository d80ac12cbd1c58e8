// The ray-traced frame (FrameRequest::renderer = RayTraced): primary rays through
// the scene's acceleration structures, built on load, drawing the surface-data
// debug views with the rasterizer's formulas (rt_view_pass.h), or the path-traced lit
// view (path_trace_pass.h, renderer_path.cpp). Views and overlays the ray tracer has
// no formula for are refused, never drawn as something else.
#include "frame_recorder.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>
#include <sherpa/scene/animation.h>
#include <sherpa/texture/mips.h>

#include <cmath>

namespace sherpa::render {
namespace {

std::uint8_t srgb_byte(float linear) {
    return static_cast<std::uint8_t>(
        std::lround(tex::linear_to_srgb(std::clamp(linear, 0.0f, 1.0f)) * 255.0f));
}

std::string ray_traced_view_names() {
    std::string out;
    for (const DebugViewInfo& v : kDebugViews)
        if (ray_traced_view(v.id)) out += (out.empty() ? "" : ", ") + std::string(v.name);
    return out;
}

} // namespace

RayTracedFrames::RayTracedFrames(SceneState& scene_state, FrameSlots& slots, SceneChanges& changes,
                                 PosePass& pose, const ShadowPass& shadows)
    : SceneStateRefs(scene_state), slots_(slots), changes_(changes), pose_(pose), shadows_(shadows),
      path_(scene_state, slots) {}

bool RayTracedFrames::traces() const {
    return acceleration && acceleration->tlas() != VK_NULL_HANDLE;
}

bool RayTracedFrames::pose_acceleration(FrameSlot& slot, const FrameRequest& settings) {
    if (!acceleration || !pose_.active()) return false;
    pose_.record(slot, settings, scene != nullptr);
    // The structures hold this pose already (a paused timeline, the default pose).
    if (!slot.posed ||
        (state.rt_pose_key == slot.pose_key && state.rt_pose_generation == state.generation))
        return false;
    PoseFrame frame;
    frame.instances = slot.posed_instances;
    frame.pose = slot.pose_address;
    frame.highlight_base = slot.highlight_base;
    frame.node_world = pose_.pose_of(settings).world;
    acceleration->update_pose(frame);
    state.rt_pose_key = slot.pose_key;
    state.rt_pose_generation = state.generation;
    return true;
}

void RayTracedFrames::check_rt(const FrameRequest& settings) const {
    if (!acceleration)
        throw gpu::GpuError(
            "the ray tracer needs the scene's acceleration structures: create the "
            "renderer with RendererOptions::ray_tracing on a device that ray traces");
    if (!ray_traced_view(settings.view))
        throw gpu::GpuError("the ray tracer does not draw view '" +
                            std::string(to_string(settings.view)) + "' (it draws " +
                            ray_traced_view_names() + ")");
    if (settings.overlays != 0 || settings.highlight_instance ||
        !settings.highlight_outline.empty())
        throw gpu::GpuError("the ray tracer draws no overlays or highlights (raster only)");
}

RayTracedFrame RayTracedFrames::rt_frame(const FrameRequest& settings,
                                         const FrameSlot& data_slot) const {
    const CameraView camera = resolve_camera(settings.camera, state.lights.cameras,
                                             float(settings.width) / float(settings.height));
    RayTracedFrame f;
    f.bindless = bindless->set();
    f.tlas = acceleration->tlas();
    f.materials = scene->materials().buffer();
    f.material_extras = scene->materials().extras_buffer();
    f.width = settings.width;
    f.height = settings.height;
    f.push.inv_view_proj = glm::inverse(camera.proj * camera.view);
    f.push.geometries = acceleration->geometry_records();
    f.push.view = static_cast<std::uint32_t>(settings.view);
    f.push.texture_lod = settings.texture_lod;
    f.push.clear_color = settings.clear_color;
    f.frame_data = resources->get(data_slot.frame_data).buffer.get();
    f.shadow_map = shadows_.descriptor();
    const MainSun sun = main_sun(state.lights, settings);
    f.push.sun = glm::vec4(-sun.direction, std::max(settings.sun_angular_radius, 0.0f));
    // As the rasterizer: no sun or no shadows, and only the facing rule remains.
    f.push.shadow_rays = sun.present && settings.shadows ? std::max(settings.shadow_rays, 1u) : 0u;
    f.push.ao_rays = settings.ao_rays;
    const core::Aabb& bounds = state.lights.cameras.bounds;
    const float diagonal = bounds.valid() ? glm::length(bounds.extent()) : 1.0f;
    f.push.ao_radius = settings.ao_radius > 0.0f ? settings.ao_radius : 0.05f * diagonal;
    return f;
}

FrameStats RayTracedFrames::render_rt(const FrameRequest& settings, std::vector<std::uint8_t>* rgba,
                                      std::uint32_t raster_slot) {
    check_rt(settings);
    // Its descriptor set is rewritten per frame, and the structures are posed below:
    // no earlier frame may be in flight.
    slots_.wait_all();
    changes_.apply_scene_changes(settings, true);
    if (!rt_views_)
        rt_views_ = std::make_unique<RtViewPass>(context, *resources, bindless->layout());
    const std::uint32_t index = slots_.take();
    FrameSlot& slot = slots_[index];
    FrameStats stats;
    // Moving meshes and node transforms of this frame's pose (FrameRequest::pose,
    // else the file's default pose) into the structures, when it is not the pose they hold.
    if (pose_acceleration(slot, settings)) {
        const AccelerationStats& a = acceleration->stats();
        if (a.posed.pose_ms >= 0.0) stats.passes.push_back({"pose_vertices", a.posed.pose_ms});
        if (a.posed.blas_ms >= 0.0) stats.passes.push_back({"posed_blas", a.posed.blas_ms});
        if (a.tlas.build_ms >= 0.0) stats.passes.push_back({"tlas", a.tlas.build_ms});
    }
    const VkAccelerationStructureKHR tlas = acceleration->tlas();
    if (tlas == VK_NULL_HANDLE) { // nothing with triangles: every ray misses
        if (rgba) {
            rgba->resize(std::size_t(settings.width) * settings.height * 4);
            const std::uint8_t c[4] = {srgb_byte(settings.clear_color.r),
                                       srgb_byte(settings.clear_color.g),
                                       srgb_byte(settings.clear_color.b), 255};
            for (std::size_t i = 0; i < rgba->size(); ++i) (*rgba)[i] = c[i % 4];
        }
        return stats;
    }
    const bool path = settings.view == DebugView::Lit; // the path tracer (renderer_path.cpp)
    VkCommandBuffer cmd = slot.recorder.begin();
    const bool timed = context.info().timestamps;
    if (timed) {
        vkCmdResetQueryPool(cmd, slot.timestamps.get(), 0, 2);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_NONE, slot.timestamps.get(), 0);
    }
    if (path)
        stats.path = path_.record(cmd, slot, settings, rgba != nullptr);
    else
        rt_views_->record(cmd, rt_frame(settings, slots_[raster_slot]));
    if (timed)
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, slot.timestamps.get(), 1);
    slot.submission = slot.recorder.submit(*resources);
    slot.has_results = false; // its queries hold this frame's two timestamps only
    slots_.wait(slot);
    if (timed) {
        std::uint64_t ts[2] = {};
        gpu::vk_check(vkGetQueryPoolResults(context.device(), slot.timestamps.get(), 0, 2,
                                            sizeof(ts), ts, sizeof(std::uint64_t),
                                            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                      "vkGetQueryPoolResults(rt timestamps)");
        stats.gpu_ms = double(ts[1] - ts[0]) * context.info().timestamp_period_ns * 1e-6;
        stats.passes.push_back({path ? "path_trace" : "rays", stats.gpu_ms});
        for (const PassTiming& p : stats.passes)
            if (p.name != "rays" && p.name != "path_trace") stats.gpu_ms += p.ms;
    }
    if (rgba && path) path_.read(*rgba);
    if (rgba && !path) rt_views_->read(*rgba);
    resources->collect_garbage();
    return stats;
}

} // namespace sherpa::render
