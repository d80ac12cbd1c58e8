#pragma once
// The in-process decoders behind image_io.cpp: PNG through libpng and JPEG through
// libjpeg-turbo (Debian's, the libraries OpenImageIO itself reads them with), so a
// process that only reads glTF's two core image formats never loads OpenImageIO.
// Their pixels equal OpenImageIO's with unassociated alpha
// (tests/texture/image_codecs_test.cpp compares every PNG and JPEG of the assets).
#include <sherpa/texture/image.h>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sherpa::tex {

enum class CodecResult {
    Ok,
    Failed,      // `error` says why (the file is damaged or refused)
    Unsupported, // a variant this decoder leaves to OpenImageIO (CMYK JPEG)
};

// Called with the header's size before any pixel is allocated (image_io.cpp).
bool decoded_size_ok(std::uint32_t width, std::uint32_t height, std::string_view name,
                     std::string& error);

bool is_png(std::span<const std::uint8_t> bytes);
bool is_jpeg(std::span<const std::uint8_t> bytes);

// RGBA8, unassociated: palette, grey and tRNS expanded, 16 bits scaled to 8 with
// rounding, no gamma or colour-space conversion.
CodecResult decode_png(std::span<const std::uint8_t> bytes, std::string_view name, RgbaImage& out,
                       std::string& error);
// Reads the chunks up to the pixel data (CRCs checked).
CodecResult probe_png(std::span<const std::uint8_t> bytes, std::string_view name,
                      std::uint32_t& width, std::uint32_t& height, std::string& error);
// 8-bit RGBA rows, stored as they are.
bool encode_png(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba,
                std::vector<std::uint8_t>& encoded, std::string& error);

// YCbCr and grey JPEG to RGBA8 (alpha 255); CMYK/YCCK are Unsupported.
CodecResult decode_jpeg(std::span<const std::uint8_t> bytes, std::string_view name, RgbaImage& out,
                        std::string& error);
CodecResult probe_jpeg(std::span<const std::uint8_t> bytes, std::string_view name,
                       std::uint32_t& width, std::uint32_t& height, std::string& error);

} // namespace sherpa::tex
