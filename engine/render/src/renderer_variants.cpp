// KHR_materials_variants inside the renderer: a switch gives the mapped meshes their
// variant's material through switch_mesh_materials() (draw groups, instance material
// words); an alpha-mode or sidedness change rebuilds the culling's per-group lists,
// and shadows are redrawn (masked casters read the material). Nothing is reloaded.
#include "renderer_impl.h"

#include <stdexcept>

namespace sherpa::gpu {

void Renderer::Impl::load_variants(const Scene& source) {
    variants_ = source.variants;
    loaded_variant_ = variant_ = source.variants.active;
}

VariantSwitch set_material_variant(Renderer& renderer, std::int32_t variant) {
    return renderer.impl_->set_variant(variant);
}

VariantSwitch Renderer::Impl::set_variant(std::int32_t variant) {
    Renderer::Impl& r = *this;
    if (variant < -1 || (variant >= 0 && std::size_t(variant) >= r.variants_.names.size()))
        throw std::out_of_range("material variant " + std::to_string(variant) + " of " +
                                std::to_string(r.variants_.names.size()));
    VariantSwitch out;
    out.variant = variant;
    if (!r.scene || variant == r.variant_) {
        r.variant_ = variant;
        return out;
    }
    // Frames in flight draw with the groups being changed: wait, keeping their
    // statistics in the history.
    for (auto& s : r.slots_) {
        r.wait_slot(*s);
        if (s->has_results && !s->history_pushed) {
            FrameStats unused;
            r.culling.read_stats(*s, r.scene.get(), unused);
        }
        s->culling.count = 0;
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> meshes;
    for (const VariantMeshMapping& m : r.variants_.meshes)
        meshes.emplace_back(m.mesh, m.material_for(variant));
    const MaterialSwitch changed = switch_mesh_materials(*r.scene, meshes);
    if (changed.modes_changed) {
        r.culling.build(*r.scene);
        r.culling.set_hidden(r.hidden_instances(), *r.scene);
    }
    r.shadows_.invalidate();
    r.variant_ = variant;
    out.meshes = changed.meshes;
    out.instances = changed.instances;
    out.gpu_bytes = changed.gpu_bytes;
    out.culling_rebuilt = changed.modes_changed;
    return out;
}

} // namespace sherpa::gpu
