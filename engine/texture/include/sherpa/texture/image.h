#pragma once
// Decoded images: tightly packed RGBA8, and decoding of encoded sources (PNG,
// JPEG, ...) through OpenImageIO. The engine's one image I/O module: the GPU layer,
// the CLI and the tests read and write PNGs through it too.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sherpa::tex {

struct RgbaImage {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> pixels; // width * height * 4 bytes, rows top to bottom

    bool empty() const { return width == 0 || height == 0; }
    // True when some texel's alpha is below 255.
    bool has_alpha() const;
};

// Decodes encoded image bytes (any format OpenImageIO reads; `name_hint` supplies
// the extension that picks the reader, and names the image in errors). Grey images
// are replicated to RGB; missing alpha becomes 255; 16-bit and float sources are
// converted to 8 bits. Returns false with `error` set on failure, without allocating
// the pixels when the header declares more than the texel budget (texel_budget.h).
bool decode_encoded_image(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                          RgbaImage& out, std::string& error);
// Opens the image and reads its header only: true when a decoder accepts it (the
// pixels may still be damaged), else false with the decoder's reason in `error`.
// `width`/`height`, when given, receive the header's size. An image over the texel
// budget (texel_budget.h) is refused here too, so a probe tells what a decode would.
bool probe_encoded_image(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                         std::string& error, std::uint32_t* width = nullptr,
                         std::uint32_t* height = nullptr);
bool read_image_file(const std::filesystem::path& path, RgbaImage& out, std::string& error);

// A high-dynamic-range image: linear float RGB, rows top to bottom.
struct FloatRgbImage {
    std::uint32_t width = 0, height = 0;
    std::vector<float> rgb; // width * height * 3 floats
};

// Reads an HDR/EXR (any format OpenImageIO reads) as float RGB, unassociated (an alpha
// channel does not scale the colour; grey is replicated). Refuses, before allocating,
// an image with no texels or over `max_side` texels a side. The file's values are
// kept as they are (NaN, negative, huge): the caller decides what they mean.
bool read_float_image_file(const std::filesystem::path& path, std::uint32_t max_side,
                           FloatRgbImage& out, std::string& error);

// Writes an RGBA8 image with OpenImageIO (format from the extension).
bool write_image_file(const std::filesystem::path& path, const RgbaImage& image,
                      std::string& error);

// PNG of rendered RGBA8 frames (golden images, sherpa-cli render): the pixels are
// stored as they are (unassociated alpha). The file is encoded in memory and
// replaced atomically, so readers never see a torn file.
bool write_png(const std::string& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgba, std::string& error);
bool read_png_rgba8(const std::string& path, std::uint32_t& width, std::uint32_t& height,
                    std::vector<std::uint8_t>& rgba, std::string& error);

} // namespace sherpa::tex
