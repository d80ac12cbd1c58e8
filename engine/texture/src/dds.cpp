// DDS layout from Microsoft's DDS_HEADER / DDS_HEADER_DXT10 documentation.
#include <sherpa/texture/dds.h>

#include <stdexcept>

namespace sherpa::tex {

namespace {
void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
constexpr std::uint32_t fourcc(char a, char b, char c, char d) {
    return std::uint32_t(std::uint8_t(a)) | std::uint32_t(std::uint8_t(b)) << 8 |
           std::uint32_t(std::uint8_t(c)) << 16 | std::uint32_t(std::uint8_t(d)) << 24;
}
} // namespace

std::vector<std::uint8_t> wrap_in_dds(BlockFormat format, std::uint32_t width, std::uint32_t height,
                                      std::span<const std::uint8_t> blocks) {
    if (width == 0 || height == 0 || blocks.size() != compressed_size(width, height))
        throw std::invalid_argument("wrap_in_dds: block data does not match the image size");
    constexpr std::uint32_t kCaps = 0x1, kHeight = 0x2, kWidth = 0x4, kPixelFormat = 0x1000,
                            kLinearSize = 0x80000, kFourCcFlag = 0x4, kCapsTexture = 0x1000;
    constexpr std::uint32_t kDxgiBc5Unorm = 83, kDxgiBc7Unorm = 98, kDimensionTexture2d = 3;
    std::vector<std::uint8_t> out;
    out.reserve(148 + blocks.size());
    put32(out, fourcc('D', 'D', 'S', ' '));
    put32(out, 124); // header size
    put32(out, kCaps | kHeight | kWidth | kPixelFormat | kLinearSize);
    put32(out, height);
    put32(out, width);
    put32(out, static_cast<std::uint32_t>(blocks.size())); // linear size of the top level
    put32(out, 0);                                         // depth
    put32(out, 1);                                         // mip count
    for (int i = 0; i < 11; ++i) put32(out, 0);            // reserved
    put32(out, 32);                                        // pixel format size
    put32(out, kFourCcFlag);
    put32(out, fourcc('D', 'X', '1', '0'));
    for (int i = 0; i < 5; ++i) put32(out, 0); // bit count and masks
    put32(out, kCapsTexture);
    for (int i = 0; i < 4; ++i) put32(out, 0); // caps2..4, reserved
    put32(out, format == BlockFormat::Bc7 ? kDxgiBc7Unorm : kDxgiBc5Unorm);
    put32(out, kDimensionTexture2d);
    put32(out, 0); // misc flags
    put32(out, 1); // array size
    put32(out, 0); // misc flags 2
    out.insert(out.end(), blocks.begin(), blocks.end());
    return out;
}

} // namespace sherpa::tex
