// Which images the displayed scene's materials use, and in which roles.
#include <sherpa/scene/material_extension_slots.h>
#include <sherpa/texture/texture_pipeline.h>

#include <algorithm>
#include <map>
#include <set>

namespace sherpa::tex {

std::string_view role_name(scene::TextureRole role) {
    switch (role) {
    case scene::kRoleNormal:
        return "normal";
    case scene::kRoleLinear:
        return "linear";
    default:
        return "color";
    }
}

std::string_view to_string(CacheState state) {
    switch (state) {
    case CacheState::Hit:
        return "hit";
    case CacheState::Miss:
        return "miss";
    case CacheState::Stale:
        return "stale";
    case CacheState::Recompressed:
        return "recompressed";
    case CacheState::Fallback:
        return "fallback";
    case CacheState::Missing:
        return "missing";
    case CacheState::Undecodable:
        return "undecodable";
    }
    return "miss";
}

std::vector<TextureUse> collect_texture_uses(const scene::Scene& scene) {
    std::set<std::uint32_t> used_materials;
    // Every material an instance can show (KHR_materials_variants included): a variant
    // switch then finds its textures on the GPU.
    for (const scene::MeshInstance& inst : scene.instances) {
        used_materials.insert(inst.material_id); // the instance's own, with or without a mesh
        for (std::uint32_t m : scene::possible_materials(scene, inst.mesh_id))
            used_materials.insert(m);
    }
    std::map<std::pair<std::int32_t, int>, TextureUse> uses;
    std::map<std::pair<std::int32_t, int>, std::set<float>> cutoffs; // of masked materials
    auto add = [&](const scene::TextureSlot& slot, scene::TextureRole role,
                   std::optional<float> cutoff) {
        if (!slot.present() || std::size_t(slot.texture) >= scene.textures.size()) return;
        const std::int32_t image = scene.textures[std::size_t(slot.texture)].image;
        if (image < 0 || std::size_t(image) >= scene.images.size()) return;
        TextureUse& use = uses[{image, int(role)}];
        use.image = image, use.role = role;
        if (std::find(use.textures.begin(), use.textures.end(), slot.texture) == use.textures.end())
            use.textures.push_back(slot.texture);
        if (cutoff) cutoffs[{image, int(role)}].insert(*cutoff);
    };
    for (std::uint32_t id : used_materials) {
        if (id >= scene.materials.size()) continue;
        const scene::MaterialInstance& m = scene.materials[id];
        const auto cutoff = m.alpha_mode == scene::AlphaMode::Mask
                                ? std::optional<float>(m.alpha_cutoff)
                                : std::nullopt;
        add(m.base_color, scene::kRoleColor, cutoff);
        add(m.emissive, scene::kRoleColor, std::nullopt);
        add(m.metallic_roughness, scene::kRoleLinear, std::nullopt);
        add(m.occlusion, scene::kRoleLinear, std::nullopt);
        add(m.normal, scene::kRoleNormal, std::nullopt);
        // Specular is sRGB colour and glossiness linear alpha: an sRGB format
        // decodes exactly that.
        if (m.specular_glossiness)
            add(m.specular_glossiness->specular_glossiness, scene::kRoleColor, std::nullopt);
        // The extensions' slots where they are drawn (material_extension_slots.h).
        for (const scene::ExtensionTextureSlot& e : scene::extension_texture_slots(m))
            add(*e.slot, e.role, std::nullopt);
    }
    std::vector<TextureUse> out;
    for (auto& [key, use] : uses) {
        // Coverage is kept for one cutoff only: scaling the mips' alpha for one cutoff
        // shifts the others (AlphaBlendModeTest masks one image at 0.25, 0.5 and 0.75;
        // kept for 0.25, the 0.75 panel vanished at a distance). Several different
        // cutoffs on one image get plain filtering.
        if (auto it = cutoffs.find(key); it != cutoffs.end() && it->second.size() == 1)
            use.alpha_cutoff = *it->second.begin();
        out.push_back(std::move(use));
    }
    return out;
}

std::int32_t PreparedTextureSet::find(std::int32_t texture, scene::TextureRole role) const {
    for (std::size_t i = 0; i < textures.size(); ++i)
        if (textures[i].role == role &&
            std::find(textures[i].textures.begin(), textures[i].textures.end(), texture) !=
                textures[i].textures.end())
            return static_cast<std::int32_t>(i);
    return -1;
}

scene::GPUMaterialData resolve_material(const scene::MaterialInstance& material,
                                        const PreparedTextureSet& set,
                                        std::span<const std::uint32_t> bindless_slot) {
    scene::GPUMaterialData gpu = scene::to_gpu_material(material);
    auto slot = [&](const scene::TextureSlot& s, scene::TextureRole role) {
        const std::int32_t i = s.present() ? set.find(s.texture, role) : -1;
        if (i < 0 || std::size_t(i) >= bindless_slot.size() || set.textures[std::size_t(i)].failed)
            return scene::kTextureSentinel;
        return bindless_slot[std::size_t(i)];
    };
    gpu.base_color_tex = slot(material.base_color, scene::kRoleColor);
    gpu.emissive_tex = slot(material.emissive, scene::kRoleColor);
    gpu.metallic_roughness_tex = slot(material.metallic_roughness, scene::kRoleLinear);
    gpu.occlusion_tex = slot(material.occlusion, scene::kRoleLinear);
    gpu.normal_tex = slot(material.normal, scene::kRoleNormal);
    return gpu;
}

} // namespace sherpa::tex
