// The schema pass: property types, required properties, enumerations, ranges and
// references, for the glTF 2.0 core schema (the table: validate_schema_table.cpp), so
// each property is checked in one place; semantic checks live in the other passes.
#include "validate_internal.h"
#include "validate_schema_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <initializer_list>

namespace sherpa::scene::detail {
namespace {

using schema::Kind;
using schema::kind_named;
using schema::Prop;
using schema::T;

// Per element of `a`, whether an earlier element holds the same integer (sorted, so
// an array of 100k indices costs n log n, not n^2).
std::vector<std::uint8_t> duplicates(const Json& a) {
    std::vector<std::pair<std::int64_t, std::size_t>> values;
    values.reserve(a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        if (is_int(a[i])) values.emplace_back(as_int(a[i]), i);
    std::sort(values.begin(), values.end());
    std::vector<std::uint8_t> dup(a.size(), 0);
    for (std::size_t k = 1; k < values.size(); ++k)
        if (values[k].first == values[k - 1].first) dup[values[k].second] = 1;
    return dup;
}

std::string short_text(const Json& j) {
    std::string s = j.dump(-1, ' ', false, Json::error_handler_t::replace);
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

// Walks the document with one pointer string that grows and shrinks with the walk:
// a pointer is copied only when a message needs it, never built per property.
struct Schema {
    Validation& v;
    std::string at; // the JSON pointer of the value being checked
    // "SHERPA_" inside an extension the Khronos validator does not know (its codes
    // would claim what it never reports), "" elsewhere.
    const char* prefix = "";

    void add(const char* code, Severity s, const std::string& where, std::string message) {
        v.add(*prefix ? std::string(prefix) + code : std::string(code), s, where,
              std::move(message));
    }
    bool declared(std::string_view extension) const {
        for (const Json& e : v.array("extensionsUsed"))
            if (e.is_string() && e.get_ref<const std::string&>() == extension) return true;
        return false;
    }
    // A material's declared extensions with a schema (undeclared ones are the
    // extension pass's UNDECLARED_EXTENSION, and the Khronos validator reads no further).
    void material_extensions(const Json& extensions) {
        for (const auto& [name, value] : extensions.items()) {
            const Kind* kind = schema::material_extension_kind(name);
            if (!kind || !declared(name)) continue;
            const Scope member(at, name);
            if (!value.is_object()) {
                type_mismatch(value, "object");
                continue;
            }
            const char* outer = prefix;
            if (kind->sherpa_codes) prefix = "SHERPA_";
            object(value, kind);
            prefix = outer;
        }
    }

    // Appends "/key" or "/index" to `at` for the lifetime of the scope.
    struct Scope {
        std::string& s;
        std::size_t mark;
        Scope(std::string& str, std::string_view key) : s(str), mark(str.size()) {
            push_key(s, key);
        }
        Scope(std::string& str, std::size_t index) : s(str), mark(str.size()) {
            push_index(s, index);
        }
        ~Scope() { s.resize(mark); }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;
    };

    void type_mismatch(const Json& j, const char* want) {
        add("TYPE_MISMATCH", Severity::Error, at,
            "Type mismatch. Property value " + short_text(j) + " is not a '" + want + "'.");
    }
    void index(const Json& j, const char* target) {
        if (!j.is_number()) return type_mismatch(j, "integer");
        if (!is_int(j)) return type_mismatch(j, "integer");
        const std::int64_t i = as_int(j);
        if (i < 0) {
            add("INVALID_INDEX", Severity::Error, at, "Index must be a non-negative integer.");
            return;
        }
        if (target && static_cast<std::uint64_t>(i) >= v.size(target))
            add("UNRESOLVED_REFERENCE", Severity::Error, at,
                "Unresolved reference: " + std::to_string(i) + ".");
    }
    void number(const Json& j, const Prop& pr) {
        if (!j.is_number()) return type_mismatch(j, "number");
        const double x = j.get<double>();
        if (pr.zero_ok && x == 0) return;
        if (x < pr.lo || x > pr.hi || (pr.open && x == pr.lo))
            add("VALUE_NOT_IN_RANGE", Severity::Error, at,
                "Value " + short_text(j) + " is out of range.");
    }
    void property(const Json& j, const Prop& pr) {
        switch (pr.type) {
        case T::Index:
            index(j, pr.target);
            break;
        case T::IndexArray: {
            if (!j.is_array()) return type_mismatch(j, "array");
            if (j.empty()) add("EMPTY_ENTITY", Severity::Error, at, "Entity cannot be empty.");
            const std::vector<std::uint8_t> dup = duplicates(j);
            const std::size_t size = pr.target ? v.size(pr.target) : SIZE_MAX;
            for (std::size_t i = 0; i < j.size(); ++i) {
                // The usual element, a resolved index seen once, needs no pointer.
                if (!dup[i] && j[i].is_number_unsigned() && j[i].get<std::uint64_t>() < size)
                    continue;
                const Scope element(at, i);
                index(j[i], pr.target);
                if (dup[i]) add("DUPLICATE_ELEMENTS", Severity::Error, at, "Duplicate element.");
            }
            break;
        }
        case T::Int:
            if (!j.is_number() || !is_int(j)) return type_mismatch(j, "integer");
            if (static_cast<double>(as_int(j)) < pr.lo || static_cast<double>(as_int(j)) > pr.hi)
                add("VALUE_NOT_IN_RANGE", Severity::Error, at,
                    "Value " + short_text(j) + " is out of range.");
            break;
        case T::Num:
            number(j, pr);
            break;
        case T::NumArray: {
            if (!j.is_array()) return type_mismatch(j, "array");
            bool length_ok = pr.lengths.size() == 0;
            for (int n : pr.lengths) length_ok |= j.size() == static_cast<std::size_t>(n);
            if (!length_ok) {
                add("ARRAY_LENGTH_NOT_IN_LIST", Severity::Error, at,
                    "Invalid array length " + std::to_string(j.size()) + ".");
                return;
            }
            if (j.empty()) add("EMPTY_ENTITY", Severity::Error, at, "Entity cannot be empty.");
            for (std::size_t i = 0; i < j.size(); ++i) {
                if (j[i].is_number() && pr.lo == -INFINITY && pr.hi == INFINITY) continue;
                const Scope element(at, i);
                if (!j[i].is_number()) {
                    add("ARRAY_TYPE_MISMATCH", Severity::Error, at,
                        "Type mismatch. Array element " + short_text(j[i]) + " is not a 'number'.");
                    continue;
                }
                number(j[i], pr);
            }
            break;
        }
        case T::Str:
            if (!j.is_string()) type_mismatch(j, "string");
            break;
        case T::Bool:
            if (!j.is_boolean()) type_mismatch(j, "boolean");
            break;
        case T::Obj:
            if (!j.is_object()) return type_mismatch(j, "object");
            object(j, pr.target);
            break;
        case T::ObjArr: {
            if (!j.is_array()) return type_mismatch(j, "array");
            if (j.empty()) add("EMPTY_ENTITY", Severity::Error, at, "Entity cannot be empty.");
            const Kind* kind = kind_of(pr.target);
            for (std::size_t i = 0; i < j.size(); ++i) {
                const Scope element(at, i);
                if (!j[i].is_object())
                    type_mismatch(j[i], "object");
                else
                    object(j[i], kind);
            }
            break;
        }
        case T::IntEnum: {
            if (!j.is_number() || !is_int(j)) return type_mismatch(j, "integer");
            bool ok = false;
            for (int x : pr.lengths) ok |= as_int(j) == x;
            if (!ok)
                add("VALUE_NOT_IN_LIST", Severity::Warning, at,
                    "Invalid value " + short_text(j) + ".");
            break;
        }
        case T::StrEnum: {
            if (!j.is_string()) return type_mismatch(j, "string");
            bool ok = false;
            for (const char* w : pr.words) ok |= j.get_ref<const std::string&>() == w;
            if (!ok)
                add("VALUE_NOT_IN_LIST", Severity::Warning, at,
                    "Invalid value " + short_text(j) + ".");
            break;
        }
        case T::Any:
            break;
        }
    }
    // kind_named's answers so far, by the name's address (the table's literals): a
    // nested object's kind was a string search over the table per object.
    struct CachedKind {
        const char* name = nullptr;
        const Kind* kind = nullptr;
    };
    std::array<CachedKind, 16> kinds{};
    std::size_t cached_kinds = 0;
    const Kind* kind_of(const char* name) {
        for (std::size_t i = 0; i < cached_kinds; ++i)
            if (kinds[i].name == name) return kinds[i].kind;
        const Kind* kind = kind_named(name);
        if (cached_kinds < kinds.size()) kinds[cached_kinds++] = {name, kind};
        return kind;
    }

    void object(const Json& obj, const char* kind_name) { object(obj, kind_of(kind_name)); }
    void object(const Json& obj, const Kind* kind) {
        if (!kind) return;
        const bool root = std::strcmp(kind->name, "root") == 0;
        std::size_t required_seen = 0; // each required property is some key's at most once
        for (const auto& [key, value] : obj.items()) {
            const Prop* found = nullptr;
            for (const Prop& pr : kind->props)
                if (key == pr.name) found = &pr; // lengths first, then the bytes
            if (found) {
                required_seen += found->required;
                const Scope member(at, key);
                property(value, *found);
            } else if (key == "extensions") {
                const Scope member(at, key);
                if (!value.is_object())
                    type_mismatch(value, "object");
                else if (std::strcmp(kind->name, "material") == 0)
                    material_extensions(value);
            } else if (key == "extras") {
                const Scope member(at, key);
                if (!value.is_object())
                    add("NON_OBJECT_EXTRAS", Severity::Information, at,
                        "Prefer JSON Objects for extras.");
            } else if (key == "name" && !root) {
                const Scope member(at, key);
                if (!value.is_string()) type_mismatch(value, "string");
            } else {
                const Scope member(at, key);
                add("UNEXPECTED_PROPERTY", Severity::Warning, at, "Unexpected property.");
            }
        }
        std::size_t required = 0;
        for (const Prop& pr : kind->props) required += pr.required;
        if (required_seen == required) return; // no look-up per required property
        for (const Prop& pr : kind->props)
            if (pr.required && !obj.contains(pr.name))
                add("UNDEFINED_PROPERTY", Severity::Error, at,
                    "Property '" + std::string(pr.name) + "' must be defined.");
    }
};

// asset.version and minVersion: "major.minor", 2.x.
void check_version(Validation& v) {
    const auto asset = v.root.find("asset");
    if (asset == v.root.end() || !asset->is_object()) return;
    auto parse = [](const Json& j, int& major, int& minor) {
        if (!j.is_string()) return false;
        const std::string& s = j.get_ref<const std::string&>();
        const auto dot = s.find('.');
        auto digits = [](std::string_view t) {
            if (t.empty() || t.size() > 9 || (t.size() > 1 && t[0] == '0')) return false;
            for (char c : t)
                if (c < '0' || c > '9') return false;
            return true;
        };
        if (dot == std::string::npos || !digits(std::string_view(s).substr(0, dot)) ||
            !digits(std::string_view(s).substr(dot + 1)))
            return false;
        major = std::stoi(s.substr(0, dot));
        minor = std::stoi(s.substr(dot + 1));
        return true;
    };
    int major = 2, minor = 0;
    const auto version = asset->find("version");
    if (version != asset->end() && version->is_string()) {
        if (!parse(*version, major, minor)) {
            v.add("PATTERN_MISMATCH", Severity::Error, "/asset/version",
                  "Value " + short_text(*version) +
                      " does not match regexp pattern '^([0-9]+)\\.([0-9]+)$'.");
        } else if (major != 2) {
            v.add("UNKNOWN_ASSET_MAJOR_VERSION", Severity::Error, "/asset/version",
                  "Unknown glTF major asset version: " + std::to_string(major) + ".");
        } else if (minor > 0) {
            v.add("UNKNOWN_ASSET_MINOR_VERSION", Severity::Warning, "/asset/version",
                  "Unknown glTF minor asset version: " + std::to_string(minor) + ".");
        }
    }
    const auto min_version = asset->find("minVersion");
    int min_major = 0, min_minor = 0;
    if (min_version == asset->end() || !min_version->is_string()) return;
    if (!parse(*min_version, min_major, min_minor)) {
        v.add("PATTERN_MISMATCH", Severity::Error, "/asset/minVersion",
              "Value " + short_text(*min_version) +
                  " does not match regexp pattern '^([0-9]+)\\.([0-9]+)$'.");
    } else if (min_major > major || (min_major == major && min_minor > minor)) {
        v.add("ASSET_MIN_VERSION_GREATER_THAN_VERSION", Severity::Error, "/asset/minVersion",
              "Asset minVersion " + short_text(*min_version) + " is greater than version.");
    }
}

} // namespace

void validate_schema(Validation& v) {
    Schema{v, {}}.object(v.root, "root");
    check_version(v);
}

} // namespace sherpa::scene::detail
