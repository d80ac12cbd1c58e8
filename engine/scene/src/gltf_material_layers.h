#pragma once
// Internal: readers of the layered material extensions (KHR_materials_clearcoat, ...)
// over tinygltf's JSON values (read_value_slot: gltf_material_values.h). Each reader range-checks
// its values: a value out of range is a warning naming the JSON path and is clamped, a non-finite
// one (or not a number) is a warning and takes the extension's default (docs/materials.md, "Bad
// input").
#include "gltf_material_values.h"

namespace sherpa::scene::detail {

// `where` is the material's path ("materials[3]").
MaterialClearcoat read_clearcoat(ImportContext& ctx, const tinygltf::Value& e,
                                 const std::string& where);

MaterialSheen read_sheen(ImportContext& ctx, const tinygltf::Value& e, const std::string& where);

MaterialAnisotropy read_anisotropy(ImportContext& ctx, const tinygltf::Value& e,
                                   const std::string& where);

MaterialIridescence read_iridescence(ImportContext& ctx, const tinygltf::Value& e,
                                     const std::string& where);

} // namespace sherpa::scene::detail
