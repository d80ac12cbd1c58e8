// Structural glTF diff by JSON pointer (json_diff.h).
#include <sherpa/lab/json_diff.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include <sherpa/core/file_io.h>
#include <sherpa/scene/pointer_target.h>

namespace sherpa::lab {
namespace {

using nlohmann::json;

std::string short_text(const json& v) {
    std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
    if (s.size() > 60) s = s.substr(0, 57) + "...";
    return s;
}

bool is_object_array(const json& v) {
    return v.is_array() && !v.empty() &&
           std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_object(); });
}

// Leaves below `a` and `b` (relative pointers) that differ.
void diff_leaves(const json& a, const json& b, const std::string& at, JsonChange& change) {
    auto add = [&](std::string line) {
        if (change.fields.size() < kMaxFieldsPerChange) change.fields.push_back(std::move(line));
        ++change.field_count;
    };
    if (a.is_object() && b.is_object()) {
        std::set<std::string> keys;
        for (const auto& [k, v] : a.items()) keys.insert(k);
        for (const auto& [k, v] : b.items()) keys.insert(k);
        for (const std::string& k : keys) {
            const std::string p = at + "/" + scene::json_pointer_token(k);
            if (!a.contains(k))
                add(p + ": added " + short_text(b[k]));
            else if (!b.contains(k))
                add(p + ": removed (was " + short_text(a[k]) + ")");
            else if (a[k] != b[k])
                diff_leaves(a[k], b[k], p, change);
        }
        return;
    }
    if (a.is_array() && b.is_array() && a.size() == b.size() &&
        (is_object_array(a) || a.size() > 4)) {
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a[i] != b[i]) diff_leaves(a[i], b[i], at + "/" + std::to_string(i), change);
        return;
    }
    add((at.empty() ? std::string("/") : at) + ": " + short_text(a) + " -> " + short_text(b));
}

// Names in a top-level array of strings (extensionsUsed): "+NAME" and "-NAME".
void diff_names(const json& a, const json& b, JsonChange& change) {
    for (const json& n : b)
        if (std::find(a.begin(), a.end(), n) == a.end()) {
            if (change.fields.size() < kMaxFieldsPerChange)
                change.fields.push_back("+" + short_text(n));
            ++change.field_count;
        }
    for (const json& n : a)
        if (std::find(b.begin(), b.end(), n) == b.end()) {
            if (change.fields.size() < kMaxFieldsPerChange)
                change.fields.push_back("-" + short_text(n));
            ++change.field_count;
        }
    if (change.field_count == 0) change.fields.push_back("order changed"), change.field_count = 1;
}

// Element-wise diff of an array of objects (nodes, accessors, lights...).
void diff_collection(const std::string& at, const json& a, const json& b, JsonDiff& out) {
    const std::size_t n = std::max(a.size(), b.size());
    for (std::size_t i = 0; i < n; ++i) {
        JsonChange c;
        c.pointer = at + "/" + std::to_string(i);
        if (i >= a.size()) {
            c.kind = JsonChangeKind::Added;
        } else if (i >= b.size()) {
            c.kind = JsonChangeKind::Removed;
        } else if (a[i] == b[i]) {
            ++out.unchanged;
            continue;
        } else {
            diff_leaves(a[i], b[i], "", c);
        }
        out.changes.push_back(std::move(c));
    }
}

std::uint64_t count_objects(const json& doc) {
    std::uint64_t n = 0;
    for (const auto& [k, v] : doc.items()) n += is_object_array(v) ? v.size() : 1;
    return n;
}

// Accessor uses by pointer: where a file reads which accessor.
std::map<std::string, std::int64_t> accessor_uses(const json& doc) {
    std::map<std::string, std::int64_t> uses;
    auto add = [&](const std::string& p, const json& v) {
        if (v.is_number_integer()) uses[p] = v.get<std::int64_t>();
    };
    auto array = [](const json& o, const char* key) -> const json& {
        static const json empty = json::array();
        return o.is_object() && o.contains(key) && o[key].is_array() ? o[key] : empty;
    };
    const json& meshes = array(doc, "meshes");
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const json& prims = array(meshes[m], "primitives");
        for (std::size_t p = 0; p < prims.size(); ++p) {
            const json& prim = prims[p];
            if (!prim.is_object()) continue;
            const std::string at =
                "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p);
            if (prim.contains("attributes") && prim["attributes"].is_object())
                for (const auto& [k, v] : prim["attributes"].items())
                    add(at + "/attributes/" + scene::json_pointer_token(k), v);
            if (prim.contains("indices")) add(at + "/indices", prim["indices"]);
            const json& targets = array(prim, "targets");
            for (std::size_t t = 0; t < targets.size(); ++t)
                if (targets[t].is_object())
                    for (const auto& [k, v] : targets[t].items())
                        add(at + "/targets/" + std::to_string(t) + "/" +
                                scene::json_pointer_token(k),
                            v);
        }
    }
    const json& skins = array(doc, "skins");
    for (std::size_t s = 0; s < skins.size(); ++s)
        if (skins[s].is_object() && skins[s].contains("inverseBindMatrices"))
            add("/skins/" + std::to_string(s) + "/inverseBindMatrices",
                skins[s]["inverseBindMatrices"]);
    const json& animations = array(doc, "animations");
    for (std::size_t a = 0; a < animations.size(); ++a) {
        const json& samplers = array(animations[a], "samplers");
        for (std::size_t s = 0; s < samplers.size(); ++s)
            for (const char* key : {"input", "output"})
                if (samplers[s].is_object() && samplers[s].contains(key))
                    add("/animations/" + std::to_string(a) + "/samplers/" + std::to_string(s) +
                            "/" + key,
                        samplers[s][key]);
    }
    return uses;
}

const char* component_name(int type) {
    switch (type) {
    case 5120:
        return "BYTE";
    case 5121:
        return "UNSIGNED_BYTE";
    case 5122:
        return "SHORT";
    case 5123:
        return "UNSIGNED_SHORT";
    case 5125:
        return "UNSIGNED_INT";
    case 5126:
        return "FLOAT";
    default:
        return "unknown";
    }
}

// glTF's normalization of integer components (specification 3.11).
double normalized(double v, int type) {
    switch (type) {
    case 5120:
        return std::max(v / 127.0, -1.0);
    case 5121:
        return v / 255.0;
    case 5122:
        return std::max(v / 32767.0, -1.0);
    case 5123:
        return v / 65535.0;
    default:
        return v;
    }
}

struct Bounds {
    int type = 0;
    bool normalized = false;
    std::vector<double> min, max;
};

Bounds bounds_of(const json& accessor) {
    Bounds b;
    if (!accessor.is_object()) return b;
    b.type = accessor.value("componentType", 0);
    b.normalized = accessor.value("normalized", false);
    for (const char* key : {"min", "max"}) {
        if (!accessor.contains(key) || !accessor[key].is_array()) continue;
        auto& out = key[1] == 'i' ? b.min : b.max;
        for (const json& v : accessor[key])
            if (v.is_number())
                out.push_back(b.normalized ? normalized(v.get<double>(), b.type) : v.get<double>());
    }
    return b;
}

void accessor_drift(const json& a, const json& b, JsonDiff& out) {
    const auto uses_a = accessor_uses(a), uses_b = accessor_uses(b);
    static const json empty = json::array();
    const json& acc_a =
        a.contains("accessors") && a["accessors"].is_array() ? a["accessors"] : empty;
    const json& acc_b =
        b.contains("accessors") && b["accessors"].is_array() ? b["accessors"] : empty;
    for (const auto& [use, ia] : uses_a) {
        const auto it = uses_b.find(use);
        if (it == uses_b.end()) continue;
        const std::int64_t ib = it->second;
        if (ia < 0 || ib < 0 || std::size_t(ia) >= acc_a.size() || std::size_t(ib) >= acc_b.size())
            continue;
        const Bounds ba = bounds_of(acc_a[std::size_t(ia)]), bb = bounds_of(acc_b[std::size_t(ib)]);
        AccessorDrift d;
        d.use = use;
        d.accessor_a = ia;
        d.accessor_b = ib;
        d.min_a = ba.min, d.max_a = ba.max, d.min_b = bb.min, d.max_b = bb.max;
        if (ba.type != bb.type || ba.normalized != bb.normalized) {
            d.note = std::string("componentType ") + component_name(ba.type) +
                     (ba.normalized ? " normalized" : "") + " -> " + component_name(bb.type) +
                     (bb.normalized ? " normalized" : "");
            // Floats and normalized integers share a value space; plain integers
            // standing for floats (quantized, dequantized by a node transform) do not.
            const bool space_a = ba.type == 5126 || ba.normalized || ba.type == bb.type;
            const bool space_b = bb.type == 5126 || bb.normalized || ba.type == bb.type;
            if (!space_a || !space_b) {
                d.comparable = false;
                d.note += ": the bounds are in different value spaces (quantized)";
            }
        }
        const bool declared_a = !ba.min.empty() || !ba.max.empty();
        const bool declared_b = !bb.min.empty() || !bb.max.empty();
        if (declared_a != declared_b) {
            d.note += std::string(d.note.empty() ? "" : "; ") +
                      (declared_a ? "B declares no min/max" : "A declares no min/max");
            d.comparable = false;
        } else if (ba.min.size() != bb.min.size() || ba.max.size() != bb.max.size()) {
            d.note += std::string(d.note.empty() ? "" : "; ") + "min/max sizes differ";
            d.comparable = false;
        }
        if (d.comparable) {
            double extent = 0.0;
            for (std::size_t c = 0; c < ba.min.size(); ++c) {
                d.drift = std::max({d.drift, std::abs(ba.min[c] - bb.min[c])});
                if (c < ba.max.size()) extent = std::max(extent, ba.max[c] - ba.min[c]);
            }
            for (std::size_t c = 0; c < ba.max.size(); ++c)
                d.drift = std::max(d.drift, std::abs(ba.max[c] - bb.max[c]));
            d.relative = extent > 0.0 ? d.drift / extent : 0.0;
            if (d.drift == 0.0 && d.note.empty()) continue; // nothing moved
        }
        out.drift.push_back(std::move(d));
    }
}

} // namespace

std::string_view to_string(JsonChangeKind kind) {
    switch (kind) {
    case JsonChangeKind::Added:
        return "added";
    case JsonChangeKind::Removed:
        return "removed";
    case JsonChangeKind::Changed:
        return "changed";
    }
    return "changed";
}

JsonDiff json_diff(std::string_view json_a, std::string_view json_b) {
    JsonDiff out;
    const json a = json::parse(json_a, nullptr, false), b = json::parse(json_b, nullptr, false);
    if (!a.is_object() || !b.is_object()) {
        out.error = std::string(!a.is_object() ? "A" : "B") + " is not a JSON object";
        return out;
    }
    out.objects_a = count_objects(a);
    out.objects_b = count_objects(b);
    std::set<std::string> keys;
    for (const auto& [k, v] : a.items()) keys.insert(k);
    for (const auto& [k, v] : b.items()) keys.insert(k);
    for (const std::string& k : keys) {
        const std::string at = "/" + scene::json_pointer_token(k);
        static const json absent; // null: the property is not there
        const json& va = a.contains(k) ? a[k] : absent;
        const json& vb = b.contains(k) ? b[k] : absent;
        if ((is_object_array(va) || va.is_null() || (va.is_array() && va.empty())) &&
            (is_object_array(vb) || vb.is_null() || (vb.is_array() && vb.empty())) &&
            (is_object_array(va) || is_object_array(vb))) {
            diff_collection(at, va.is_array() ? va : json::array(),
                            vb.is_array() ? vb : json::array(), out);
            continue;
        }
        JsonChange c;
        c.pointer = at;
        if (va.is_null()) {
            c.kind = JsonChangeKind::Added;
        } else if (vb.is_null()) {
            c.kind = JsonChangeKind::Removed;
        } else if (va == vb) {
            ++out.unchanged;
            continue;
        } else if (va.is_array() && vb.is_array()) {
            diff_names(va, vb, c);
        } else {
            diff_leaves(va, vb, "", c);
        }
        out.changes.push_back(std::move(c));
    }
    accessor_drift(a, b, out);
    return out;
}

bool read_gltf_json(const std::string& path, std::string& text, std::string& error) {
    std::vector<std::uint8_t> bytes;
    if (!core::read_file(path, bytes, error)) return false;
    if (bytes.size() < 4 || std::memcmp(bytes.data(), "glTF", 4) != 0) {
        text.assign(bytes.begin(), bytes.end());
        return true;
    }
    auto le32 = [&](std::size_t at) {
        return std::uint32_t(bytes[at]) | std::uint32_t(bytes[at + 1]) << 8 |
               std::uint32_t(bytes[at + 2]) << 16 | std::uint32_t(bytes[at + 3]) << 24;
    };
    // Header (magic, version, length), then the first chunk: length, type "JSON".
    if (bytes.size() < 20 || le32(12 + 4) != 0x4E4F534Au) {
        error = path + ": GLB without a JSON chunk first";
        return false;
    }
    const std::uint64_t length = le32(12);
    if (20 + length > bytes.size()) {
        error = path + ": GLB JSON chunk (" + std::to_string(length) +
                " bytes) runs past the end of the file";
        return false;
    }
    text.assign(bytes.begin() + 20, bytes.begin() + 20 + static_cast<std::ptrdiff_t>(length));
    return true;
}

} // namespace sherpa::lab
