#pragma once
// The one entry point that turns a scene spec (a path or `builtin:...`) into a Scene.
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include <sherpa/core/progress.h>
#include <sherpa/scene/mesh_tangents.h>
#include <sherpa/scene/scene.h>
#include <sherpa/scene/validation.h>

namespace sherpa::scene {

// Stages of load_scene, in order (builtin scenes skip Parse).
enum class LoadStage { Parse, Geometry, Tangents };
std::string_view to_string(LoadStage stage); // parse, geometry, tangents

struct LoadOptions {
    std::int32_t scene_index = -1; // -1: the file's default scene
    // Tangents after import: by default the glTF rule (generate with MikkTSpace where
    // TANGENT is absent and the material has a normal texture). Off: tangents stay as read.
    bool generate_tangents = true;
    SceneTangentOptions tangents;
    // Called on the loading thread when a stage starts (done 0) and ends (done ==
    // total); tangents also report per mesh.
    std::function<void(LoadStage stage, std::size_t done, std::size_t total)> progress;
    // Polled between stages and between meshes of the tangent stage: a cancelled
    // load returns no scene, `cancelled` set and error "cancelled".
    const core::CancelToken* cancel = nullptr;
};

// Either a scene or an error message naming the source and the problem. A failed
// load returns no partial scene.
struct LoadResult {
    std::unique_ptr<Scene> scene;
    std::string error;
    // When the file is refused: what the validator found before the refusal, ending
    // with a SHERPA_LOAD_REFUSED error that carries `error`. (A loaded scene carries
    // its report in Scene::validation.)
    ValidationReport validation{};
    bool cancelled = false;
    explicit operator bool() const { return scene != nullptr; }
};

LoadResult load_scene(std::string_view spec, const LoadOptions& options = {});
LoadResult import_gltf(const std::string& path, const LoadOptions& options = {});
// `builtin:default` or `builtin:grid?n=N`.
LoadResult make_builtin_scene(std::string_view spec);

} // namespace sherpa::scene
