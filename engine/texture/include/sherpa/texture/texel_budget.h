#pragma once
// The decoded-size limit of one image. A PNG, JPEG or WebP header of a few bytes can
// declare 30000x30000 texels, and a Zstandard-supercompressed KTX2 level of a few KB
// can inflate to hundreds of MB: every decoder asks check_texel_budget() with the
// size the header declares before it allocates anything sized by it, and an image
// over the limit is undecodable (a named error for that image; the scene still loads).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace sherpa::tex {

// Texels one image may declare: 8192x8192 (67,108,864 texels, 256 MiB as RGBA8; the
// texture pipeline's float mip chain of such an image takes about 1.3 GiB more).
inline constexpr std::uint64_t kMaxImageTexels = std::uint64_t{8192} * 8192;
// The longest side accepted (Vulkan's common maxImageDimension2D).
inline constexpr std::uint64_t kMaxImageSide = 16384;

// True when a `width` x `height` image may be decoded. Otherwise false, with `error`
// naming the image (`name`, when not empty, then ": "), its declared size and the limit.
bool check_texel_budget(std::uint64_t width, std::uint64_t height, std::string_view name,
                        std::string& error);

struct DeclaredSize {
    std::uint32_t width = 0, height = 0;
};

// The size a PNG (IHDR), JPEG (first SOFn marker) or WebP (VP8, VP8L or VP8X) header
// declares, read from the bytes without a decoder; nullopt for other formats and for
// headers cut short.
std::optional<DeclaredSize> declared_image_size(std::span<const std::uint8_t> bytes);

} // namespace sherpa::tex
