#pragma once
// Internal: bounds-checked decoding of glTF accessors (any component type,
// normalized or not, strided/interleaved, sparse) into floats or indices.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <sherpa/scene/scene.h>

namespace tinygltf {
class Model;
}

namespace sherpa::scene::detail {

// Decodes accessor `index` into `components` floats per element, applying glTF's
// normalisation rules and sparse substitution. `where` is the JSON path used in
// error messages (e.g. "meshes[0].primitives[1].attributes.POSITION").
// Throws ImportError if the accessor is out of range, has the wrong type
// (component count not in `allowed_components`), or reads past its buffer.
std::vector<float> read_accessor_floats(const tinygltf::Model& model, int index,
                                        std::initializer_list<std::uint32_t> allowed_components,
                                        std::uint32_t& components, const std::string& where);

// Decodes an index accessor (SCALAR of unsigned byte/short/int).
std::vector<std::uint32_t> read_accessor_indices(const tinygltf::Model& model, int index,
                                                 const std::string& where);

// The bytes of bufferView `view_index`, range-checked against its buffer.
std::span<const std::uint8_t> buffer_view_bytes(const tinygltf::Model& model, int view_index,
                                                const std::string& where);

// Describes where the accessor's data lives, for the inspection docks.
AccessorSource describe_accessor(const tinygltf::Model& model, int index);

// Number of elements, after validating the index only.
std::uint32_t accessor_count(const tinygltf::Model& model, int index, const std::string& where);

// The violation when the decoded `values` of accessor `index` leave the min/max it
// declares (compared after normalisation, with slack for exporters' rounding);
// nullopt when they fit or the accessor declares none.
std::optional<AccessorRangeViolation> check_declared_range(const tinygltf::Model& model, int index,
                                                           const std::vector<float>& values,
                                                           std::uint32_t components,
                                                           const std::string& where);
// One warning line for a violation.
std::string describe_range_violation(const AccessorRangeViolation& v);

// Components per element of an accessor type (SCALAR 1 .. VEC4 4); 0 for matrices,
// which are never vertex attributes or indices.
std::uint32_t type_components(int type);

} // namespace sherpa::scene::detail
