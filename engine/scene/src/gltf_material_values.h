#pragma once
// Internal: the importer's readers of values inside a material's extension objects
// (tinygltf leaves those as JSON values), shared by gltf_materials.cpp and the files
// that read one family of material extensions each.
#include "import_context.h"

#include <string>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {

// A textureInfo inside an extension object; an absent one is an empty slot.
TextureSlot read_value_slot(ImportContext& ctx, const tinygltf::Value& info,
                            const std::string& where, TextureRole role);
// `n` numbers of an array at `key`, or `fallback` when absent or malformed.
glm::vec4 vec_or(const tinygltf::Value& obj, const char* key, glm::vec4 fallback, int n);

// KHR_materials_transmission, _volume, _diffuse_transmission and _dispersion of material
// `m` (gltf_materials_volume.cpp): each read, range-checked with a warning naming the
// property and its fallback, and set on `m` when the material uses it.
void read_volume_extensions(ImportContext& ctx, const tinygltf::ExtensionMap& extensions,
                            MaterialInstance& m, const std::string& where);

} // namespace sherpa::scene::detail
