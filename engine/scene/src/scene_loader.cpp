#include <sherpa/scene/scene_loader.h>

namespace sherpa {

LoadResult load_scene(std::string_view spec, const LoadOptions& options) {
    if (spec.rfind("builtin:", 0) == 0) {
        LoadResult r = make_builtin_scene(spec);
        if (r && options.scene_index > 0) {
            std::string error;
            if (!select_scene(*r.scene, options.scene_index, error))
                return {nullptr, std::string(spec) + ": " + error};
        }
        return r;
    }
    return import_gltf(std::string(spec), options);
}

} // namespace sherpa
