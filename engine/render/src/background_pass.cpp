// The environment behind the scene (FrameRequest::background environment or
// blurred): one full-screen triangle at the far plane, depth-tested EQUAL against the
// cleared far depth, so only pixels no surface covers are shaded. Nothing is drawn
// (and nothing built) for a solid-colour background or without an environment.
//
// A full-screen pass has a cost per pixel whatever it draws (on lavapipe at 1280x720
// the background pass is most of what an environment adds to a frame), and the
// background depends on the view, the environment and the display settings alone.
// So while they hold still (the same key two frames in a row: an animation played,
// a selection, a material edited) the background is drawn once into an image of the
// target's size and copied into the target before the surfaces are drawn over it:
// the same bytes the pass would write, for the cost of a copy. A moving view draws
// it as above, and never pays for the image.
#include "draw.h"
#include "passes.h"

#include <sherpa/gpu/vk_helpers.h>

#include "background_frag.h"
#include "background_vert.h"

namespace sherpa::gpu {

BackgroundPass::BackgroundPass() = default;
BackgroundPass::~BackgroundPass() {
    release();
}

bool BackgroundPass::active(const FrameContext& f) {
    return f.environment && !f.settings.floor_only && f.settings.view == DebugView::Lit &&
           f.settings.background != Background::Color;
}

std::uint64_t BackgroundPass::bytes() const {
    return resources_ && kept_.valid() ? resources_->images().get(kept_).allocation_size : 0;
}

void BackgroundPass::release() {
    if (resources_ && kept_.valid()) resources_->images().destroy(kept_); // after its frames
    kept_ = {};
    kept_key_.reset();
}

VkPipeline BackgroundPass::pipeline(FrameContext& f, bool depth) {
    VkDevice device = f.context.device();
    if (!vert_) {
        vert_ = create_shader_module(device, spirv_background_vert, "background.vert");
        frag_ = create_shader_module(device, spirv_background_frag, "background.frag");
    }
    const VkFormat format = f.pipelines.color_format();
    UniquePipeline& p = (depth ? pipelines_ : kept_pipelines_)[format];
    if (!p) {
        PipelineDesc d{vert_.get(), frag_.get()};
        d.depth = depth; // the kept image has no depth attachment: every pixel is drawn
        p = make_graphics_pipeline(device, f.pipelines.layout(), format, d,
                                   "vkCreateGraphicsPipelines(background)");
    }
    return p.get();
}

bool BackgroundPass::prepare(FrameContext& f) {
    copied_ = false;
    if (!active(f) || !f.target.blit_target) return false;
    resources_ = &f.resources;
    // What the shaders read this frame (written by write_frame_data before the passes).
    const auto& data = *static_cast<const GPUFrameData*>(f.resources.get(f.slot.frame_data).mapped);
    const Key key{data.view_proj,         data.camera_position, data.environment, data.display,
                  f.slot.set_environment, f.target.format,      f.target.width,   f.target.height};
    const bool still = last_key_ == key;
    last_key_ = key;
    if (kept_key_ != key) {
        if (!still) return false; // a moving view: drawn where no surface is (record())
        build_kept(f);
        kept_key_ = key;
    }
    copy_kept(f);
    copied_ = true;
    return true;
}

// The background over the whole kept image (no depth: every pixel), left a copy source.
void BackgroundPass::build_kept(FrameContext& f) {
    ImagePool& images = f.resources.images();
    const bool fits = kept_.valid() && images.get(kept_).desc.format == f.target.format &&
                      images.get(kept_).desc.width == f.target.width &&
                      images.get(kept_).desc.height == f.target.height;
    VkImageLayout from = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    if (!fits) {
        release();
        ImageDesc d;
        d.format = f.target.format;
        d.width = f.target.width;
        d.height = f.target.height;
        d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        d.name = "background";
        kept_ = images.create(d);
        from = VK_IMAGE_LAYOUT_UNDEFINED;
    }
    const Image& kept = images.get(kept_);
    // Earlier frames may still copy from it: their copies before this frame's drawing.
    transition(f.cmd, {kept.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, from,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
    auto color = vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    color.imageView = kept.view.get();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE; // every pixel is drawn
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    auto ri = vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    ri.renderArea = {{0, 0}, {f.target.width, f.target.height}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &color;
    vkCmdBeginRendering(f.cmd, &ri);
    set_viewport(f.cmd, f.target.width, f.target.height);
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline(f, false));
    vkCmdDraw(f.cmd, 3, 1, 0, 0);
    vkCmdEndRendering(f.cmd);
    // Copies of this and later frames read it (a barrier orders later submissions too).
    transition(f.cmd,
               {kept.image.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                VK_ACCESS_2_TRANSFER_READ_BIT});
}

// The kept background into the target, then the target a colour attachment again.
void BackgroundPass::copy_kept(FrameContext& f) {
    const Image& kept = f.resources.images().get(kept_);
    // The target's previous contents do not matter; earlier frames may still read it
    // (a readback copy, a comparison's shaders: the stages begin_camera_rendering waits on).
    transition(f.cmd,
               {f.target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                    VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = region.srcSubresource;
    region.extent = {f.target.width, f.target.height, 1};
    vkCmdCopyImage(f.cmd, kept.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, f.target.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transition(f.cmd,
               {f.target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
}

void BackgroundPass::record(FrameContext& f) {
    if (!active(f) || copied_) return;
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline(f, true));
    vkCmdSetCullMode(f.cmd, VK_CULL_MODE_NONE);
    vkCmdSetFrontFace(f.cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
    set_depth(f.cmd, VK_COMPARE_OP_EQUAL, false); // reverse-Z: 0 is the cleared far plane
    vkCmdDraw(f.cmd, 3, 1, 0, 0);
}

} // namespace sherpa::gpu
