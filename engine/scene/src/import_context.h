#pragma once
// Internal: state shared by the importer stages while one glTF file is converted.
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/scene/scene.h>

namespace tinygltf {
class Model;
}

namespace sherpa::scene::detail {

struct ImportContext {
    ImportContext(const tinygltf::Model& m, Scene& s) : model(m), scene(s) {}
    const tinygltf::Model& model;
    Scene& scene;
    std::int32_t default_material = -1; // created on first use
    std::set<int> range_checked;        // accessors whose declared min/max were checked
    // Per accessor, whether the validator's data pass found every value inside its
    // declared min/max (Validation::bounds_hold): those are not scanned again.
    std::vector<std::uint8_t> bounds_hold;
    // Primitives a decoder could not read, (mesh, primitive) -> why: import_meshes skips
    // them by name.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> undecodable;
    // Lights and cameras skipped with a warning (an odd object does not refuse the
    // whole file): their records stay for the indices, nodes do not place them.
    std::vector<std::uint8_t> light_skipped, camera_skipped;
    // Non-unit normals renormalised, over the whole file: one warning at the end of
    // import_meshes (quantized normals are non-unit by design; a line per primitive
    // would flood the log).
    struct Renormalised {
        std::uint64_t normals = 0;
        std::uint32_t primitives = 0;
        float worst_length = 1.0f; // the length farthest from 1
        std::string worst_where;
    } renormalised;

    void warn(std::string message) { scene.warnings.push_back(std::move(message)); }
    // A part of the file that is not shown: a warning line and a `code` error message
    // in scene.validation with the JSON pointer `message` starts with.
    void skip(std::string_view code, const std::string& message);
    // Index of Sherpa's default material, appending it the first time it is needed.
    std::uint32_t default_material_id();
    // Compares accessor `index`'s decoded values with its declared min/max once per
    // accessor; a violation becomes a warning and a Scene::range_violations entry.
    void check_declared_range(int index, const std::vector<float>& values, std::uint32_t components,
                              const std::string& where);
};

// Stages, in the order import_gltf() runs them. Each throws ImportError on bad input.
void import_samplers_images_textures(ImportContext& ctx);
void import_materials(ImportContext& ctx);
void import_meshes(ImportContext& ctx);
// KHR_materials_variants: the root's names and each primitive's mappings (gltf_variants.cpp).
void import_material_variants(ImportContext& ctx);
void import_lights_cameras(ImportContext& ctx);
void import_nodes_and_scenes(ImportContext& ctx);
// EXT_mesh_gpu_instancing rows of each node (after nodes and skins; gltf_instancing.cpp).
void import_gpu_instancing(ImportContext& ctx);

} // namespace sherpa::scene::detail
