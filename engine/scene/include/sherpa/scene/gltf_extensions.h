#pragma once
// The glTF extensions Sherpa reads. One list for the importer (which refuses a file
// whose extensionsRequired names another, before anything else is looked at, so the
// user is told about the extension rather than a symptom of it) and for inspection
// (info --json reports every used/required extension with `supported`; info, render,
// the editor's log and its Validation dock warn about every used one that is not).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/scene/material.h>
#include <sherpa/scene/validation.h>

namespace sherpa::scene {

struct Scene;

// Extensions the importer decodes or honours, sorted by name.
std::span<const std::string_view> supported_gltf_extensions();

// True when `name` is one of supported_gltf_extensions().
bool is_supported_gltf_extension(std::string_view name);

// Codes of the warnings about what is not drawn (Sherpa's own: the Khronos
// validator's UNSUPPORTED_EXTENSION means "the validator cannot check it", which is
// another question, and it does not raise it for ratified extensions).
inline constexpr std::string_view kExtensionNotDrawnCode = "SHERPA_EXTENSION_NOT_DRAWN";
inline constexpr std::string_view kMaterialExtensionNotDrawnCode =
    "SHERPA_MATERIAL_EXTENSION_NOT_DRAWN";

// One name of the file's extensionsUsed, as Sherpa treats it.
struct ExtensionUse {
    std::string name;
    std::uint32_t used_index = 0;         // position in extensionsUsed
    bool required = false;                // also in extensionsRequired
    bool supported = false;               // is_supported_gltf_extension(name)
    std::vector<std::uint32_t> materials; // Scene::materials whose extensions name it
};
std::vector<ExtensionUse> extension_uses(const Scene& scene);

// The extensions a material names that Sherpa does not implement (it is drawn
// without them), in the material's order.
std::vector<std::string> unsupported_extensions(const MaterialInstance& material);

// One warning per unsupported name of extensionsUsed (/extensionsUsed/i) and one per
// material that names an unsupported extension (/materials/m/extensions/NAME), in
// that order: what the importer adds to Scene::validation.
std::vector<ValidationMessage> unsupported_extension_messages(const Scene& scene);

// The lines for Scene::warnings (info, render's stderr, the log): the text of each
// extensionsUsed message, and of each material message whose extension is not
// declared in extensionsUsed.
std::vector<std::string> unsupported_extension_warnings(const Scene& scene);

} // namespace sherpa::scene
