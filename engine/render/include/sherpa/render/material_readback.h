#pragma once
// A material record read back from the loaded scene's GPU material array, with the
// bindless slots inverted to the scene textures they hold: what the GPU really
// shades with (the editor's material dock shows it next to the glTF values).
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/scene/material.h>

namespace sherpa::scene {
struct Scene;
} // namespace sherpa::scene

namespace sherpa::render {

class Renderer;

struct MaterialReadback {
    scene::GPUMaterialData record{};
    std::vector<int> bindless_to_texture; // bindless slot -> scene texture, -1: none
    // The material's words of the extension buffer as the GPU holds them: its
    // GPUExtensionIndex, then its blocks (word offsets in the index are from the
    // buffer's start: subtract extension_first). Empty where it has none.
    std::vector<glm::uvec4> extension_words;
    std::uint32_t extension_first = 0;
};

// Material `material` of `scene`, the scene the renderer has loaded; nullopt when
// nothing is loaded or the index is out of range. Waits for one copy on the GPU.
std::optional<MaterialReadback> read_material(Renderer& renderer, const scene::Scene& scene,
                                              int material);

} // namespace sherpa::render
