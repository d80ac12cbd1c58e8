#include "gltf_validate.h"

#include "checked_math.h"
#include "json_checker.h"

#include <sherpa/scene/gltf_extensions.h>

#include <cctype>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sherpa::scene::detail {
namespace {

using Bytes = std::span<const std::uint8_t>;

bool starts_with(Bytes b, const char* magic, std::size_t at = 0) {
    const std::size_t n = std::strlen(magic);
    return b.size() >= at + n && std::memcmp(b.data() + at, magic, n) == 0;
}

// What a file that is not a JSON object starts with, for "not a glTF file: starts
// with ...". Recognises the formats people most often mistake for glTF.
std::string sniff(Bytes b) {
    if (starts_with(b, "\x89PNG")) return "PNG image bytes";
    if (starts_with(b, "\xFF\xD8\xFF")) return "JPEG image bytes";
    if (starts_with(b, "RIFF") && starts_with(b, "WEBP", 8)) return "WebP image bytes";
    if (starts_with(b, "\xABKTX 20\xBB")) return "KTX2 texture bytes";
    if (starts_with(b, "DDS ")) return "DDS texture bytes";
    if (starts_with(b, "PK\x03\x04")) return "ZIP archive bytes";
    if (starts_with(b, "\x1F\x8B")) return "gzip-compressed bytes";
    if (!b.empty() && b[0] == '<') return "'<' (XML or HTML text)";
    char hex[40];
    const std::size_t n = std::min<std::size_t>(b.size(), 4);
    bool binary = false;
    for (std::size_t i = 0; i < n; ++i) binary |= b[i] < 0x09 || b[i] == 0x7F;
    if (!binary && !b.empty() && b[0] >= 0x20 && b[0] < 0x7F)
        return std::string("text that is not a JSON object ('") + static_cast<char>(b[0]) + "')";
    int len = 0;
    for (std::size_t i = 0; i < n; ++i)
        len += std::snprintf(hex + len, sizeof(hex) - static_cast<std::size_t>(len), "%s%02X",
                             i ? " " : "", b[i]);
    return "binary data (" + std::string(hex, static_cast<std::size_t>(len)) + ")";
}

std::uint32_t le32(Bytes b, std::size_t at) {
    return static_cast<std::uint32_t>(b[at]) | static_cast<std::uint32_t>(b[at + 1]) << 8 |
           static_cast<std::uint32_t>(b[at + 2]) << 16 |
           static_cast<std::uint32_t>(b[at + 3]) << 24;
}

// The JSON chunk of a .glb, or the problem with its header.
std::string glb_json(Bytes b, Bytes& json_bytes) {
    if (b.size() < 20)
        return "binary glTF (.glb) is truncated: " + std::to_string(b.size()) +
               " bytes, the header alone needs 20";
    if (le32(b, 4) != 2)
        return "binary glTF (.glb) version " + std::to_string(le32(b, 4)) +
               "; Sherpa reads version 2";
    if (le32(b, 8) > b.size())
        return "binary glTF (.glb) is truncated: its header says " + std::to_string(le32(b, 8)) +
               " bytes, the file has " + std::to_string(b.size());
    if (!starts_with(b, "JSON", 16)) return "binary glTF (.glb) does not start with a JSON chunk";
    const std::size_t length = le32(b, 12);
    if (!range_fits(20, length, b.size()))
        return "binary glTF (.glb) JSON chunk of " + std::to_string(length) +
               " bytes runs past the end of the file";
    json_bytes = b.subspan(20, length);
    return {};
}

// nlohmann's own DOM builder (what json::parse runs), which also notes the document
// order of the keys DocumentOrder keeps: one parse gives both. It follows the path
// /meshes/m/primitives/p/attributes through the first levels only (a flag and a
// counter per level), so the cost per token is a few compares.
class OrderRecordingParser : public nlohmann::detail::json_sax_dom_parser<json> {
    using Base = nlohmann::detail::json_sax_dom_parser<json>;

public:
    OrderRecordingParser(json& out, DocumentOrder* order) : Base(out), order_(order) {}

    bool null() { return element(), Base::null(); }
    bool boolean(bool x) { return element(), Base::boolean(x); }
    bool number_integer(number_integer_t x) { return element(), Base::number_integer(x); }
    bool number_unsigned(number_unsigned_t x) { return element(), Base::number_unsigned(x); }
    bool number_float(number_float_t x, const string_t& s) {
        return element(), Base::number_float(x, s);
    }
    bool string(string_t& x) { return element(), Base::string(x); }
    bool binary(binary_t& x) { return element(), Base::binary(x); }
    bool start_object(std::size_t n) { return open(false), Base::start_object(n); }
    bool start_array(std::size_t n) { return open(true), Base::start_array(n); }
    bool end_object() { return close(), Base::end_object(); }
    bool end_array() { return close(), Base::end_array(); }
    bool key(string_t& k) {
        if (order_ && k.size() == 10 && k == "extensions") order_->has_extensions = true;
        if (order_ && depth_ < kLevels && on_path_[depth_]) {
            if (depth_ == 6)
                order_->attributes[count_[2] - 1][count_[4] - 1].push_back(k);
            else
                matched_[depth_] = k == kPath[depth_];
        }
        return Base::key(k);
    }

private:
    // Depth (open containers) -> the key its object must have for the path to go on:
    // the root's "meshes", a mesh's "primitives", a primitive's "attributes".
    static constexpr std::size_t kLevels = 7;
    static constexpr std::string_view kPath[kLevels] = {"", "meshes",     "", "primitives",
                                                        "", "attributes", ""};
    void element() {
        if (depth_ < kLevels) ++count_[depth_]; // counts array elements (objects ignore it)
    }
    void open(bool array) {
        element();
        ++depth_;
        if (!order_ || depth_ >= kLevels) return;
        const std::size_t d = depth_;
        // Levels 2 and 4 are arrays (meshes, primitives), the others objects; levels
        // 2, 4 and 6 are the values of the keys kPath names one level up.
        const bool want_array = d == 2 || d == 4;
        const bool keyed = d % 2 == 0;
        on_path_[d] =
            array == want_array && (d == 1 || (on_path_[d - 1] && (!keyed || matched_[d - 1])));
        matched_[d] = false;
        count_[d] = 0;
        if (d == 6 && on_path_[d]) {
            auto& meshes = order_->attributes;
            if (meshes.size() < count_[2]) meshes.resize(count_[2]);
            auto& prims = meshes[count_[2] - 1];
            if (prims.size() < count_[4]) prims.resize(count_[4]);
        }
    }
    void close() {
        if (depth_ < kLevels) on_path_[depth_] = false;
        --depth_;
    }

    DocumentOrder* order_;
    std::size_t depth_ = 0;
    bool on_path_[kLevels] = {}, matched_[kLevels] = {};
    std::size_t count_[kLevels] = {};
};

std::string check_depth(Bytes b) {
    const std::size_t at = json_depth_exceeded_at(b, kMaxJsonDepth);
    if (at == SIZE_MAX) return {};
    return "JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels (at byte " +
           std::to_string(at) + "); no glTF needs that, and parsing it would overflow the stack";
}

// The problem with a buffer's relative-path URI, or "": tinygltf decodes percent
// escapes leniently, so "%zz" and "%00" became a truncated or empty path.
std::string uri_problem(const std::string& uri) {
    if (uri.empty()) return "is empty";
    if (uri.rfind("data:", 0) == 0) return {};
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') continue;
        if (i + 2 >= uri.size() || !std::isxdigit(static_cast<unsigned char>(uri[i + 1])) ||
            !std::isxdigit(static_cast<unsigned char>(uri[i + 2])))
            return "has a malformed percent escape at character " + std::to_string(i);
        if (uri[i + 1] == '0' && uri[i + 2] == '0') return "contains a NUL byte (%00)";
    }
    return {};
}

// asset.version and asset.minVersion: Sherpa reads glTF 2.0.
std::string check_asset(const json& root) {
    const auto asset = root.find("asset");
    if (asset == root.end() || !asset->is_object())
        return "no \"asset\" object: not a glTF 2.0 file";
    const auto version = asset->find("version");
    if (version == asset->end() || !version->is_string())
        return "asset.version is missing: not a glTF 2.0 file";
    const std::string v = version->get<std::string>();
    if (v.rfind("2.", 0) != 0) return "asset.version \"" + v + "\": Sherpa reads glTF 2.x only";
    // asset.minVersion above 2.0 is named by the validator and a warning; the file loads.
    return {};
}

// extensionsRequired, checked before any other property: a file that needs an
// extension Sherpa does not read fails on the extension's name, not on a symptom of
// it (a Draco primitive's accessors have no bufferView, which tinygltf reports as
// "accessor[0] invalid bufferView").
std::string check_required_extensions(const json& root) {
    const auto required = root.find("extensionsRequired");
    if (required == root.end()) return {};
    if (!required->is_array())
        return "extensionsRequired: " + describe(*required) + " is not an array";
    // Named by the first one's place (its JSON pointer), then all of them.
    std::string unsupported, first;
    for (std::size_t i = 0; i < required->size(); ++i) {
        const json& name = (*required)[i];
        if (!name.is_string())
            return "extensionsRequired: " + describe(name) + " is not an extension name";
        if (is_supported_gltf_extension(name.get<std::string>())) continue;
        if (first.empty()) first = "extensionsRequired[" + std::to_string(i) + "]";
        unsupported += (unsupported.empty() ? "\"" : ", \"") + name.get<std::string>() + "\"";
    }
    if (unsupported.empty()) return {};
    return first + ": " + unsupported +
           " not supported by Sherpa (the file cannot be read without it)";
}

std::string check_properties(const json& root) {
    Checker c;
    std::vector<std::uint64_t> buffer_lengths;
    c.each(root, "buffers", [&](const json& b, const std::string& w) {
        buffer_lengths.push_back(c.uint(b, "byteLength", w, 1, kMaxSafe, true).value_or(0));
        if (const auto uri = b.find("uri"); c.error.empty() && uri != b.end()) {
            if (!uri->is_string())
                c.error = w + ".uri: " + describe(*uri) + " is not a string";
            else if (const std::string p = uri_problem(uri->get<std::string>()); !p.empty())
                c.error = w + ".uri " + describe(*uri) + ": " + p;
        }
    });
    c.each(root, "bufferViews", [&](const json& v, const std::string& w) {
        const auto buffer = c.index(v, "buffer", w, true);
        const auto offset = c.uint(v, "byteOffset", w, 0, kMaxSafe).value_or(0);
        const auto length = c.uint(v, "byteLength", w, 1, kMaxSafe, true).value_or(0);
        if (const auto stride = c.uint(v, "byteStride", w, 4, 252); stride && *stride % 4)
            c.error = w + ".byteStride: " + std::to_string(*stride) + " is not a multiple of 4";
        if (c.error.empty() && buffer && *buffer < buffer_lengths.size() &&
            !range_fits(offset, length, buffer_lengths[*buffer]))
            c.error = w + ": byteOffset " + std::to_string(offset) + " + byteLength " +
                      std::to_string(length) + " exceeds buffers[" + std::to_string(*buffer) +
                      "].byteLength " + std::to_string(buffer_lengths[*buffer]);
    });
    c.each(root, "accessors", [&](const json& a, const std::string& w) {
        c.index(a, "bufferView", w);
        c.uint(a, "byteOffset", w, 0, kMaxSafe);
        c.uint(a, "componentType", w, 5120, 5126, true);
        c.uint(a, "count", w, 0, kMaxSafe, true);
        if (c.error.empty() && a.contains("sparse")) {
            const json& s = a["sparse"];
            const std::string sw = w + ".sparse";
            c.uint(s, "count", sw, 1, kMaxSafe, true);
            for (const char* part : {"indices", "values"}) {
                if (!c.error.empty()) break;
                if (!s.contains(part) || !s[part].is_object()) {
                    c.error = sw + "." + part + ": required object is missing";
                    break;
                }
                c.index(s[part], "bufferView", sw + "." + part, true);
                c.uint(s[part], "byteOffset", sw + "." + part, 0, kMaxSafe);
            }
            if (c.error.empty())
                c.uint(s["indices"], "componentType", sw + ".indices", 5121, 5125, true);
        }
    });
    c.each(root, "images",
           [&](const json& i, const std::string& w) { c.index(i, "bufferView", w); });
    c.each(root, "textures", [&](const json& t, const std::string& w) {
        c.index(t, "source", w);
        c.index(t, "sampler", w);
    });
    c.each(root, "meshes", [&](const json& m, const std::string& w) {
        if (!m.contains("primitives") || !m["primitives"].is_array()) {
            c.error = w + ".primitives: required array is missing";
            return;
        }
        for (std::size_t p = 0; p < m["primitives"].size() && c.error.empty(); ++p) {
            const json& prim = m["primitives"][p];
            const std::string pw = w + ".primitives[" + std::to_string(p) + "]";
            c.index(prim, "indices", pw);
            c.index(prim, "material", pw);
            c.uint(prim, "mode", pw, 0, 6);
            if (prim.contains("attributes") && prim["attributes"].is_object())
                for (const auto& [name, value] : prim["attributes"].items())
                    c.index(prim["attributes"], name.c_str(), pw + ".attributes");
        }
    });
    c.each(root, "nodes", [&](const json& n, const std::string& w) {
        for (const char* key : {"mesh", "camera", "skin"}) c.index(n, key, w);
        c.index_array(n, "children", w);
        // EXT_mesh_gpu_instancing's accessor ids, which tinygltf reads as int, are not
        // refused: drop_unreadable_instancing_ids (gltf_lenient.h) ignores them by name.
    });
    c.each(root, "scenes",
           [&](const json& s, const std::string& w) { c.index_array(s, "nodes", w); });
    if (c.error.empty()) c.index(root, "scene", "(root)");
    return c.error;
}

} // namespace

std::string validate_gltf_bytes(std::span<const std::uint8_t> bytes) {
    json root;
    if (std::string e = parse_gltf_document(bytes, root); !e.empty()) return e;
    if (std::string e = check_gltf_document(root); !e.empty()) return e;
    return check_gltf_properties(root);
}

std::string check_gltf_document(const nlohmann::json& root) {
    if (std::string e = check_asset(root); !e.empty()) return e;
    return check_required_extensions(root);
}

std::string check_gltf_properties(const nlohmann::json& root) {
    if (std::string e = check_properties(root); !e.empty()) return e;
    return check_extension_properties(root);
}

std::string parse_gltf_document(std::span<const std::uint8_t> bytes, nlohmann::json& root,
                                std::string* khronos_code, DocumentOrder* order) {
    if (bytes.empty()) return "file is empty";
    Bytes text = bytes;
    if (starts_with(bytes, "glTF")) {
        if (std::string e = glb_json(bytes, text); !e.empty()) {
            if (khronos_code && bytes.size() >= 20 &&
                !range_fits(20, le32(bytes, 12), bytes.size()))
                *khronos_code = "GLB_UNEXPECTED_END_OF_CHUNK_DATA";
            return e;
        }
    } else {
        std::size_t at = starts_with(bytes, "\xEF\xBB\xBF") ? 3 : 0; // UTF-8 byte order mark
        while (at < bytes.size() && std::strchr(" \t\r\n", bytes[at]) && bytes[at]) ++at;
        if (at == bytes.size()) return "file holds only white space";
        if (bytes[at] != '{') return "not a glTF file: starts with " + sniff(bytes.subspan(at));
    }
    if (std::string e = check_depth(text); !e.empty()) return e;
    try {
        OrderRecordingParser sax(root, order);
        json::sax_parse(text.begin(), text.end(), &sax);
    } catch (const json::parse_error& e) {
        if (khronos_code) *khronos_code = "INVALID_JSON";
        return "not valid JSON: parse error at byte " + std::to_string(e.byte) +
               (e.id == 101 ? " (syntax error or invalid UTF-8)" : "");
    } catch (const std::exception&) {
        return "not valid JSON";
    }
    if (!root.is_object()) return "the top-level JSON value is not an object: not a glTF file";
    return {};
}

std::size_t json_depth_exceeded_at(std::span<const std::uint8_t> text, std::size_t limit) {
    std::size_t depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const std::uint8_t c = text[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '{' || c == '[') {
            if (++depth > limit) return i;
        } else if ((c == '}' || c == ']') && depth > 0) {
            --depth;
        }
    }
    return SIZE_MAX;
}

} // namespace sherpa::scene::detail
