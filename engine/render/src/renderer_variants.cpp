// KHR_materials_variants inside the renderer: a switch gives the mapped meshes their
// variant's material through switch_mesh_materials() (draw groups, instance material
// words, the ray tracer's geometry records); an alpha-mode or sidedness change rebuilds
// the culling's per-group lists (and, where a geometry built opaque now needs any-hit,
// the TLAS with that instance flag), and shadows are redrawn (masked casters read the
// material). Nothing is reloaded and no BLAS is rebuilt.
#include "frame_recorder.h"
#include "scene_changes.h"

#include <stdexcept>

namespace sherpa::render {

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
    for (const scene::VariantMeshMapping& m : state.variants.meshes)
        meshes.emplace_back(m.mesh, m.material_for(variant));
    const MaterialSwitch changed = switch_mesh_materials(*state.gpu, meshes);
    if (changed.modes_changed) {
        culling.build(*scene);
        culling.set_hidden(state.hidden_instances(), *scene);
    }
    shadows_.invalidate();
    if (acceleration) {
        // The ray tracer's geometry records follow (retire_culling() waited for the
        // frames in flight, so no ray-traced frame reads them).
        const auto rt = acceleration->follow_materials(*state.gpu);
        out.rt_records = rt.records;
        out.rt_gpu_bytes = rt.gpu_bytes;
        out.rt_forced_blas = rt.forced_blas;
        out.rt_unculled_blas = rt.unculled_blas;
        out.tlas_rebuilt = rt.tlas_rebuilt;
        // The rebuilt TLAS holds the loaded transforms: the frame's pose goes in again.
        if (rt.tlas_rebuilt) state.rt_pose_generation = 0;
    }
    ++state.material_generation; // the path tracer's accumulation starts over
    state.variant = variant;
    out.meshes = changed.meshes;
    out.instances = changed.instances;
    out.gpu_bytes = changed.gpu_bytes;
    out.culling_rebuilt = changed.modes_changed;
    return out;
}

} // namespace sherpa::render
