#include <sherpa/scene/material_variants.h>

#include <algorithm>

#include <sherpa/scene/scene.h>

namespace sherpa::scene {
namespace {

const VariantMeshMapping* mapping_of(const Scene& scene, std::uint32_t mesh) {
    const auto& all = scene.variants.meshes;
    const auto it =
        std::lower_bound(all.begin(), all.end(), mesh,
                         [](const VariantMeshMapping& m, std::uint32_t v) { return m.mesh < v; });
    return it != all.end() && it->mesh == mesh ? &*it : nullptr;
}

} // namespace

std::int32_t find_variant(const Scene& scene, std::string_view name) {
    const auto& names = scene.variants.names;
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<std::int32_t>(it - names.begin());
}

std::uint32_t variant_material(const Scene& scene, std::uint32_t mesh, std::int32_t variant) {
    const VariantMeshMapping* m = mapping_of(scene, mesh);
    if (!m) return mesh < scene.meshes.size() ? scene.meshes[mesh].material_id : 0;
    return m->material_for(variant);
}

std::vector<std::uint32_t> possible_materials(const Scene& scene, std::uint32_t mesh) {
    const VariantMeshMapping* m = mapping_of(scene, mesh);
    if (!m) return {mesh < scene.meshes.size() ? scene.meshes[mesh].material_id : 0};
    std::vector<std::uint32_t> out;
    for (std::int32_t v : m->materials)
        if (v >= 0 && std::uint32_t(v) != m->default_material) out.push_back(std::uint32_t(v));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    out.insert(out.begin(), m->default_material);
    return out;
}

std::vector<VariantChange> variant_changes(const Scene& scene, std::int32_t variant) {
    std::vector<VariantChange> out;
    for (const VariantMeshMapping& m : scene.variants.meshes) {
        const std::uint32_t to = variant_material(scene, m.mesh, variant);
        if (to == m.default_material) continue;
        const Mesh& mesh = scene.meshes[m.mesh];
        out.push_back({m.mesh, mesh.group_id, mesh.primitive_index, m.default_material, to});
    }
    return out;
}

std::uint32_t apply_material_variant(Scene& scene, std::int32_t variant) {
    scene.variants.active = variant;
    for (const VariantMeshMapping& m : scene.variants.meshes)
        scene.meshes[m.mesh].material_id = variant_material(scene, m.mesh, variant);
    std::uint32_t changed = 0;
    for (MeshInstance& inst : scene.instances) {
        if (inst.mesh_id >= scene.meshes.size()) continue;
        const std::uint32_t material = scene.meshes[inst.mesh_id].material_id;
        changed += inst.material_id != material;
        inst.material_id = material;
    }
    return changed;
}

} // namespace sherpa::scene
