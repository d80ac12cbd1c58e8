// The recorder's images: depth, the offscreen colour target and scaled targets, the
// comparison side, their bytes, and the readback of a finished offscreen frame.
#include "render_targets.h"

#include "pipelines.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/vk_helpers.h>

#include <cstring>

namespace sherpa::render {

RenderTargets::~RenderTargets() {
    for (gpu::ImageHandle* h : {&color_, &depth_, &scaled_, &side_})
        resources_.images().destroy(*h);
    resources_.destroy(readback_);
}

const gpu::Image& RenderTargets::depth(std::uint32_t width, std::uint32_t height) {
    if (depth_.valid()) {
        const gpu::ImageDesc& d = resources_.images().get(depth_).desc;
        if (d.width == width && d.height == height) return resources_.images().get(depth_);
        resources_.images().destroy(depth_);
    }
    depth_ = resources_.images().create(depth_attachment_desc(width, height, "depth"));
    return resources_.images().get(depth_);
}

bool RenderTargets::ensure_color(gpu::ImageHandle& image, VkFormat format, std::uint32_t width,
                                 std::uint32_t height, const char* name) {
    if (image.valid()) {
        const gpu::ImageDesc& d = resources_.images().get(image).desc;
        if (d.format == format && d.width == width && d.height == height) return false;
        resources_.images().destroy(image); // freed once the frames drawing into it are done
    }
    gpu::ImageDesc d;
    d.format = format;
    d.width = width;
    d.height = height;
    // Transfer writes: a kept background is copied in (BackgroundPass).
    d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
              VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.name = name;
    image = resources_.images().create(d);
    return true;
}

gpu::RenderTarget RenderTargets::offscreen(std::uint32_t width, std::uint32_t height) {
    if (ensure_color(color_, kOffscreenFormat, width, height, "offscreen colour")) {
        resources_.destroy(readback_); // sized by the colour target
        readback_ = resources_.create_buffer({VkDeviceSize(width) * height * 4,
                                              VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                              gpu::MemoryUsage::Readback, "readback"});
    }
    const gpu::Image& color = resources_.images().get(color_);
    return {color.image.get(),
            color.view.get(),
            kOffscreenFormat,
            width,
            height,
            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            true};
}

const gpu::Image& RenderTargets::scaled(VkFormat format, std::uint32_t width,
                                        std::uint32_t height) {
    ensure_color(scaled_, format, width, height, "reduced-resolution colour");
    return resources_.images().get(scaled_);
}

const gpu::Image& RenderTargets::side(std::uint32_t width, std::uint32_t height) {
    gpu::ImageDesc d;
    d.format = kOffscreenFormat;
    d.width = width;
    d.height = height;
    d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
              VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    // The comparison reads the stored sRGB bytes as they are, through an UNORM view.
    d.alias_format = VK_FORMAT_R8G8B8A8_UNORM;
    d.name = "comparison side";
    if (!side_.valid() || resources_.images().get(side_).desc.width != d.width ||
        resources_.images().get(side_).desc.height != d.height) {
        resources_.images().destroy(side_); // freed once the frames reading it are done
        side_ = resources_.images().create(d);
    }
    return resources_.images().get(side_);
}

std::uint64_t RenderTargets::bytes() const {
    std::uint64_t bytes = 0;
    for (gpu::ImageHandle h : {color_, depth_, scaled_, side_})
        if (h.valid()) bytes += resources_.images().get(h).allocation_size;
    return bytes;
}

void RenderTargets::record_readback(VkCommandBuffer cmd, std::uint32_t width,
                                    std::uint32_t height) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, resources_.images().get(color_).image.get(),
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           resources_.get(readback_).buffer.get(), 1, &region);
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void RenderTargets::read_offscreen(std::vector<std::uint8_t>& rgba, std::uint32_t width,
                                   std::uint32_t height) const {
    rgba.resize(std::size_t(width) * height * 4);
    std::memcpy(rgba.data(), resources_.get(readback_).mapped, rgba.size());
}

} // namespace sherpa::render
