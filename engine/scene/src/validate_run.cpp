// The validator's shared helpers, the extension checks and the entry point over the
// JSON document (see validate_internal.h).
#include "validate_internal.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace sherpa::scene::detail {
namespace {

// Escapes a key for a JSON pointer (RFC 6901: "~" -> "~0", "/" -> "~1").
void append_key(std::string& out, std::string_view key) {
    bool plain = true; // (find_first_of("~/") calls memchr once per character)
    for (char c : key) plain &= c != '~' && c != '/';
    if (plain) {
        out.append(key); // the usual key: one copy
        return;
    }
    for (char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
}

// Extensions the Khronos validator knows, with the objects each may extend.
struct KnownExtension {
    std::string_view name;
    std::array<std::string_view, 2> kinds;
};
constexpr KnownExtension kKnown[] = {
    {"KHR_animation_pointer", {"target", ""}},
    {"KHR_lights_punctual", {"root", "node"}},
    {"KHR_materials_anisotropy", {"material", ""}},
    {"KHR_materials_clearcoat", {"material", ""}},
    {"KHR_materials_dispersion", {"material", ""}},
    {"KHR_materials_emissive_strength", {"material", ""}},
    {"KHR_materials_ior", {"material", ""}},
    {"KHR_materials_iridescence", {"material", ""}},
    {"KHR_materials_pbrSpecularGlossiness", {"material", ""}},
    {"KHR_materials_sheen", {"material", ""}},
    {"KHR_materials_specular", {"material", ""}},
    {"KHR_materials_transmission", {"material", ""}},
    {"KHR_materials_unlit", {"material", ""}},
    {"KHR_materials_variants", {"root", "primitive"}},
    {"KHR_materials_volume", {"material", ""}},
    {"KHR_mesh_quantization", {"", ""}},
    {"KHR_texture_transform", {"textureInfo", ""}},
    {"EXT_texture_webp", {"texture", ""}},
};
const KnownExtension* known(std::string_view name) {
    for (const auto& k : kKnown)
        if (k.name == name) return &k;
    return nullptr;
}

bool valid_extension_name(std::string_view s) {
    const auto us = s.find('_');
    if (us == std::string_view::npos || us == 0 || us + 1 == s.size()) return false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        const bool upper_digit = (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (i < us ? !upper_digit : !(upper_digit || (c >= 'a' && c <= 'z') || c == '_'))
            return false;
    }
    return true;
}

// The kind of object at a pointer, for where an extension may appear.
std::string_view kind_at(const std::vector<std::string_view>& seg) {
    const std::size_t n = seg.size();
    if (n == 0) return "root";
    if (n == 2) {
        if (seg[0] == "materials") return "material";
        if (seg[0] == "nodes") return "node";
        if (seg[0] == "textures") return "texture";
    }
    if (n == 4 && seg[0] == "meshes" && seg[2] == "primitives") return "primitive";
    if (n == 5 && seg[0] == "animations" && seg[2] == "channels" && seg[4] == "target")
        return "target";
    if (seg[0] == "materials" && n >= 3 && seg.back().ends_with("Texture")) return "textureInfo";
    return "other";
}

struct ExtensionWalk {
    Validation& v;
    std::vector<std::string> used;
    std::vector<std::string_view> segments;
    std::string pointer;

    void check(const Json& extensions) {
        for (const auto& [name, value] : extensions.items()) {
            std::string p = pointer + "/extensions/";
            append_key(p, name);
            if (std::find(used.begin(), used.end(), name) == used.end()) {
                v.add("UNDECLARED_EXTENSION", Severity::Error, p,
                      "Extension is not declared in extensionsUsed.");
                continue;
            }
            if (const KnownExtension* k = known(name)) {
                const std::string_view kind = kind_at(segments);
                if (k->kinds[0] != kind && k->kinds[1] != kind)
                    v.add("UNEXPECTED_EXTENSION_OBJECT", Severity::Error, p,
                          "Unexpected location for this extension.");
            }
        }
    }
    void walk(const Json& j, std::size_t depth) {
        if (depth > 64) return;
        if (j.is_object()) {
            for (const auto& [key, value] : j.items()) {
                if (key == "extras") continue;
                if (key == "extensions" && value.is_object()) {
                    check(value);
                    continue; // extension contents belong to each extension
                }
                if (!value.is_structured()) continue;
                const std::size_t mark = pointer.size();
                push_key(pointer, key);
                segments.push_back(key);
                walk(value, depth + 1);
                segments.pop_back();
                pointer.resize(mark);
            }
        } else if (j.is_array()) {
            for (std::size_t i = 0; i < j.size(); ++i) {
                if (!j[i].is_structured()) continue;
                const std::size_t mark = pointer.size();
                push_index(pointer, i);
                segments.push_back("#"); // kind_at looks at keys, never at array indices
                walk(j[i], depth + 1);
                segments.pop_back();
                pointer.resize(mark);
            }
        }
    }
};

} // namespace

void push_key(std::string& pointer, std::string_view key) {
    pointer += '/';
    append_key(pointer, key);
}

void push_index(std::string& pointer, std::size_t index) {
    char digits[24];
    const auto end = std::to_chars(digits, digits + sizeof digits, index).ptr;
    pointer += '/';
    pointer.append(digits, end);
}

std::string ptr(std::string_view base, std::string_view key) {
    std::string out(base);
    out += '/';
    append_key(out, key);
    return out;
}

std::string ptr(std::string_view base, std::size_t index) {
    return std::string(base) + '/' + std::to_string(index);
}

void Validation::add(std::string_view code, Severity s, std::string pointer, std::string message) {
    if (report.messages.size() >= kMaxValidationMessages) {
        report.truncated = true;
        return;
    }
    report.messages.push_back({std::string(code), std::move(message), std::move(pointer), s});
}

namespace {
const char* role_name(AccessorRole r) {
    constexpr const char* kNames[] = {"",    "VertexAttribute", "PrimitiveIndices",
                                      "IBM", "AnimationInput",  "AnimationOutput"};
    return kNames[static_cast<int>(r)];
}
const char* role_name(ViewRole r) {
    constexpr const char* kNames[] = {"", "VertexBuffer", "IndexBuffer", "IBM", "Image", "Other"};
    return kNames[static_cast<int>(r)];
}
} // namespace

void Validation::use_view(std::int64_t view, ViewRole role, const std::string& pointer) {
    if (view < 0 || static_cast<std::size_t>(view) >= view_roles.size()) return;
    ViewRole& was = view_roles[static_cast<std::size_t>(view)];
    if (was == ViewRole::None)
        was = role;
    else if (was != role)
        add("BUFFER_VIEW_TARGET_OVERRIDE", Severity::Error, pointer,
            std::string("Override of previously set bufferView target or usage. Initial: '") +
                role_name(was) + "', new: '" + role_name(role) + "'.");
}

void Validation::use_accessor(std::int64_t a, AccessorRole role, ViewRole view_role,
                              const std::string& pointer) {
    if (a < 0 || static_cast<std::size_t>(a) >= accessor_roles.size()) return;
    AccessorRole& was = accessor_roles[static_cast<std::size_t>(a)];
    if (was == AccessorRole::None)
        was = role;
    else if (was != role)
        add("ACCESSOR_USAGE_OVERRIDE", Severity::Error, pointer,
            std::string("Override of previously set accessor usage. Initial: '") + role_name(was) +
                "', new: '" + role_name(role) + "'.");
    // declared_accessors is sized with accessor_roles (validate_buffers.cpp).
    use_view(declared_accessors[static_cast<std::size_t>(a)].view, view_role, pointer);
}

const Json& Validation::array(const char* key) const {
    // The passes ask for the same few arrays once per object they check (an index's
    // target, per node of a 100k-node file): a map look-up each time was a fifth of the
    // validator's time there.
    for (std::size_t i = 0; i < cached_arrays; ++i)
        if (arrays[i].key == key) return *arrays[i].array;
    static const Json empty = Json::array();
    const auto it = root.find(key);
    const Json& found = it != root.end() && it->is_array() ? *it : empty;
    if (cached_arrays < arrays.size()) arrays[cached_arrays++] = {key, &found};
    return found;
}

const Json& Validation::member(const Json& obj, const char* key) {
    static const Json null;
    if (!obj.is_object()) return null;
    const auto it = obj.find(key);
    return it != obj.end() ? *it : null;
}

const Json& Validation::member(const Json& a, std::size_t i) {
    static const Json empty = Json::object();
    return a.is_array() && i < a.size() && a[i].is_object() ? a[i] : empty;
}

bool is_int(const Json& j) {
    if (j.is_number_integer()) return true;
    if (!j.is_number_float()) return false;
    const double x = j.get<double>();
    return std::isfinite(x) && x == std::floor(x) && std::abs(x) < 9007199254740992.0;
}

std::int64_t as_int(const Json& j) {
    if (j.is_number_unsigned())
        return static_cast<std::int64_t>(
            std::min<std::uint64_t>(j.get<std::uint64_t>(), INT64_MAX));
    if (j.is_number_integer()) return j.get<std::int64_t>();
    return is_int(j) ? static_cast<std::int64_t>(j.get<double>()) : -1;
}

std::int64_t int_or(const Json& obj, const char* key, std::int64_t fallback) {
    if (!obj.is_object()) return fallback;
    const auto it = obj.find(key);
    return it != obj.end() && is_int(*it) ? as_int(*it) : fallback;
}

std::int64_t ref(const Validation& v, const Json& obj, const char* key, const char* target) {
    const std::int64_t i = int_or(obj, key, -1);
    return i >= 0 && static_cast<std::uint64_t>(i) < v.size(target) ? i : -1;
}

std::uint32_t components_of(std::string_view t) {
    if (t == "SCALAR") return 1;
    if (t == "VEC2") return 2;
    if (t == "VEC3") return 3;
    if (t == "VEC4" || t == "MAT2") return 4;
    if (t == "MAT3") return 9;
    if (t == "MAT4") return 16;
    return 0;
}

std::uint32_t component_size(std::int64_t ct) {
    switch (ct) {
    case 5120:
    case 5121:
        return 1;
    case 5122:
    case 5123:
        return 2;
    case 5125:
    case 5126:
        return 4;
    default:
        return 0;
    }
}

void validate_document(Validation& v) {
    validate_schema(v);
    validate_extensions(v);
    validate_buffers(v);
    validate_meshes(v);
    validate_nodes(v);
    validate_animations(v);
    validate_materials(v);
    validate_unused(v);
}

void validate_extensions(Validation& v) {
    ExtensionWalk walk{v, {}, {}, {}};
    // The walk over every object is skipped where the parse saw no "extensions" key.
    const bool walk_document = !v.order || v.order->has_extensions;
    const Json& used = v.array("extensionsUsed");
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (!used[i].is_string()) {
            v.add("ARRAY_TYPE_MISMATCH", Severity::Error, ptr("/extensionsUsed", i),
                  "Type mismatch. Array element is not a 'string'.");
            continue;
        }
        const std::string& name = used[i].get_ref<const std::string&>();
        if (std::find(walk.used.begin(), walk.used.end(), name) != walk.used.end()) {
            v.add("DUPLICATE_ELEMENTS", Severity::Error, ptr("/extensionsUsed", i),
                  "Duplicate element.");
            continue;
        }
        walk.used.push_back(name);
        if (!valid_extension_name(name))
            v.add("INVALID_EXTENSION_NAME_FORMAT", Severity::Warning, ptr("/extensionsUsed", i),
                  "Extension name has invalid format.");
        if (!known(name))
            v.add("UNSUPPORTED_EXTENSION", Severity::Information, ptr("/extensionsUsed", i),
                  "Cannot validate an extension as it is not supported by the validator: '" + name +
                      "'.");
    }
    const Json& required = v.array("extensionsRequired");
    bool quantization_required = false;
    for (std::size_t i = 0; i < required.size(); ++i) {
        if (!required[i].is_string()) continue;
        const std::string& name = required[i].get_ref<const std::string&>();
        quantization_required |= name == "KHR_mesh_quantization";
        if (std::find(walk.used.begin(), walk.used.end(), name) == walk.used.end())
            v.add("UNUSED_EXTENSION_REQUIRED", Severity::Error, ptr("/extensionsRequired", i),
                  "Unused extension '" + name + "' cannot be required.");
    }
    for (std::size_t i = 0; i < walk.used.size(); ++i)
        if (walk.used[i] == "KHR_mesh_quantization" && !quantization_required)
            v.add("NON_REQUIRED_EXTENSION", Severity::Error, ptr("/extensionsUsed", i),
                  "Extension 'KHR_mesh_quantization' cannot be optional.");
    if (walk_document) walk.walk(v.root, 0);
}

} // namespace sherpa::scene::detail
