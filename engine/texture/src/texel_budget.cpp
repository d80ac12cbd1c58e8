// Header-only size checks that run before any decoder allocates (see texel_budget.h).
#include <sherpa/texture/texel_budget.h>

#include <cstring>

namespace sherpa::tex {

namespace {
using Bytes = std::span<const std::uint8_t>;

bool starts_with(Bytes b, const char* magic, std::size_t at = 0) {
    const std::size_t n = std::strlen(magic);
    return b.size() >= at + n && std::memcmp(b.data() + at, magic, n) == 0;
}
std::uint32_t be(Bytes b, std::size_t at, int n) {
    std::uint32_t v = 0;
    for (int i = 0; i < n; ++i) v = v << 8 | b[at + std::size_t(i)];
    return v;
}
std::uint32_t le(Bytes b, std::size_t at, int n) {
    std::uint32_t v = 0;
    for (int i = n; i-- > 0;) v = v << 8 | b[at + std::size_t(i)];
    return v;
}

std::optional<DeclaredSize> png_size(Bytes b) {
    // Signature (8), IHDR length (4), "IHDR", width and height big-endian.
    if (b.size() < 24 || !starts_with(b, "IHDR", 12)) return std::nullopt;
    return DeclaredSize{be(b, 16, 4), be(b, 20, 4)};
}

std::optional<DeclaredSize> jpeg_size(Bytes b) {
    std::size_t at = 2; // after SOI
    while (at + 4 <= b.size()) {
        if (b[at] != 0xFF) return std::nullopt; // not at a marker: damaged
        const std::uint8_t marker = b[at + 1];
        if (marker == 0xFF) { // fill byte
            ++at;
            continue;
        }
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) { // no length
            at += 2;
            continue;
        }
        if (marker == 0xDA || marker == 0xD9) return std::nullopt; // scan before any frame
        const std::size_t length = be(b, at + 2, 2);
        // SOF0..SOF15 except DHT (C4), JPG (C8) and DAC (CC): precision, height, width.
        if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 &&
            marker != 0xCC) {
            if (at + 9 > b.size()) return std::nullopt;
            return DeclaredSize{be(b, at + 7, 2), be(b, at + 5, 2)};
        }
        if (length < 2) return std::nullopt;
        at += 2 + length;
    }
    return std::nullopt;
}

std::optional<DeclaredSize> webp_size(Bytes b) {
    if (b.size() < 30) return std::nullopt;
    if (starts_with(b, "VP8X", 12)) // canvas width-1 and height-1, 24 bits each
        return DeclaredSize{le(b, 24, 3) + 1, le(b, 27, 3) + 1};
    if (starts_with(b, "VP8L", 12) && b[20] == 0x2F) { // 14 bits each, minus one
        const std::uint32_t bits = le(b, 21, 4);
        return DeclaredSize{(bits & 0x3FFF) + 1, ((bits >> 14) & 0x3FFF) + 1};
    }
    if (starts_with(b, "VP8 ", 12) && b[23] == 0x9D && b[24] == 0x01 && b[25] == 0x2A)
        return DeclaredSize{le(b, 26, 2) & 0x3FFF, le(b, 28, 2) & 0x3FFF};
    return std::nullopt;
}
} // namespace

bool check_texel_budget(std::uint64_t width, std::uint64_t height, std::string_view name,
                        std::string& error) {
    const bool too_wide = width > kMaxImageSide || height > kMaxImageSide;
    // Both sides are at most 16384 here, so the product cannot wrap.
    if (!too_wide && width * height <= kMaxImageTexels) return true;
    error = std::string(name) + (name.empty() ? "" : ": ") + "declares " + std::to_string(width) +
            "x" + std::to_string(height) + " texels; Sherpa decodes at most " +
            std::to_string(kMaxImageTexels) + " texels (8192x8192) and " +
            std::to_string(kMaxImageSide) + " per side per image: not decoded";
    return false;
}

std::optional<DeclaredSize> declared_image_size(std::span<const std::uint8_t> bytes) {
    if (starts_with(bytes, "\x89PNG\r\n\x1A\n")) return png_size(bytes);
    if (starts_with(bytes, "\xFF\xD8\xFF")) return jpeg_size(bytes);
    if (starts_with(bytes, "RIFF") && starts_with(bytes, "WEBP", 8)) return webp_size(bytes);
    return std::nullopt;
}

} // namespace sherpa::tex
