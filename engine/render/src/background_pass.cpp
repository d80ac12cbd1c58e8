// The environment behind the scene (FrameRequest::background environment or
// blurred): one full-screen triangle over every pixel, in its own rendering before
// the camera's, which then loads the target instead of clearing it and draws the
// surfaces over it (blended ones blend over it). Nothing is drawn (and nothing built)
// for a solid-colour background or without an environment.
//
// Drawn first, with no depth attachment, every pixel is shaded (the surfaces' too),
// and still it costs less on lavapipe than the same triangle drawn after the opaque
// surfaces, depth-tested EQUAL against the far plane so as to shade only the pixels
// no surface covers (docs/environment.md, "Speed").
//
// A full-screen pass has a cost per pixel whatever it draws (on lavapipe at 1280x720
// the background is most of what an environment adds to a frame), and the background
// depends on the view, the environment and the display settings alone. So while they
// hold still (the same Key two frames in a row: an animation played, a selection, a
// material edited) it is drawn once into an image of the target's size and copied into
// the target: the same bytes, for the cost of a copy. A moving view draws it into the
// target, and never pays for the image.
#include "draw.h"
#include "passes.h"

#include <sherpa/gpu/vk_helpers.h>

#include "background_frag.h"
#include "background_vert.h"

namespace sherpa::render {

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

VkPipeline BackgroundPass::pipeline(FrameContext& f) {
    VkDevice device = f.context.device();
    if (!vert_) {
        vert_ = gpu::create_shader_module(device, spirv_background_vert, "background.vert");
        frag_ = gpu::create_shader_module(device, spirv_background_frag, "background.frag");
    }
    const VkFormat format = f.pipelines.color_format();
    gpu::UniquePipeline& p = pipelines_[format];
    if (!p) {
        PipelineDesc d{vert_.get(), frag_.get()};
        d.depth = false; // its own rendering, no depth: every pixel is drawn
        p = make_graphics_pipeline(device, f.pipelines.layout(), format, d,
                                   "vkCreateGraphicsPipelines(background)");
    }
    return p.get();
}

bool BackgroundPass::prepare(FrameContext& f) {
    if (!active(f)) return false;
    resources_ = &f.resources;
    if (f.target.blit_target) { // the target takes copies: the background may be kept
        // What the shaders read this frame (written by write_frame_data before the passes).
        const auto& data =
            *static_cast<const GPUFrameData*>(f.resources.get(f.slot.frame_data).mapped);
        const Key key{data.view_proj, data.camera_position,   data.environment,
                      data.display,   f.slot.set_environment, f.target.format,
                      f.target.width, f.target.height};
        const bool still = last_key_ == key;
        last_key_ = key;
        if (kept_key_ == key || still) {
            if (kept_key_ != key) build_kept(f);
            kept_key_ = key;
            copy_kept(f);
            return true;
        }
    }
    // A moving view (or a target that takes no copies): drawn into the target.
    gpu::transition(f.cmd, {f.target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, kColorTargetReaders,
                            VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
    draw_whole(f, f.target.view);
    gpu::transition(
        f.cmd,
        {f.target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
         VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
    return true;
}

// The background over every pixel of `view` (the target's size), in its own rendering.
void BackgroundPass::draw_whole(FrameContext& f, VkImageView view) {
    auto color =
        gpu::vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    color.imageView = view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE; // every pixel is drawn
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    auto ri = gpu::vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    ri.renderArea = {{0, 0}, {f.target.width, f.target.height}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &color;
    vkCmdBeginRendering(f.cmd, &ri);
    set_viewport(f.cmd, f.target.width, f.target.height);
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline(f));
    vkCmdDraw(f.cmd, 3, 1, 0, 0);
    vkCmdEndRendering(f.cmd);
}

// The background over the whole kept image (no depth: every pixel), left a copy source.
void BackgroundPass::build_kept(FrameContext& f) {
    gpu::ImagePool& images = f.resources.images();
    const bool fits = kept_.valid() && images.get(kept_).desc.format == f.target.format &&
                      images.get(kept_).desc.width == f.target.width &&
                      images.get(kept_).desc.height == f.target.height;
    VkImageLayout from = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    if (!fits) {
        release();
        gpu::ImageDesc d;
        d.format = f.target.format;
        d.width = f.target.width;
        d.height = f.target.height;
        d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        d.name = "background";
        kept_ = images.create(d);
        from = VK_IMAGE_LAYOUT_UNDEFINED;
    }
    const gpu::Image& kept = images.get(kept_);
    // Earlier frames may still copy from it: their copies before this frame's drawing.
    gpu::transition(f.cmd, {kept.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, from,
                            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
    draw_whole(f, kept.view.get());
    // Copies of this and later frames read it (a barrier orders later submissions too).
    gpu::transition(f.cmd,
                    {kept.image.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT});
}

// The kept background into the target, then the target a colour attachment again.
void BackgroundPass::copy_kept(FrameContext& f) {
    const gpu::Image& kept = f.resources.images().get(kept_);
    // The target's previous contents do not matter; earlier frames may still read it
    // (a readback copy, a comparison's shaders: the stages begin_camera_rendering waits on).
    gpu::transition(f.cmd,
                    {f.target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kColorTargetReaders, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = region.srcSubresource;
    region.extent = {f.target.width, f.target.height, 1};
    vkCmdCopyImage(f.cmd, kept.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, f.target.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    gpu::transition(
        f.cmd, {f.target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
}

} // namespace sherpa::render
