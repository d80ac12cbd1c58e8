#include <sherpa/scene/mesh_tangents.h>
#include <sherpa/scene/scene_loader.h>

#include "load_stages.h"

namespace sherpa::scene {

std::string_view to_string(LoadStage stage) {
    switch (stage) {
    case LoadStage::Parse:
        return "parse";
    case LoadStage::Geometry:
        return "geometry";
    case LoadStage::Tangents:
        return "tangents";
    }
    return "?";
}

namespace detail {

bool begin_stage(const LoadOptions& options, LoadStage stage, std::size_t total) {
    if (core::is_cancelled(options.cancel)) return false;
    if (options.progress) options.progress(stage, 0, total);
    return true;
}

bool end_stage(const LoadOptions& options, LoadStage stage, std::size_t total) {
    if (options.progress) options.progress(stage, total, total);
    return !core::is_cancelled(options.cancel);
}

bool tangent_stage(Scene& scene, const LoadOptions& options) {
    const std::size_t meshes = scene.meshes.size();
    if (!begin_stage(options, LoadStage::Tangents, meshes)) return false;
    if (options.generate_tangents) {
        SceneTangentOptions tangents = options.tangents;
        if (options.progress)
            tangents.progress = [&options](std::size_t done, std::size_t total) {
                options.progress(LoadStage::Tangents, done, total);
            };
        tangents.cancel = options.cancel;
        add_tangent_warnings(scene, generate_scene_tangents(scene, tangents));
    }
    return end_stage(options, LoadStage::Tangents, meshes);
}

LoadResult cancelled_result() {
    LoadResult r;
    r.error = "cancelled";
    r.cancelled = true;
    return r;
}

} // namespace detail

LoadResult load_scene(std::string_view spec, const LoadOptions& options) {
    if (spec.rfind("builtin:", 0) == 0) {
        if (!detail::begin_stage(options, LoadStage::Geometry)) return detail::cancelled_result();
        LoadResult r = make_builtin_scene(spec);
        if (!r) return r;
        if (!detail::end_stage(options, LoadStage::Geometry)) return detail::cancelled_result();
        // Same tangent rule as for files: generated scenes carry normal maps too.
        if (!detail::tangent_stage(*r.scene, options)) return detail::cancelled_result();
        if (options.scene_index > 0) {
            std::string error;
            if (!select_scene(*r.scene, options.scene_index, error))
                return {nullptr, std::string(spec) + ": " + error};
        }
        return r;
    }
    return import_gltf(std::string(spec), options);
}

} // namespace sherpa::scene
