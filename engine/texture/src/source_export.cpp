// Source images as decoded, written as PNGs (textures --export-source).
#include <sherpa/texture/source_export.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>
#include <system_error>

#include <sherpa/scene/image_sources.h>
#include <sherpa/texture/basis.h>
#include <sherpa/texture/texture_cache.h>

namespace sherpa::tex {
namespace {

// Bidirectional-text controls (U+061C, U+200E/F, U+202A-U+202E, U+2066-U+2069) as
// UTF-8: the byte length of the one starting at name[at], or 0. "photo\u202Egnp.exe"
// would show as "photoexe.png".
std::size_t bidi_control_at(std::string_view name, std::size_t at) {
    const auto byte = [&](std::size_t i) {
        return at + i < name.size() ? static_cast<unsigned char>(name[at + i]) : 0u;
    };
    if (byte(0) == 0xD8 && byte(1) == 0x9C) return 2;
    if (byte(0) != 0xE2) return 0;
    if (byte(1) == 0x80 &&
        (byte(2) == 0x8E || byte(2) == 0x8F || (byte(2) >= 0xAA && byte(2) <= 0xAE)))
        return 3;
    if (byte(1) == 0x81 && byte(2) >= 0xA6 && byte(2) <= 0xA9) return 3;
    return 0;
}

// Longest name kept as it is: NAME_MAX is 255 bytes on Linux file systems, and the
// name still gets "_imageN_K.png" appended when it collides.
constexpr std::size_t kMaxStemBytes = 160;

// A name over kMaxStemBytes keeps its first 120 bytes (cut at a UTF-8 character
// boundary) and gets 16 hex digits of the whole name's hash, so long names that
// share a beginning stay apart.
std::string shortened(std::string name) {
    if (name.size() <= kMaxStemBytes) return name;
    const std::uint64_t hash =
        hash_bytes({reinterpret_cast<const std::uint8_t*>(name.data()), name.size()}).low;
    std::size_t cut = 120;
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
    char hex[20];
    std::snprintf(hex, sizeof hex, "_%016llx", static_cast<unsigned long long>(hash));
    return name.substr(0, cut) + hex;
}

// Keeps what every common file system accepts in a name; the rest becomes '_', bidi
// controls are dropped, and a long name is shortened (see above).
std::string file_safe(std::string_view name) {
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (const std::size_t n = bidi_control_at(name, i)) {
            i += n - 1;
            continue;
        }
        const char c = name[i];
        const auto u = static_cast<unsigned char>(c);
        const bool bad = u < 0x20 || u == 0x7f ||
                         std::string_view("/\\:*?\"<>|").find(c) != std::string_view::npos;
        out += bad ? '_' : c;
    }
    if (out.empty() || out == "." || out == "..") return {};
    return shortened(std::move(out));
}

std::string base_name(const scene::Scene& scene, const scene::ImageRecord& img, std::size_t index) {
    const std::string n = "image" + std::to_string(index);
    if (const auto path = scene::image_file_path(scene, img); !path.empty()) {
        if (std::string stem = file_safe(path.stem().string()); !stem.empty()) return stem;
        return n;
    }
    if (std::string named = file_safe(img.name); !named.empty()) return named;
    if (img.buffer_view >= 0) return n + "_bufferView" + std::to_string(img.buffer_view);
    if (img.uri.rfind("data:", 0) == 0) return n + "_datauri";
    return n + "_generated";
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

} // namespace

// The MIME type wins over the URI because embedded images have no URI.
std::string image_decoder_hint(const scene::ImageRecord& img) {
    if (img.mime_type == "image/png") return "image.png";
    if (img.mime_type == "image/jpeg") return "image.jpg";
    if (img.mime_type == "image/webp") return "image.webp";
    const auto slash = img.uri.find_last_of('/');
    return img.uri.substr(slash == std::string::npos ? 0 : slash + 1);
}

bool decode_image_source(const scene::ImageRecord& img, RgbaImage& out, std::string& error) {
    if (scene::image_is_missing(img)) {
        error =
            "missing: " +
            (!img.uri.empty() ? "'" + img.uri + "' (the file does not exist or cannot be read)"
             : img.buffer_view >= 0 ? "bufferView " + std::to_string(img.buffer_view) + " is empty"
                                    : std::string("no bytes to decode"));
        return false;
    }
    if (img.encoded.empty()) {
        if (img.pixels.size() != std::size_t{img.width} * img.height * 4 || img.pixels.empty()) {
            error = "image has neither encoded bytes nor RGBA8 pixels";
            return false;
        }
        out = RgbaImage{img.width, img.height, img.pixels};
        return true;
    }
    return decode_image_or_ktx2(img.encoded, image_decoder_hint(img), out,
                                error); // KTX2 by identifier
}

std::vector<std::string> source_export_names(const scene::Scene& scene) {
    std::vector<std::string> names;
    std::set<std::string> taken; // lower-case
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        std::string name = base_name(scene, scene.images[i], i);
        if (taken.count(lower(name + ".png"))) name += "_image" + std::to_string(i);
        // Only a file literally named like another's fallback can still collide.
        for (int k = 2; taken.count(lower(name + ".png")); ++k)
            name = base_name(scene, scene.images[i], i) + "_image" + std::to_string(i) + "_" +
                   std::to_string(k);
        taken.insert(lower(name + ".png"));
        names.push_back(name + ".png");
    }
    return names;
}

std::vector<SourceExport> export_sources(const scene::Scene& scene,
                                         const std::filesystem::path& dir) {
    std::vector<SourceExport> out;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const std::vector<std::string> names = source_export_names(scene);
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        SourceExport e;
        e.image = static_cast<std::int32_t>(i);
        e.file = dir / names[i];
        const std::string where = scene::image_location(scene, e.image);
        RgbaImage decoded;
        std::string error;
        if (scene::image_is_missing(scene.images[i])) {
            e.error = where + ": missing (no bytes to decode)";
        } else if (!decode_image_source(scene.images[i], decoded, error)) {
            e.error = where + ": " + error;
        } else if (!write_png(e.file.string(), decoded.width, decoded.height, decoded.pixels,
                              error)) {
            e.error = e.file.string() + ": " + error;
        } else {
            e.width = decoded.width;
            e.height = decoded.height;
        }
        out.push_back(std::move(e));
    }
    return out;
}

} // namespace sherpa::tex
