#pragma once
// KHR_materials_variants: the file's named variants and, per primitive, the material
// each variant gives it. Choosing a variant changes only which material each engine
// mesh (and its instances) uses: geometry, textures and every other record stay.
// Everything a variant can show (its materials' textures, the vertex streams they
// read, tangents for their normal maps) is prepared at load, so a switch never
// reloads the file.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sherpa::scene {

struct Scene;

// One engine mesh that some variant maps to another material.
struct VariantMeshMapping {
    std::uint32_t mesh = 0;             // index into Scene::meshes
    std::uint32_t default_material = 0; // the primitive's own material (Scene::materials)
    // Per variant (Scene::variants.names order): its material, -1 where the variant
    // does not map this primitive (then the default material shows).
    std::vector<std::int32_t> materials;
    // The material `variant` gives this mesh (-1 or an unmapped variant: the default).
    std::uint32_t material_for(std::int32_t variant) const {
        return variant >= 0 && std::size_t(variant) < materials.size() &&
                       materials[std::size_t(variant)] >= 0
                   ? static_cast<std::uint32_t>(materials[std::size_t(variant)])
                   : default_material;
    }
};

struct MaterialVariants {
    std::vector<std::string> names;         // root extensions.KHR_materials_variants.variants
    std::vector<VariantMeshMapping> meshes; // ascending mesh index
    std::int32_t active = -1;               // the variant the scene shows now; -1: defaults
    bool empty() const { return names.empty(); }
};

// Index of the variant called `name`, -1 when the file has none of that name.
std::int32_t find_variant(const Scene& scene, std::string_view name);

// The material of engine mesh `mesh` under `variant` (-1: the default).
std::uint32_t variant_material(const Scene& scene, std::uint32_t mesh, std::int32_t variant);

// Every material engine mesh `mesh` can show: its default first, then each variant's
// (distinct, ascending). What streams, textures and tangents are prepared for.
std::vector<std::uint32_t> possible_materials(const Scene& scene, std::uint32_t mesh);

// One primitive whose material a variant changes.
struct VariantChange {
    std::uint32_t mesh = 0; // engine mesh
    std::uint32_t gltf_mesh = 0, primitive = 0;
    std::uint32_t from = 0, to = 0; // Scene::materials
};
// What `variant` changes against the defaults (-1: nothing), in mesh order.
std::vector<VariantChange> variant_changes(const Scene& scene, std::int32_t variant);

// Shows `variant` (-1: the defaults): sets each mapped mesh's material_id and its
// instances' material_id. Returns how many instances changed material. Precondition:
// variant < scene.variants.names.size().
std::uint32_t apply_material_variant(Scene& scene, std::int32_t variant);

} // namespace sherpa::scene
