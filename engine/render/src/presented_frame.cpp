#include "frame_recorder.h"

#include <algorithm>

#include <sherpa/render/presented_frame.h>

namespace sherpa::render {

namespace {

// The reduced frame (in TRANSFER_SRC layout) stretched over the whole target, which
// is left in its final layout.
void blit_to_target(VkCommandBuffer cmd, VkImage from, VkExtent2D from_size,
                    const gpu::RenderTarget& to) {
    gpu::transition(cmd,
                    {to.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                     VK_ACCESS_2_NONE, // the acquire wait
                     VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {static_cast<std::int32_t>(from_size.width),
                            static_cast<std::int32_t>(from_size.height), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[1] = {static_cast<std::int32_t>(to.width),
                            static_cast<std::int32_t>(to.height), 1};
    vkCmdBlitImage(cmd, from, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, to.blit_filter);
    gpu::transition(cmd,
                    {to.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     to.final_layout, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE});
}

} // namespace

PresentedFrame::PresentedFrame(Renderer& renderer, const FrameRequest& settings,
                               float resolution_scale)
    : renderer_(renderer), settings_(settings), resolution_scale_(resolution_scale) {
    renderer_.frames().rays().check_drawable(settings_);
}

void PresentedFrame::wait_for_slot(std::uint32_t slot) {
    // The slot's previous frame is done: its timestamps and culling counts are final.
    completed_ = renderer_.frames().slot_stats(slot);
    if (settings_.renderer == RendererKind::RayTraced) { // the rays' image into the target
        const double ms = renderer_.frames().comparison().take_stats(slot).composite_ms;
        if (ms > 0.0) {
            completed_.passes.push_back({"composite", ms});
            completed_.gpu_ms += ms;
        }
    }
}

void PresentedFrame::record(VkCommandBuffer cmd, std::uint32_t slot,
                            const gpu::RenderTarget& target) {
    if (settings_.renderer == RendererKind::RayTraced) {
        // The rays' storage image (sRGB-encoded bytes in a UNORM image: no blit converts
        // it right) reaches the target through the comparison pass's composite of side
        // A alone, which also scales a reduced frame up (nearest).
        const float scale =
            resolution_scale_ > 0.0f && resolution_scale_ < 1.0f ? resolution_scale_ : 1.0f;
        settings_.width = std::max(1u, static_cast<std::uint32_t>(float(target.width) * scale));
        settings_.height = std::max(1u, static_cast<std::uint32_t>(float(target.height) * scale));
        FrameRecorder& r = renderer_.frames();
        CompositeInputs in;
        in.width = settings_.width;
        in.height = settings_.height;
        in.a = in.b = record_side(r, cmd, slot, settings_);
        r.comparison().bind(slot, in);
        r.comparison().record_composite(cmd, slot, in, target, CompositeMode::SideA, 0.0f, 1.0f);
        return;
    }
    const bool reduced = target.blit_target && resolution_scale_ > 0.0f && resolution_scale_ < 1.0f;
    if (!reduced) {
        settings_.width = target.width;
        settings_.height = target.height;
        renderer_.frames().record_frame(cmd, slot, target, settings_);
        return;
    }
    const auto scaled = [&](std::uint32_t side) {
        return std::max(1u,
                        static_cast<std::uint32_t>(static_cast<float>(side) * resolution_scale_));
    };
    const VkExtent2D size{scaled(target.width), scaled(target.height)};
    settings_.width = size.width;
    settings_.height = size.height;
    const gpu::Image& image =
        renderer_.frames().targets().scaled(target.format, size.width, size.height);
    gpu::RenderTarget reduced_target{image.image.get(), image.view.get(),
                                     target.format,     size.width,
                                     size.height,       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    renderer_.frames().record_frame(cmd, slot, reduced_target, settings_);
    blit_to_target(cmd, image.image.get(), size, target);
}

void PresentedFrame::submitted(std::uint32_t slot, std::uint64_t submission) {
    renderer_.frames().slots().finish(slot, submission);
}

} // namespace sherpa::render
