#pragma once
// A FrameRecorder's own images (private to the render layer): the offscreen colour
// target and its readback, the depth attachment, the presenter's reduced-resolution
// image, and the image a comparison side is drawn into. Each is made on first use and
// remade when its size or format changes (the old one freed once the frames using it
// are done).
#include <sherpa/gpu/frame_source.h>
#include <sherpa/gpu/resources.h>

#include <cstdint>
#include <vector>

namespace sherpa::render {

class RenderTargets {
public:
    static constexpr VkFormat kOffscreenFormat = VK_FORMAT_R8G8B8A8_SRGB;
    explicit RenderTargets(gpu::ResourceManager& resources) : resources_(resources) {}
    ~RenderTargets();
    RenderTargets(const RenderTargets&) = delete;
    RenderTargets& operator=(const RenderTargets&) = delete;

    // The depth attachment of this size.
    const gpu::Image& depth(std::uint32_t width, std::uint32_t height);
    // The offscreen colour target (render(), render_comparison()), left by a frame in
    // TRANSFER_SRC layout, with its readback buffer.
    gpu::RenderTarget offscreen(std::uint32_t width, std::uint32_t height);
    // Its copy into the readback buffer, and the rows read back once complete.
    void record_readback(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height);
    void read_offscreen(std::vector<std::uint8_t>& rgba, std::uint32_t width,
                        std::uint32_t height) const;
    // The presenter's reduced-resolution image (`format`, colour attachment and blit source).
    const gpu::Image& scaled(VkFormat format, std::uint32_t width, std::uint32_t height);
    // A comparison side's raster image (kOffscreenFormat, sampled through an UNORM alias).
    const gpu::Image& side(std::uint32_t width, std::uint32_t height);
    // Bytes of these images.
    std::uint64_t bytes() const;

private:
    // Keeps `image` a colour attachment and transfer source of this format and size;
    // true when it was (re)made.
    bool ensure_color(gpu::ImageHandle& image, VkFormat format, std::uint32_t width,
                      std::uint32_t height, const char* name);
    gpu::ResourceManager& resources_;
    gpu::ImageHandle color_, depth_, scaled_, side_;
    gpu::BufferHandle readback_;
};

} // namespace sherpa::render
