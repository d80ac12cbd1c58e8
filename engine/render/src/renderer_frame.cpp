// A frame as the Renderer records it: frame constants, then the passes in order
// (record_passes), with a timestamp after each timed pass and the pipeline
// statistics around the camera's passes.
#include "draw.h"
#include "frame_recorder.h"

#include <sherpa/render/gpu_structs.h>

namespace sherpa::render {

namespace {

// Timestamp indices: kPassNames[i] spans [i, i + 1].
enum Timestamp : std::uint32_t {
    kFrameStart,
    kAfterShadows,
    kAfterTransmission,
    kAfterPrepass,
    kAfterOpaque,
    kAfterMask,
    kAfterBlend,
    kAfterOverlays,
};
static_assert(kAfterOverlays + 1 == kTimestampCount);

} // namespace

void FrameRecorder::record_frame(VkCommandBuffer cmd, std::uint32_t index,
                                 const gpu::RenderTarget& target, const FrameRequest& settings) {
    changes_.apply_scene_changes(settings, false);
    FrameSlot& slot = slots_[index];
    slots_.wait(slot);
    // Frames nobody read the results of (the swapchain path) still reach the
    // culling history, before this slot's queries are reset.
    if (slot.has_results && !slot.history_pushed) {
        FrameStats unused;
        culling.read_stats(slot, scene.get(), unused);
    }
    vkResetQueryPool(context.device(), slot.timestamps.get(), 0, kTimestampCount);
    if (slot.statistics) vkResetQueryPool(context.device(), slot.statistics.get(), 0, 1);
    slot.has_results = false;
    slot.ray_traced = false;
    slot.draw_calls = 0;
    FrameContext f{
        cmd,     slot,       index,       pipelines_for(target.format), settings,    target,
        context, *resources, scene.get(), culling.scene_culling(),      state.lights};
    f.environment = environment.get();
    record_passes(f);
}

void FrameRecorder::record_passes(FrameContext& f) {
    pose_.record(f); // before the frame data: the shadow fit and cache read the pose
    begin_frame(f);
    transmission_->prepare(f); // writes the slot's set: before it is bound
    culling.record(f);
    bind_frame(f);
    timestamp(f, kFrameStart);
    shadows_.record(f);
    timestamp(f, kAfterShadows);
    transmission_->record(f); // only scenes with a transmissive material
    timestamp(f, kAfterTransmission);
    // The environment behind the surfaces, drawn or copied into the target first.
    begin_camera_rendering(f, background_.prepare(f));
    floor_.record(f);
    prepass_.record(f);
    timestamp(f, kAfterPrepass);
    opaque_.record(f);
    timestamp(f, kAfterOpaque);
    mask_.record(f);
    timestamp(f, kAfterMask);
    blend_.record(f);
    timestamp(f, kAfterBlend);
    overlays_.record(f);
    highlight_.record(f);
    timestamp(f, kAfterOverlays);
    end_camera_rendering(f);
}

void FrameRecorder::timestamp(FrameContext& f, std::uint32_t index) {
    vkCmdWriteTimestamp2(f.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, f.slot.timestamps.get(),
                         index);
}

// Frame constants, the slot's descriptor set, and whether the depth prepass runs.
void FrameRecorder::begin_frame(FrameContext& f) {
    FrameSlot& slot = f.slot;
    write_frame_data(f);
    slot.shadows_rendered = f.cascades > 0;
    slot.push_base = GPUPushConstants{};
    if (scene) slot.push_base.instances = scene->instances_address();
    if (slot.posed) { // moving scenes draw the instances of this frame's pose
        slot.push_base.instances = slot.posed_instances;
        slot.push_base.pose = slot.pose_address;
        slot.push_base.highlight_base = slot.highlight_base;
    }
    slots_.bind_frame_set(slot, shadows_.descriptor());
    slot.push_base.cascade = kNoCascade;
    f.prepass =
        !f.settings.floor_only && prepass_enabled(f.settings.depth_prepass, context.info().is_cpu(),
                                                  scene ? scene->triangle_count() : 0,
                                                  std::uint64_t{f.target.width} * f.target.height);
}

// Descriptor sets and index buffer of every draw of the frame.
void FrameRecorder::bind_frame(FrameContext& f) {
    const VkDescriptorSet sets[] = {bindless->set(), f.slot.set};
    vkCmdBindDescriptorSets(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, f.pipelines.layout(), 0, 2,
                            sets, 0, nullptr);
    if (scene && scene->index_buffer() != VK_NULL_HANDLE)
        vkCmdBindIndexBuffer(f.cmd, scene->index_buffer(), 0, VK_INDEX_TYPE_UINT32);
}

// The target and depth in attachment layouts (both cleared: their previous
// contents do not matter; with `background`, the target holds the background already
// and is loaded), dynamic rendering begun, statistics started.
void FrameRecorder::begin_camera_rendering(FrameContext& f, bool background) {
    const gpu::Image& depth_image = targets_.depth(f.target.width, f.target.height);
    if (!background)
        gpu::transition(
            f.cmd,
            {f.target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
             VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, kColorTargetReaders, VK_ACCESS_2_NONE,
             VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT});
    gpu::transition(
        f.cmd,
        {depth_image.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
         VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});

    auto color =
        gpu::vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    color.imageView = f.target.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = background ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    const glm::vec4 cc = f.settings.clear_color;
    color.clearValue.color = {{cc.r, cc.g, cc.b, cc.a}};
    auto depth =
        gpu::vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    depth.imageView = depth_image.view.get();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {0.0f, 0}; // reverse-Z: 0 is infinitely far
    auto ri = gpu::vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    ri.renderArea = {{0, 0}, {f.target.width, f.target.height}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &color;
    ri.pDepthAttachment = &depth;
    vkCmdBeginRendering(f.cmd, &ri);
    set_viewport(f.cmd, f.target.width, f.target.height);
    if (f.slot.statistics) vkCmdBeginQuery(f.cmd, f.slot.statistics.get(), 0, 0);
}

void FrameRecorder::end_camera_rendering(FrameContext& f) {
    if (f.slot.statistics) vkCmdEndQuery(f.cmd, f.slot.statistics.get(), 0);
    vkCmdEndRendering(f.cmd);
    // What reads the target next: a copy (readback, blit), shaders (a comparison
    // side, see renderer_side.cpp) or the presentation engine (no access).
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    if (f.target.final_layout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL) {
        stage = VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT;
        access = VK_ACCESS_2_TRANSFER_READ_BIT;
    } else if (f.target.final_layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) {
        stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    }
    gpu::transition(f.cmd, {f.target.image, VK_IMAGE_ASPECT_COLOR_BIT,
                            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, f.target.final_layout,
                            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, stage, access});
}

} // namespace sherpa::render
