#pragma once
// Structural diff of two glTF documents by JSON pointer: which objects (elements of
// the top-level arrays, and the top-level properties) were added, removed or
// changed, with the fields that changed, and how far each accessor's declared
// min/max moved where both files use it for the same thing. Objects are matched by
// index (glTF has no object identity); accessors for the drift are matched by use
// (/meshes/m/primitives/p/attributes/POSITION in both files), since optimizers
// renumber them. What `sherpa-cli compare` prints as json_diff.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sherpa::lab {

enum class JsonChangeKind : std::uint8_t { Added, Removed, Changed };
std::string_view to_string(JsonChangeKind kind); // "added", "removed", "changed"

struct JsonChange {
    JsonChangeKind kind = JsonChangeKind::Changed;
    std::string pointer; // the object: "/materials/2", "/asset"
    // Changed: the differing leaves below it, "/pbrMetallicRoughness/roughnessFactor:
    // 0.5 -> 1" (the first kMaxFieldsPerChange; field_count counts them all).
    std::vector<std::string> fields;
    std::size_t field_count = 0;
};
inline constexpr std::size_t kMaxFieldsPerChange = 8;

// One use of an accessor in both files whose declared bounds differ. Values are
// in the accessor's value domain (normalized integers as their float values).
struct AccessorDrift {
    std::string use; // "/meshes/0/primitives/0/attributes/POSITION", "/skins/0/inverseBindMatrices"
    std::int64_t accessor_a = -1, accessor_b = -1;
    std::vector<double> min_a, max_a, min_b, max_b; // empty where a file declares none
    // False when the two accessors' values live in different spaces (a float accessor
    // quantized to unnormalized integers: the node transform dequantizes): no drift.
    bool comparable = true;
    double drift = 0.0;    // largest |a - b| over the min and max components
    double relative = 0.0; // drift / the largest extent (max - min) of A's components
    // Why the numbers are not comparable, or what else changed ("componentType FLOAT
    // -> UNSIGNED_SHORT: quantized, B's bounds are in its integer space").
    std::string note;
};

struct JsonDiff {
    std::vector<JsonChange> changes; // in document order: top-level arrays, then properties
    std::vector<AccessorDrift> drift;
    std::uint64_t objects_a = 0, objects_b = 0, unchanged = 0;
    std::string error; // set when a document is not a JSON object
};

// Both arguments are glTF JSON text.
JsonDiff json_diff(std::string_view json_a, std::string_view json_b);

// The JSON text of a .gltf file, or of a .glb's JSON chunk. False with `error`
// (naming the file) when the file cannot be read or is not a well-formed GLB.
bool read_gltf_json(const std::string& path, std::string& text, std::string& error);

} // namespace sherpa::lab
