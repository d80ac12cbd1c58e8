// Raw JSON checks of the extension properties Sherpa reads (see json_checker.h):
// tinygltf parses extension integers into `int` (wrapping, not failing), so a meshopt count of
// 2^32, a Draco attribute id of 2^32 or a textureInfo index of 2^32 wrapped to a small number and
// passed every later range check, while 5 was an error.
#include "json_checker.h"

#include <string_view>

namespace sherpa::scene::detail {
namespace {

constexpr const char* kMeshoptCodecs[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};
constexpr const char* kImageExtensions[] = {"KHR_texture_basisu", "EXT_texture_webp"};

// obj.extensions[name] when both are objects, else null.
const json* extension(const json& obj, const char* name) {
    const auto all = obj.find("extensions");
    if (all == obj.end() || !all->is_object()) return nullptr;
    const auto ext = all->find(name);
    return ext != all->end() && ext->is_object() ? &*ext : nullptr;
}

void check_string(Checker& c, const json& obj, const char* key, const std::string& where,
                  bool required) {
    if (!c.error.empty()) return;
    const auto it = obj.find(key);
    if (it == obj.end()) {
        if (required) c.error = where + "." + key + ": required property is missing";
    } else if (!it->is_string()) {
        c.error = where + "." + key + ": " + describe(*it) + " is not a string";
    }
}

void check_meshopt(Checker& c, const json& root) {
    c.each(root, "buffers", [&](const json& b, const std::string& w) {
        for (const char* codec : kMeshoptCodecs)
            if (const json* ext = extension(b, codec); ext && c.error.empty()) {
                const auto fallback = ext->find("fallback");
                if (fallback != ext->end() && !fallback->is_boolean())
                    c.error = w + ".extensions." + codec + ".fallback: " + describe(*fallback) +
                              " is not a boolean";
            }
    });
    c.each(root, "bufferViews", [&](const json& v, const std::string& w) {
        for (const char* codec : kMeshoptCodecs)
            if (const json* ext = extension(v, codec)) {
                // tinygltf stores extension integers as int (2^32 + 3 arrives as 3),
                // so offsets, lengths and counts are held to int's range too.
                const std::string ew = w + ".extensions." + codec;
                c.index(*ext, "buffer", ew, true);
                c.uint(*ext, "byteOffset", ew, 0, kMaxIndex);
                c.uint(*ext, "byteLength", ew, 0, kMaxIndex, true);
                c.uint(*ext, "byteStride", ew, 1, 256, true);
                c.uint(*ext, "count", ew, 0, kMaxIndex, true);
                check_string(c, *ext, "mode", ew, true);
                check_string(c, *ext, "filter", ew, false);
            }
    });
}

void check_draco(Checker& c, const json& root) {
    c.each(root, "meshes", [&](const json& m, const std::string& w) {
        const auto prims = m.find("primitives"); // an array: checked with the core properties
        for (std::size_t p = 0; prims != m.end() && p < prims->size() && c.error.empty(); ++p) {
            const json* ext = extension((*prims)[p], "KHR_draco_mesh_compression");
            if (!ext) continue;
            const std::string ew =
                w + ".primitives[" + std::to_string(p) + "].extensions.KHR_draco_mesh_compression";
            c.index(*ext, "bufferView", ew, true);
            const auto ids = ext->find("attributes");
            if (ids == ext->end() || !ids->is_object()) {
                if (c.error.empty()) c.error = ew + ".attributes: required object is missing";
                continue;
            }
            for (const auto& [name, id] : ids->items())
                c.value(id, ew + ".attributes." + name, 0, kMaxIndex);
        }
    });
}

void check_texture_sources(Checker& c, const json& root) {
    c.each(root, "textures", [&](const json& t, const std::string& w) {
        for (const char* name : kImageExtensions)
            if (const json* ext = extension(t, name))
                c.index(*ext, "source", w + ".extensions." + name);
    });
}

// Every textureInfo under a material (core slots and any extension's "...Texture"
// object, e.g. KHR_materials_clearcoat's clearcoatTexture), with its
// KHR_texture_transform texCoord override. `extras` belong to applications.
void check_texture_infos(Checker& c, const json& obj, const std::string& where) {
    for (const auto& [key, value] : obj.items()) {
        if (!c.error.empty()) return;
        if (!value.is_object() || key == "extras") continue;
        const std::string w = where + "." + key;
        if (std::string_view(key).ends_with("Texture")) {
            c.index(value, "index", w, true);
            c.index(value, "texCoord", w);
            if (const json* t = extension(value, "KHR_texture_transform"))
                c.index(*t, "texCoord", w + ".extensions.KHR_texture_transform");
        }
        check_texture_infos(c, value, w);
    }
}

} // namespace

std::string check_extension_properties(const json& root) {
    Checker c;
    check_meshopt(c, root);
    check_draco(c, root);
    check_texture_sources(c, root);
    c.each(root, "materials",
           [&](const json& m, const std::string& w) { check_texture_infos(c, m, w); });
    return c.error;
}

} // namespace sherpa::scene::detail
