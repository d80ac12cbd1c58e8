// Image data as the Khronos glTF-Validator reads it: the format from the first bytes
// against the declared media type, and the PNG/JPEG headers (dimensions, streams cut
// short, colour-space or pixel-shape chunks the core spec does not support). No pixel
// is decoded: only the headers and the PNG chunk list are walked.
#include "validate_internal.h"

#include "checked_math.h"

#include <cstring>

namespace sherpa::scene::detail {
namespace {

using Bytes = std::span<const std::uint8_t>;

bool starts(Bytes b, const char* magic, std::size_t n, std::size_t at = 0) {
    return b.size() >= at + n && std::memcmp(b.data() + at, magic, n) == 0;
}

std::uint32_t be32(Bytes b, std::size_t at) {
    return std::uint32_t(b[at]) << 24 | std::uint32_t(b[at + 1]) << 16 |
           std::uint32_t(b[at + 2]) << 8 | std::uint32_t(b[at + 3]);
}

// The media type the bytes are, or "" when none Khronos recognises.
std::string_view sniff(Bytes b) {
    if (starts(b, "\x89PNG\r\n\x1a\n", 8)) return "image/png";
    if (starts(b, "\xFF\xD8", 2)) return "image/jpeg";
    if (starts(b, "RIFF", 4) && starts(b, "WEBP", 4, 8)) return "image/webp";
    return {};
}

struct Header {
    bool truncated = false;
    bool unsupported = false; // colour-space information, non-square pixels, animation
    std::uint32_t width = 0, height = 0;
};

// PNG: IHDR's size, then every chunk to IEND (a length past the end is a cut stream).
Header png(Bytes b) {
    Header h;
    std::size_t at = 8;
    bool first = true;
    while (true) {
        if (at + 8 > b.size()) return h.truncated = true, h;
        const std::uint32_t length = be32(b, at);
        const Bytes type = b.subspan(at + 4, 4);
        if (!range_fits(at + 8, std::size_t{length} + 4, b.size())) return h.truncated = true, h;
        const Bytes data = b.subspan(at + 8, length);
        if (first && starts(type, "IHDR", 4) && length >= 8) {
            h.width = be32(data, 0);
            h.height = be32(data, 4);
        }
        first = false;
        // A colour profile (the Khronos validator leaves gAMA and cHRM alone) or an
        // animation: unsupported.
        if (starts(type, "iCCP", 4) || starts(type, "acTL", 4)) h.unsupported = true;
        if (starts(type, "pHYs", 4) && length >= 8 && be32(data, 0) != be32(data, 4))
            h.unsupported = true;
        if (starts(type, "IEND", 4)) return h;
        at += 12 + std::size_t{length};
    }
}

// JPEG: markers up to the first start of frame, whose dimensions it holds.
Header jpeg(Bytes b) {
    Header h;
    std::size_t at = 2;
    while (true) {
        while (at < b.size() && b[at] == 0xFF && at + 1 < b.size() && b[at + 1] == 0xFF) ++at;
        if (at + 4 > b.size()) return h.truncated = true, h;
        const std::uint8_t marker = b[at + 1];
        const std::size_t length = std::size_t{b[at + 2]} << 8 | b[at + 3];
        const bool sof =
            marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (sof) {
            if (at + 9 > b.size()) return h.truncated = true, h;
            h.height = std::uint32_t{b[at + 5]} << 8 | b[at + 6];
            h.width = std::uint32_t{b[at + 7]} << 8 | b[at + 8];
            return h;
        }
        if (length < 2) return h.truncated = true, h;
        at += 2 + length;
    }
}

bool power_of_two(std::uint32_t x) {
    return x && !(x & (x - 1));
}

// The declared media type: mimeType, else a data URI's own.
std::string declared_type(const Json& image) {
    const Json& mime = Validation::member(image, "mimeType");
    if (mime.is_string()) return mime.get<std::string>();
    const Json& uri = Validation::member(image, "uri");
    if (!uri.is_string()) return {};
    const std::string& u = uri.get_ref<const std::string&>();
    if (!u.starts_with("data:")) return {};
    const std::size_t end = u.find_first_of(";,");
    return end == std::string::npos ? std::string() : u.substr(5, end - 5);
}

} // namespace

void validate_images(Validation& v, std::span<const Bytes> buffers, std::span<const Bytes> images) {
    const Json& list = v.array("images");
    const Json& views = v.array("bufferViews");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Json& image = Validation::member(list, i);
        Bytes bytes = i < images.size() ? images[i] : Bytes{};
        if (const std::int64_t vi = ref(v, image, "bufferView", "bufferViews"); vi >= 0) {
            const Json& view = views[static_cast<std::size_t>(vi)];
            const std::int64_t b = ref(v, view, "buffer", "buffers");
            const std::int64_t offset = int_or(view, "byteOffset", 0);
            const std::int64_t length = int_or(view, "byteLength", -1);
            bytes = {};
            if (b >= 0 && static_cast<std::size_t>(b) < buffers.size() && offset >= 0 &&
                length > 0 &&
                range_fits(static_cast<std::size_t>(offset), static_cast<std::size_t>(length),
                           buffers[static_cast<std::size_t>(b)].size()))
                bytes = buffers[static_cast<std::size_t>(b)].subspan(
                    static_cast<std::size_t>(offset), static_cast<std::size_t>(length));
        }
        if (bytes.empty()) continue; // not loaded: the URI's own message says why
        const std::string where = ptr("/images", i);
        const std::string_view format = sniff(bytes);
        if (format.empty()) {
            v.add("IMAGE_UNRECOGNIZED_FORMAT", Severity::Warning, where,
                  "Image format not recognized.");
            continue;
        }
        if (const std::string declared = declared_type(image);
            !declared.empty() && declared != format)
            v.add("IMAGE_MIME_TYPE_INVALID", Severity::Error,
                  ptr(where, image.contains("bufferView") ? "bufferView" : "uri"),
                  "Recognized image format '" + std::string(format) +
                      "' does not match declared image format '" + declared + "'.");
        if (format == "image/webp") continue; // only its container is checked
        const Header h = format == "image/png" ? png(bytes) : jpeg(bytes);
        if (h.truncated) {
            v.add("IMAGE_UNEXPECTED_EOS", Severity::Error, where,
                  "Unexpected end of image stream.");
            continue;
        }
        if (h.unsupported)
            v.add("IMAGE_FEATURES_UNSUPPORTED", Severity::Warning, where,
                  "Image contains unsupported features like non-default colorspace information, "
                  "non-square pixels, or animation.");
        if (h.width && h.height && (!power_of_two(h.width) || !power_of_two(h.height)))
            v.add("IMAGE_NPOT_DIMENSIONS", Severity::Information, where,
                  "Image has non-power-of-two dimensions: " + std::to_string(h.width) + "x" +
                      std::to_string(h.height) + ".");
    }
}

} // namespace sherpa::scene::detail
