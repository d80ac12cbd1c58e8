#pragma once
// Independent image decoders for tests: libpng and libjpeg called directly, never
// through OpenImageIO (which Sherpa itself decodes with), so a test compares
// Sherpa's texels with what the file stores rather than with Sherpa's own reading.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sherpa::test {

// Tightly packed RGBA8, rows top to bottom; colour exactly as stored in the file
// (PNG: unassociated, no gamma conversion), alpha 255 where the file has none.
struct ReferenceImage {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
    const std::uint8_t* texel(std::uint32_t x, std::uint32_t y) const {
        return rgba.data() + (std::size_t(y) * width + x) * 4;
    }
};

// libpng: palette, grey and tRNS expanded, 16-bit reduced to 8 bits.
bool read_png_reference(const std::filesystem::path& path, ReferenceImage& out, std::string& error);
// libjpeg(-turbo): decoded to RGB.
bool read_jpeg_reference(const std::filesystem::path& path, ReferenceImage& out,
                         std::string& error);
// By extension (.png, .jpg/.jpeg); false for other formats.
bool read_reference_image(const std::filesystem::path& path, ReferenceImage& out,
                          std::string& error);

} // namespace sherpa::test
