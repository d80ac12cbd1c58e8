#pragma once
// The glTF extensions Sherpa reads. One list for the importer (which refuses a file
// whose extensionsRequired names another, before anything else is looked at, so the
// user is told about the extension rather than a symptom of it) and for inspection
// (info --json reports every used/required extension with `supported`).
#include <span>
#include <string_view>

namespace sherpa {

// Extensions the importer decodes or honours, sorted by name.
std::span<const std::string_view> supported_gltf_extensions();

// True when `name` is one of supported_gltf_extensions().
bool is_supported_gltf_extension(std::string_view name);

} // namespace sherpa
