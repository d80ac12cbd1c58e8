#include "gltf_primitives.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include <sherpa/scene/scene_loader.h>

namespace sherpa::tools {

std::vector<GltfPrimitive> read_gltf_primitives(const std::string& path) {
    scene::LoadOptions options;
    options.generate_tangents = false; // the file's data only
    scene::LoadResult loaded = scene::load_scene(path, options);
    if (!loaded) throw std::runtime_error(loaded.error);
    const scene::Scene& scene = *loaded.scene;
    std::vector<GltfPrimitive> out;
    auto has = [](const scene::Mesh& m, scene::VertexAttribute a) {
        return m.provenance_of(a) == scene::Provenance::Authored;
    };
    for (const scene::Mesh& mesh : scene.meshes) {
        GltfPrimitive g;
        g.mesh = mesh.group_id;
        g.primitive = mesh.primitive_index;
        if (mesh.material_id < scene.materials.size()) {
            const scene::TextureSlot& normal = scene.materials[mesh.material_id].normal;
            g.has_normal_texture = normal.present();
            if (g.has_normal_texture) g.tex_coord = normal.tex_coord;
        }
        const scene::VertexAttribute uv_set = g.tex_coord == 1 ? scene::VertexAttribute::TexCoord1
                                                               : scene::VertexAttribute::TexCoord0;
        for (const scene::Vertex& v : mesh.vertices) {
            g.positions.push_back(v.position);
            if (has(mesh, scene::VertexAttribute::Normal)) g.normals.push_back(v.normal);
            if (has(mesh, uv_set) && g.tex_coord <= 1)
                g.uvs.push_back(g.tex_coord == 1 ? v.uv1 : v.uv0);
            if (has(mesh, scene::VertexAttribute::Tangent)) g.tangents.push_back(v.tangent);
        }
        g.indices = mesh.indices;
        out.push_back(std::move(g));
    }
    return out;
}

std::vector<std::string> sample_models(const std::string& assets_dir) {
    std::vector<std::string> names;
    const std::filesystem::path root = std::filesystem::path(assets_dir) / "gltf";
    if (!std::filesystem::is_directory(root)) return names;
    for (const auto& entry : std::filesystem::directory_iterator(root)) {
        const std::string name = entry.path().filename().string();
        if (std::filesystem::exists(sample_model_path(assets_dir, name))) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string sample_model_path(const std::string& assets_dir, const std::string& name) {
    return assets_dir + "/gltf/" + name + "/glTF/" + name + ".gltf";
}

} // namespace sherpa::tools
