#include "gltf_prepare.h"

#include "gltf_lenient.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sherpa::scene::detail {
namespace {

using nlohmann::json;

constexpr const char* kCodecs[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};

bool mentions(std::span<const std::uint8_t> bytes, std::string_view key) {
    return std::search(bytes.begin(), bytes.end(), key.begin(), key.end()) != bytes.end();
}

std::uint32_t le32(std::span<const std::uint8_t> b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
           std::uint32_t(b[at + 3]) << 24;
}

// Gives each fallback buffer of `root` a 1-byte data URI; false when there is none.
bool replace_fallback_buffers(json& root) {
    bool changed = false;
    if (!root.contains("buffers") || !root["buffers"].is_array()) return false;
    for (json& buffer : root["buffers"]) {
        if (!buffer.is_object() || buffer.contains("uri") || !buffer.contains("extensions"))
            continue;
        for (const char* codec : kCodecs) {
            const json& ext = buffer["extensions"];
            if (ext.is_object() && ext.contains(codec) && ext[codec].is_object() &&
                ext[codec].value("fallback", false)) {
                buffer["uri"] = "data:application/octet-stream;base64,AA==";
                buffer["byteLength"] = 1;
                changed = true;
            }
        }
    }
    return changed;
}

// Moves each Draco primitive's bufferView-less `indices` into its extension object.
bool stash_draco_indices(json& root) {
    if (!root.contains("meshes") || !root["meshes"].is_array()) return false;
    const json* accessors = root.contains("accessors") ? &root["accessors"] : nullptr;
    bool changed = false;
    for (json& mesh : root["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives")) continue;
        for (json& prim : mesh["primitives"]) {
            if (!prim.is_object() || !prim.contains("indices") || !prim.contains("extensions") ||
                !prim["extensions"].is_object() ||
                !prim["extensions"].contains("KHR_draco_mesh_compression") ||
                !prim["extensions"]["KHR_draco_mesh_compression"].is_object())
                continue;
            const std::size_t index = prim["indices"].get<std::size_t>(); // validated
            if (accessors && index < accessors->size() &&
                (*accessors)[index].contains("bufferView"))
                continue;
            prim["extensions"]["KHR_draco_mesh_compression"][kDracoIndicesKey] = index;
            prim.erase("indices");
            changed = true;
        }
    }
    return changed;
}

} // namespace

std::vector<std::uint8_t> prepared_for_tinygltf(std::span<const std::uint8_t> bytes) {
    if (!mentions(bytes, "\"fallback\"") && !mentions(bytes, "KHR_draco_mesh_compression"))
        return {}; // most files: no second JSON parse
    const bool glb = bytes.size() >= 20 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const std::size_t json_length = glb ? le32(bytes, 12) : bytes.size();
    const auto json_bytes = glb ? bytes.subspan(20, json_length) : bytes;
    json root = json::parse(json_bytes.begin(), json_bytes.end());
    const bool fallback = replace_fallback_buffers(root);
    if (!stash_draco_indices(root) && !fallback) return {};
    return with_json(root, bytes, glb); // a .glb keeps its BIN chunk
}

} // namespace sherpa::scene::detail
