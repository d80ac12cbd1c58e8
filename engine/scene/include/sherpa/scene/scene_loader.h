#pragma once
// The one entry point that turns a scene spec (a path or `builtin:...`) into a Scene.
#include <memory>
#include <string>
#include <string_view>

#include <sherpa/scene/mesh_tangents.h>
#include <sherpa/scene/scene.h>

namespace sherpa {

struct LoadOptions {
    std::int32_t scene_index = -1; // -1: the file's default scene
    // Tangents after import: by default the glTF rule (generate with MikkTSpace where
    // TANGENT is absent and the material has a normal texture). Off: tangents stay as read.
    bool generate_tangents = true;
    SceneTangentOptions tangents;
};

// Either a scene or an error message naming the source and the problem. A failed
// load returns no partial scene.
struct LoadResult {
    std::unique_ptr<Scene> scene;
    std::string error;
    explicit operator bool() const { return scene != nullptr; }
};

LoadResult load_scene(std::string_view spec, const LoadOptions& options = {});
LoadResult import_gltf(const std::string& path, const LoadOptions& options = {});
// `builtin:default` or `builtin:grid?n=N`.
LoadResult make_builtin_scene(std::string_view spec);

} // namespace sherpa
