#pragma once
// Internal: readers of the layered material extensions (KHR_materials_clearcoat, ...)
// over tinygltf's JSON values, and the texture-slot reader they share with
// gltf_materials.cpp. Each reader range-checks its values: a value out of range is a
// warning naming the JSON path and is clamped, a non-finite one (or not a number) is
// a warning and takes the extension's default (docs/materials.md, "Bad input").
#include "import_context.h"

#include <string>

#include <tiny_gltf.h>

namespace sherpa::detail {

// A textureInfo inside an extension object (tinygltf leaves those as JSON values).
TextureSlot read_value_slot(ImportContext& ctx, const tinygltf::Value& info,
                            const std::string& where, TextureRole role);

// `where` is the material's path ("materials[3]").
MaterialClearcoat read_clearcoat(ImportContext& ctx, const tinygltf::Value& e,
                                 const std::string& where);

MaterialSheen read_sheen(ImportContext& ctx, const tinygltf::Value& e, const std::string& where);

} // namespace sherpa::detail
