#pragma once
// Internal: state shared by the importer stages while one glTF file is converted.
#include <string>

#include <sherpa/scene/scene.h>

namespace tinygltf {
class Model;
}

namespace sherpa::detail {

struct ImportContext {
    const tinygltf::Model& model;
    Scene& scene;
    std::int32_t default_material = -1; // created on first use

    void warn(std::string message) { scene.warnings.push_back(std::move(message)); }
    // Index of Sherpa's default material, appending it the first time it is needed.
    std::uint32_t default_material_id();
};

// Stages, in the order import_gltf() runs them. Each throws ImportError on bad input.
void import_samplers_images_textures(ImportContext& ctx);
void import_materials(ImportContext& ctx);
void import_meshes(ImportContext& ctx);
void import_lights_cameras(ImportContext& ctx);
void import_nodes_and_scenes(ImportContext& ctx);

} // namespace sherpa::detail
