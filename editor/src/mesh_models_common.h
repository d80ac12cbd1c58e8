#pragma once
// What the mesh dock's models share: the scene kept alive while shown and the
// mesh they read from.
#include <memory>

#include <sherpa/scene/scene.h>

namespace sherpa::editor {

struct MeshRef {
    std::shared_ptr<const scene::Scene> scene; // keeps the data alive across a scene swap
    int mesh = -1;
    const scene::Mesh* get() const {
        return scene && mesh >= 0 && static_cast<std::size_t>(mesh) < scene->meshes.size()
                   ? &scene->meshes[static_cast<std::size_t>(mesh)]
                   : nullptr;
    }
};

} // namespace sherpa::editor
