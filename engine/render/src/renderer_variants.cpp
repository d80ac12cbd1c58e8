// KHR_materials_variants inside the renderer: a switch gives the mapped meshes their
// variant's material through switch_mesh_materials() (draw groups, instance material
// words); an alpha-mode or sidedness change rebuilds the culling's per-group lists,
// and shadows are redrawn (masked casters read the material). Nothing is reloaded.
#include "frame_recorder.h"
#include "scene_changes.h"

#include <stdexcept>

namespace sherpa::gpu {

VariantSwitch set_material_variant(Renderer& renderer, std::int32_t variant) {
    return renderer.frames().changes().set_variant(variant);
}

VariantSwitch SceneChanges::set_variant(std::int32_t variant) {
    if (variant < -1 || (variant >= 0 && std::size_t(variant) >= state.variants.names.size()))
        throw std::out_of_range("material variant " + std::to_string(variant) + " of " +
                                std::to_string(state.variants.names.size()));
    VariantSwitch out;
    out.variant = variant;
    if (!scene || variant == state.variant) {
        state.variant = variant;
        return out;
    }
    // Frames in flight draw with the groups being changed.
    retire_culling();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> meshes;
    for (const VariantMeshMapping& m : state.variants.meshes)
        meshes.emplace_back(m.mesh, m.material_for(variant));
    const MaterialSwitch changed = switch_mesh_materials(*state.gpu, meshes);
    if (changed.modes_changed) {
        culling.build(*scene);
        culling.set_hidden(state.hidden_instances(), *scene);
    }
    shadows_.invalidate();
    state.variant = variant;
    out.meshes = changed.meshes;
    out.instances = changed.instances;
    out.gpu_bytes = changed.gpu_bytes;
    out.culling_rebuilt = changed.modes_changed;
    return out;
}

} // namespace sherpa::gpu
