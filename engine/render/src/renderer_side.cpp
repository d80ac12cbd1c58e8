// The renderer as one side of a comparison, or a presented ray-traced frame: the
// frame recorded into an image of the renderer that the comparison pass samples
// (comparison_pass.h), raster or ray traced, with the presenter's frame slots.
#include "frame_recorder.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>

namespace sherpa::render {

void RayTracedFrames::check_drawable(const FrameRequest& settings) const {
    if (settings.renderer != RendererKind::RayTraced) return;
    check_rt(settings);
    // It draws the rasterizer's shadow frame first and waits for it (render_offscreen): not
    // inside a frame another recorder owns.
    if (settings.view == DebugView::ShadowError)
        throw gpu::GpuError(
            "the shadow-error view is drawn offscreen only (sherpa-cli render, the Lab's "
            "shadows family), not in presented or compared frames");
}

ComparisonPass& FrameRecorder::comparison() {
    if (!comparison_)
        comparison_ = std::make_unique<ComparisonPass>(context, *resources, kFramesInFlight);
    return *comparison_;
}

SideImage record_side(FrameRecorder& frames, VkCommandBuffer cmd, std::uint32_t index,
                      const FrameRequest& settings) {
    FrameSlot& slot = frames.slots()[index];
    RayTracedFrames& rays = frames.rays();
    if (settings.renderer == RendererKind::RayTraced && rays.traces())
        return rays.record_rt_side(cmd, slot, settings);
    rays.check_drawable(settings);
    const gpu::Image& image = frames.targets().side(settings.width, settings.height);
    if (settings.renderer == RendererKind::RayTraced) {
        // Nothing with triangles to trace: every ray misses, the clear colour.
        frames.slots().wait_all();
        rays.begin_rt_side(cmd, slot);
        gpu::transition(
            cmd, {image.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
        const glm::vec4 c = settings.clear_color;
        const VkClearColorValue clear{{c.r, c.g, c.b, 1.0f}};
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cmd, image.image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear,
                             1, &range);
        gpu::transition(
            cmd, {image.image.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
        rays.end_rt_side(cmd, slot);
        return {image.alias_view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    slot.ray_traced = false;
    const gpu::RenderTarget target{
        image.image.get(), image.view.get(), FrameRecorder::kOffscreenFormat,
        settings.width,    settings.height,  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    frames.record_frame(cmd, index, target, settings);
    return {image.alias_view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

SideImage RayTracedFrames::record_rt_side(VkCommandBuffer cmd, FrameSlot& slot,
                                          const FrameRequest& settings) {
    check_rt(settings);
    // The ray tracer's descriptor set and image are rewritten per frame: no earlier
    // frame of this renderer may still be in flight (a presented RT frame waits for
    // the previous one; rays on lavapipe take far longer than that wait).
    slots_.wait_all();
    changes_.apply_scene_changes(settings, true);
    if (!rt_views_)
        rt_views_ = std::make_unique<RtViewPass>(context, *resources, bindless->layout());
    // This frame's pose into the structures (submitted and waited for on its own),
    // when they hold another one.
    pose_acceleration(slot, settings);
    begin_rt_side(cmd, slot);
    slot.path_traced = settings.view == DebugView::Lit;
    if (slot.path_traced) { // path traced, accumulating while nothing changes
        last_path_ = path_.record(cmd, slot, settings, false);
        end_rt_side(cmd, slot);
        return {path_.view(), VK_IMAGE_LAYOUT_GENERAL};
    }
    rt_views_->record(cmd, rt_frame(settings, slot), false);
    end_rt_side(cmd, slot);
    return {rt_views_->view(), VK_IMAGE_LAYOUT_GENERAL};
}

// A ray-traced side has two timestamps, no culling, draws or pipeline statistics.
void RayTracedFrames::begin_rt_side(VkCommandBuffer cmd, FrameSlot& slot) {
    slot.ray_traced = true;
    slot.path_traced = false;   // record_rt_side says otherwise
    slot.history_pushed = true; // no culling to report
    slot.has_results = false;
    slot.draw_calls = 0;
    if (!context.info().timestamps) return;
    vkResetQueryPool(context.device(), slot.timestamps.get(), 0, kTimestampCount);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_NONE, slot.timestamps.get(), 0);
}

void RayTracedFrames::end_rt_side(VkCommandBuffer cmd, FrameSlot& slot) {
    if (context.info().timestamps)
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, slot.timestamps.get(), 1);
}

FrameStats RayTracedFrames::read_rt_stats(FrameSlot& slot) {
    FrameStats s;
    if (slot.path_traced) s.path = last_path_;
    if (!slot.has_results || !context.info().timestamps) return s;
    std::uint64_t ts[2] = {};
    gpu::vk_check(vkGetQueryPoolResults(context.device(), slot.timestamps.get(), 0, 2, sizeof(ts),
                                        ts, sizeof(std::uint64_t),
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  "vkGetQueryPoolResults(rt timestamps)");
    s.gpu_ms = double(ts[1] - ts[0]) * context.info().timestamp_period_ns * 1e-6;
    s.passes.push_back({slot.path_traced ? "path_trace" : "rays", s.gpu_ms});
    return s;
}

} // namespace sherpa::render
