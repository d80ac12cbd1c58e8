// The renderer's images: depth, the offscreen colour target and scaled targets, their
// bytes, and the readback of a finished offscreen frame.
#include "renderer_impl.h"

#include <sherpa/gpu/vk_helpers.h>

#include <cstring>

namespace sherpa::gpu {

void Renderer::Impl::ensure_depth(std::uint32_t width, std::uint32_t height) {
    if (depth_.valid()) {
        const ImageDesc& d = resources->images().get(depth_).desc;
        if (d.width == width && d.height == height) return;
        resources->images().destroy(depth_);
    }
    ImageDesc d;
    d.format = kDepthFormat;
    d.width = width;
    d.height = height;
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    d.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    d.name = "depth";
    depth_ = resources->images().create(d);
}

bool Renderer::Impl::ensure_color_target(ImageHandle& image, VkFormat format, std::uint32_t width,
                                         std::uint32_t height, const char* name) {
    if (image.valid()) {
        const ImageDesc& d = resources->images().get(image).desc;
        if (d.format == format && d.width == width && d.height == height) return false;
        resources->images().destroy(image); // freed once the frames drawing into it are done
    }
    ImageDesc d;
    d.format = format;
    d.width = width;
    d.height = height;
    d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.name = name;
    image = resources->images().create(d);
    return true;
}

void Renderer::Impl::ensure_offscreen(std::uint32_t width, std::uint32_t height) {
    if (!ensure_color_target(color_, kOffscreenFormat, width, height, "offscreen colour")) return;
    resources->destroy(readback_); // sized by the colour target
    readback_ = resources->create_buffer({VkDeviceSize(width) * height * 4,
                                          VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback,
                                          "readback"});
}

const Image& Renderer::Impl::scaled_target(VkFormat format, std::uint32_t width,
                                           std::uint32_t height) {
    ensure_color_target(scaled_, format, width, height, "reduced-resolution colour");
    return resources->images().get(scaled_);
}

std::uint64_t Renderer::Impl::render_target_bytes() const {
    std::uint64_t bytes = shadows_.bytes() + transmission_->bytes();
    for (ImageHandle h : {color_, depth_, scaled_, side_})
        if (h.valid()) bytes += resources->images().get(h).allocation_size;
    return bytes;
}

RenderTarget Renderer::Impl::offscreen_target(std::uint32_t width, std::uint32_t height) {
    ensure_offscreen(width, height);
    const Image& color = resources->images().get(color_);
    return {color.image.get(),
            color.view.get(),
            kOffscreenFormat,
            width,
            height,
            VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
}

void Renderer::Impl::record_readback(VkCommandBuffer cmd, std::uint32_t width,
                                     std::uint32_t height) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, resources->images().get(color_).image.get(),
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           resources->get(readback_).buffer.get(), 1, &region);
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void Renderer::Impl::read_offscreen(std::vector<std::uint8_t>& rgba, std::uint32_t width,
                                    std::uint32_t height) const {
    rgba.resize(std::size_t(width) * height * 4);
    std::memcpy(rgba.data(), resources->get(readback_).mapped, rgba.size());
}

} // namespace sherpa::gpu
