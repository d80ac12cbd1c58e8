#include "gltf_lenient.h"

#include <cstring>
#include <string_view>

namespace sherpa::scene::detail {
namespace {

using nlohmann::json;

// glTF properties whose values are integers (indices, sizes, enums).
constexpr std::string_view kIntegerKeys[] = {"byteOffset",
                                             "byteLength",
                                             "byteStride",
                                             "count",
                                             "componentType",
                                             "bufferView",
                                             "buffer",
                                             "target",
                                             "mode",
                                             "indices",
                                             "material",
                                             "mesh",
                                             "skin",
                                             "camera",
                                             "children",
                                             "nodes",
                                             "joints",
                                             "skeleton",
                                             "sampler",
                                             "source",
                                             "index",
                                             "texCoord",
                                             "input",
                                             "output",
                                             "node",
                                             "scene",
                                             "magFilter",
                                             "minFilter",
                                             "wrapS",
                                             "wrapT",
                                             "inverseBindMatrices",
                                             "light",
                                             "attributes",
                                             "targets",
                                             "variants"};

bool integer_key(std::string_view key) {
    for (std::string_view k : kIntegerKeys)
        if (k == key) return true;
    return false;
}

bool to_integer(json& j) {
    if (!j.is_number_float()) return false;
    const double x = j.get<double>();
    if (!(x == static_cast<double>(static_cast<std::int64_t>(x))) || x < -9007199254740992.0 ||
        x > 9007199254740992.0)
        return false;
    if (x >= 0)
        j = static_cast<std::uint64_t>(x); // nlohmann keeps integers >= 0 unsigned
    else
        j = static_cast<std::int64_t>(x);
    return true;
}

// Integer-valued members: the value, array elements, or (attributes, targets) the
// values of an object or of objects in an array.
bool normalize_value(json& j, int depth) {
    bool changed = to_integer(j);
    if (depth < 2 && (j.is_array() || j.is_object()))
        for (json& e : j) changed |= normalize_value(e, depth + 1);
    return changed;
}

bool walk(json& j, int depth) {
    if (depth > 32) return false;
    bool changed = false;
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) {
            if (it.key() == "extras") continue;
            if (integer_key(it.key())) changed |= normalize_value(it.value(), 0);
            if (it.value().is_structured()) changed |= walk(it.value(), depth + 1);
        }
    } else if (j.is_array()) {
        for (json& e : j)
            if (e.is_structured()) changed |= walk(e, depth + 1);
    }
    return changed;
}

// Bytes a base64 payload decodes to.
std::size_t base64_size(std::string_view payload) {
    std::size_t n = payload.size();
    std::size_t pad = 0;
    while (n > 0 && payload[n - 1] == '=' && pad < 2) --n, ++pad;
    return n / 4 * 3 + (n % 4 == 3 ? 2 : n % 4 == 2 ? 1 : 0);
}

constexpr std::string_view kReadableMedia[] = {
    "data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,",
    "data:image/jpeg;base64,", "data:image/png;base64,", "data:text/plain;base64,"};

bool has_scheme(std::string_view uri) {
    const auto colon = uri.find(':');
    if (colon == std::string_view::npos || colon < 2) return false; // "C:" is a drive
    for (std::size_t i = 0; i < colon; ++i) {
        const char c = uri[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
              (i > 0 && ((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.'))))
            return false;
    }
    return true;
}

bool is_fallback(const json& buffer) {
    if (!buffer.contains("extensions") || !buffer["extensions"].is_object()) return false;
    for (const char* codec : {"EXT_meshopt_compression", "KHR_meshopt_compression"}) {
        const json& e = buffer["extensions"];
        if (e.contains(codec) && e[codec].is_object() && e[codec].value("fallback", false))
            return true;
    }
    return false;
}

void put_le32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint32_t le32(std::span<const std::uint8_t> b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
           std::uint32_t(b[at + 3]) << 24;
}

} // namespace

std::optional<json> with_channel_nodes(const json& root) {
    auto nodeless = [](const json& channel) {
        return channel.is_object() && channel.contains("target") && channel["target"].is_object() &&
               !channel["target"].contains("node");
    };
    bool any = false;
    if (root.contains("animations") && root["animations"].is_array())
        for (const json& a : root["animations"])
            if (a.is_object() && a.contains("channels") && a["channels"].is_array())
                for (const json& c : a["channels"]) any = any || nodeless(c);
    if (!any) return std::nullopt;
    json out = root;
    for (json& a : out["animations"])
        if (a.is_object() && a.contains("channels") && a["channels"].is_array())
            for (json& c : a["channels"])
                if (nodeless(c)) c["target"]["node"] = -1;
    return out;
}

bool normalize_integers(json& root) {
    return walk(root, 0);
}

bool replace_unreadable_buffers(json& root, bool glb, bool glb_has_bin, ValidationReport& report) {
    if (!root.contains("buffers") || !root["buffers"].is_array()) return false;
    bool changed = false;
    json& buffers = root["buffers"];
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        json& b = buffers[i];
        if (!b.is_object() || is_fallback(b)) continue;
        const std::string where = "/buffers/" + std::to_string(i);
        std::string why;
        const auto uri = b.find("uri");
        if (uri == b.end()) {
            if (!glb)
                why = "has no uri (a placeholder): nothing reads its data";
            else if (i > 0)
                why = "has no uri and is not the first buffer: a GLB's BIN chunk belongs to "
                      "buffers[0]";
            else if (!glb_has_bin)
                why = "has no uri and the GLB has no BIN chunk";
        } else if (uri->is_string()) {
            const std::string& u = uri->get_ref<const std::string&>();
            if (u.rfind("data:", 0) == 0) {
                std::string_view header;
                for (std::string_view h : kReadableMedia)
                    if (u.compare(0, h.size(), h) == 0) header = h;
                if (header.empty()) {
                    why = "data URI is not base64 data of a buffer media type";
                } else {
                    const std::size_t size = base64_size(std::string_view(u).substr(header.size()));
                    const std::int64_t declared = b.value("byteLength", std::int64_t{0});
                    if (size == 0) {
                        why = "data URI holds no data";
                    } else if (static_cast<std::int64_t>(size) != declared) {
                        b["byteLength"] = size; // tinygltf wants them equal; views were checked
                        changed = true;
                        report.messages.push_back(
                            {"SHERPA_BUFFER_LENGTH_ADJUSTED",
                             "data URI holds " + std::to_string(size) + " bytes, byteLength says " +
                                 std::to_string(declared) + "; read as " + std::to_string(size),
                             where, Severity::Warning});
                    }
                }
            } else if (has_scheme(u)) {
                why = "uri \"" + u.substr(0, 60) +
                      "\" is not a relative path; Sherpa does not fetch it";
            }
        }
        if (why.empty()) continue;
        b["uri"] = "data:application/octet-stream;base64,AA==";
        b["byteLength"] = 1;
        changed = true;
        report.messages.push_back(
            {"SHERPA_BUFFER_NOT_LOADED",
             "buffers[" + std::to_string(i) + "] " + why + "; what reads it is skipped", where,
             Severity::Warning});
    }
    return changed;
}

bool drop_unreadable_instancing_ids(json& root, ValidationReport& report) {
    const auto nodes = root.find("nodes");
    if (nodes == root.end() || !nodes->is_array()) return false;
    bool changed = false;
    for (std::size_t n = 0; n < nodes->size(); ++n) {
        json& node = (*nodes)[n];
        if (!node.is_object() || !node.contains("extensions")) continue;
        json& extensions = node["extensions"];
        if (!extensions.is_object() || !extensions.contains("EXT_mesh_gpu_instancing")) continue;
        json& ext = extensions["EXT_mesh_gpu_instancing"];
        if (!ext.is_object() || !ext.contains("attributes") || !ext["attributes"].is_object())
            continue;
        json& attributes = ext["attributes"];
        for (auto it = attributes.begin(); it != attributes.end();) {
            if (it->is_number_unsigned() && it->get<std::uint64_t>() <= 0x7FFFFFFF) {
                ++it;
                continue;
            }
            const std::string path = "nodes[" + std::to_string(n) +
                                     "].extensions.EXT_mesh_gpu_instancing.attributes." + it.key();
            report.messages.push_back(
                {"SHERPA_VALUE_IGNORED",
                 path + ": " + it->dump(-1, ' ', false, json::error_handler_t::replace) +
                     " is not an accessor index Sherpa can read (0..2147483647); the attribute "
                     "is ignored",
                 "/nodes/" + std::to_string(n) + "/extensions/EXT_mesh_gpu_instancing/attributes/" +
                     it.key(),
                 Severity::Warning});
            it = attributes.erase(it);
            changed = true;
        }
    }
    return changed;
}

std::vector<std::uint8_t> with_json(const json& root, std::span<const std::uint8_t> file,
                                    bool glb) {
    std::string text = root.dump(-1, ' ', false, json::error_handler_t::replace);
    if (!glb) return {text.begin(), text.end()};
    text.resize((text.size() + 3) / 4 * 4, ' '); // chunks are 4-byte aligned
    const std::size_t json_length = le32(file, 12);
    const auto rest = file.subspan(std::min(file.size(), 20 + json_length)); // BIN chunk as it was
    std::vector<std::uint8_t> out(file.begin(), file.begin() + 8);
    put_le32(out, static_cast<std::uint32_t>(12 + 8 + text.size() + rest.size()));
    put_le32(out, static_cast<std::uint32_t>(text.size()));
    put_le32(out, 0x4E4F534Au); // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    out.insert(out.end(), rest.begin(), rest.end());
    return out;
}

} // namespace sherpa::scene::detail
