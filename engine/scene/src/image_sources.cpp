#include <sherpa/scene/image_sources.h>
#include <sherpa/scene/material_extension_slots.h>

#include <array>
#include <utility>

namespace sherpa::scene {
namespace {

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// glTF URIs are percent-encoded ("my%20image.png"); malformed escapes stay as written.
std::string percent_decoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size()) {
            const int high = hex_value(uri[i + 1]), low = hex_value(uri[i + 2]);
            if (high >= 0 && low >= 0) {
                out += static_cast<char>(high * 16 + low);
                i += 2;
                continue;
            }
        }
        out += uri[i];
    }
    return out;
}

bool reads_image(const Scene& scene, const TextureSlot& slot, std::int32_t image) {
    return slot.present() && std::size_t(slot.texture) < scene.textures.size() &&
           scene.textures[std::size_t(slot.texture)].image == image;
}

} // namespace

std::filesystem::path image_file_path(const Scene& scene, const ImageRecord& image) {
    if (image.uri.empty() || image.uri.rfind("data:", 0) == 0) return {};
    const std::filesystem::path uri(percent_decoded(image.uri));
    if (uri.is_absolute() || scene.source.rfind("builtin:", 0) == 0) return uri;
    return std::filesystem::path(scene.source).parent_path() / uri;
}

bool image_is_missing(const ImageRecord& image) {
    return image.encoded.empty() && image.pixels.empty();
}

std::string image_missing_reason(const Scene& scene, const ImageRecord& image) {
    const std::filesystem::path path = image_file_path(scene, image);
    if (!image_is_missing(image) || path.empty()) return {};
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) return "not found";
    if (ec) return "cannot be read: " + ec.message();
    if (std::filesystem::is_directory(status)) return "is a directory, not a file";
    if (!std::filesystem::is_regular_file(status)) return "is not a regular file";
    if (std::filesystem::file_size(path, ec) == 0 && !ec) return "is empty";
    return "cannot be read";
}

std::vector<std::string> image_slot_uses(const Scene& scene, std::int32_t image) {
    std::vector<std::string> uses;
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const MaterialInstance& mat = scene.materials[m];
        const std::array<std::pair<const TextureSlot*, const char*>, 5> slots{{
            {&mat.base_color, "baseColorTexture"},
            {&mat.metallic_roughness, "metallicRoughnessTexture"},
            {&mat.normal, "normalTexture"},
            {&mat.occlusion, "occlusionTexture"},
            {&mat.emissive, "emissiveTexture"},
        }};
        std::string names;
        for (const auto& [slot, name] : slots)
            if (reads_image(scene, *slot, image))
                names += (names.empty() ? "" : ", ") + std::string(name);
        if (mat.specular_glossiness &&
            reads_image(scene, mat.specular_glossiness->specular_glossiness, image))
            names += (names.empty() ? "" : ", ") + std::string("specularGlossinessTexture");
        for (const ExtensionTextureSlot& e : extension_texture_slots(mat))
            if (reads_image(scene, *e.slot, image))
                names += (names.empty() ? "" : ", ") + std::string(e.name);
        if (names.empty()) continue;
        const std::string who =
            mat.name.empty() ? "material " + std::to_string(m) : "material '" + mat.name + "'";
        uses.push_back(who + " " + names);
    }
    return uses;
}

std::string image_location(const Scene& scene, std::int32_t image) {
    if (image < 0 || std::size_t(image) >= scene.images.size())
        return "image " + std::to_string(image);
    const ImageRecord& img = scene.images[std::size_t(image)];
    if (const auto path = image_file_path(scene, img); !path.empty()) return path.string();
    if (img.buffer_view >= 0) return "bufferView " + std::to_string(img.buffer_view);
    if (img.uri.rfind("data:", 0) == 0) return "data URI";
    return "image " + std::to_string(image);
}

} // namespace sherpa::scene
