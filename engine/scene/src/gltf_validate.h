#pragma once
// Internal: checks on a glTF file's raw bytes and JSON before tinygltf parses it.
// tinygltf trusts too much: its recursive parser overflows the stack on deep
// nesting, it turns a negative or wrongly typed byteOffset into 0 (so a mesh reads
// the wrong bytes silently), and a PNG renamed .gltf reaches the user as the JSON
// library's raw exception. These checks refuse such files first, in words.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace sherpa::scene::detail {

// Deepest JSON nesting Sherpa parses. Real glTF files nest about 10 levels (extras
// a few more); tinygltf recurses per level and overflowed at ~20,000.
inline constexpr std::size_t kMaxJsonDepth = 256;

// Byte offset of the first bracket that nests deeper than `limit` in JSON text
// (strings skipped, escapes honoured, no recursion), or SIZE_MAX when none does.
std::size_t json_depth_exceeded_at(std::span<const std::uint8_t> text, std::size_t limit);

// The problem with a .gltf/.glb file's bytes, or an empty string when they may be
// handed to tinygltf. Never throws. Runs the steps below.
std::string validate_gltf_bytes(std::span<const std::uint8_t> bytes);

// What the parsed JSON forgets: nlohmann::json keeps object keys sorted, while the
// Khronos validator walks them in document order, and some of its messages depend on
// that order (of two accessors sharing a view without byteStride, the second one is
// named). The parse records the order where it matters: each mesh primitive's
// attribute names, as written (`attributes[m][p]`; empty where the file has none).
struct DocumentOrder {
    std::vector<std::vector<std::vector<std::string>>> attributes;
    // Whether any object has an "extensions" key (else no walk needs to look for one).
    bool has_extensions = false;
    // The names of /meshes/m/primitives/p/attributes in document order, or null.
    const std::vector<std::string>* attributes_of(std::size_t m, std::size_t p) const {
        return m < attributes.size() && p < attributes[m].size() ? &attributes[m][p] : nullptr;
    }
};

// Step 1: the container and the JSON (parsed into `root`: the importer's one parse of
// it, which the validator reads too; `order`, when given, receives the document order
// above from the same parse). `khronos_code`, when given, receives the Khronos
// validator's code for the problem where it has one (INVALID_JSON, ...).
std::string parse_gltf_document(std::span<const std::uint8_t> bytes, nlohmann::json& root,
                                std::string* khronos_code = nullptr,
                                DocumentOrder* order = nullptr);
// Step 1b: asset.version and extensionsRequired (after the validator has run, so a
// refused file still gets its Khronos messages).
std::string check_gltf_document(const nlohmann::json& root);
// Step 2: the properties whose values index memory or other arrays, which tinygltf
// would silently turn into 0 or -1 when mistyped.
std::string check_gltf_properties(const nlohmann::json& root);

} // namespace sherpa::scene::detail
