#pragma once
// Internal: the one mechanism that checks glTF properties in the raw JSON, before
// tinygltf reads them. tinygltf keeps integers in `int`, so 2^32 arrives as 0 and a
// later range check passes; a string or 0.5 arrives as 0 or -1. Every property that
// indexes memory or another array is therefore checked here, from nlohmann's exact
// value, and a bad one is refused with its JSON path ("accessors[3].byteOffset: ...").
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace sherpa::scene::detail {

inline constexpr std::uint64_t kMaxSafe = (std::uint64_t{1} << 53) - 1; // JSON's exact integers
inline constexpr std::uint64_t kMaxIndex = 0x7FFFFFFF;                  // what tinygltf's int holds

// A JSON value as it appears in a message, cut to 40 characters.
inline std::string describe(const nlohmann::json& v) {
    std::string s = v.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace);
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

using json = nlohmann::json;

// Raw JSON property checks: the properties whose values index memory or other
// arrays, which tinygltf would silently turn into 0 or -1 when mistyped.
struct Checker {
    std::string error;

    // JSON value `v` at `path` as an integer in [lo, hi].
    std::optional<std::uint64_t> value(const json& v, const std::string& path, std::uint64_t lo,
                                       std::uint64_t hi) {
        if (!error.empty()) return std::nullopt;
        if (!v.is_number_unsigned()) { // nlohmann stores every integer >= 0 as unsigned
            error = path + ": " + describe(v) + " is not a non-negative integer";
            return std::nullopt;
        }
        const std::uint64_t x = v.get<std::uint64_t>();
        if (x < lo || x > hi) {
            error = path + ": " + std::to_string(x) + " is out of the range " + std::to_string(lo) +
                    ".." + std::to_string(hi);
            return std::nullopt;
        }
        return x;
    }
    // An optional (or required) integer property in [lo, hi].
    std::optional<std::uint64_t> uint(const json& obj, const char* key, const std::string& where,
                                      std::uint64_t lo, std::uint64_t hi, bool required = false) {
        if (!error.empty() || !obj.is_object()) return std::nullopt;
        const auto it = obj.find(key);
        if (it != obj.end()) return value(*it, where + "." + key, lo, hi);
        if (required) error = where + "." + key + ": required property is missing";
        return std::nullopt;
    }
    std::optional<std::uint64_t> index(const json& obj, const char* key, const std::string& where,
                                       bool required = false) {
        return uint(obj, key, where, 0, kMaxIndex, required);
    }
    void index_array(const json& obj, const char* key, const std::string& where) {
        if (!error.empty() || !obj.is_object() || !obj.contains(key)) return;
        const json& a = obj[key];
        if (!a.is_array()) {
            error = where + "." + key + ": is not an array";
            return;
        }
        for (std::size_t i = 0; i < a.size(); ++i)
            value(a[i], where + "." + key + "[" + std::to_string(i) + "]", 0, kMaxIndex);
    }
    // Each element of top-level array `key`, with its JSON path.
    template <typename F> void each(const json& root, const char* key, F&& f) {
        if (!error.empty() || !root.contains(key)) return;
        const json& a = root[key];
        if (!a.is_array()) {
            error = std::string(key) + ": is not an array";
            return;
        }
        for (std::size_t i = 0; i < a.size() && error.empty(); ++i) {
            const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
            if (!a[i].is_object())
                error = where + ": is not a JSON object";
            else
                f(a[i], where);
        }
    }
};

// The properties of the extensions Sherpa reads (meshopt streams and fallback
// buffers, Draco streams, texture image extensions, every material textureInfo),
// checked like the core ones: the problem with its JSON path, or "".
std::string check_extension_properties(const nlohmann::json& root);

} // namespace sherpa::scene::detail
