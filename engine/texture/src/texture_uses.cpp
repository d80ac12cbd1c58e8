// Which images the displayed scene's materials use, and in which roles.
#include <sherpa/texture/texture_pipeline.h>

#include <algorithm>
#include <map>
#include <set>

namespace sherpa::tex {

std::string_view role_name(TextureRole role) {
    switch (role) {
    case kRoleNormal:
        return "normal";
    case kRoleLinear:
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

std::vector<TextureUse> collect_texture_uses(const Scene& scene) {
    std::set<std::uint32_t> used_materials;
    // Every material an instance can show (KHR_materials_variants included): a variant
    // switch then finds its textures on the GPU.
    for (const MeshInstance& inst : scene.instances) {
        used_materials.insert(inst.material_id); // the instance's own, with or without a mesh
        for (std::uint32_t m : possible_materials(scene, inst.mesh_id)) used_materials.insert(m);
    }
    std::map<std::pair<std::int32_t, int>, TextureUse> uses;
    std::map<std::pair<std::int32_t, int>, std::set<float>> cutoffs; // of masked materials
    auto add = [&](const TextureSlot& slot, TextureRole role, std::optional<float> cutoff) {
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
        const MaterialInstance& m = scene.materials[id];
        const auto cutoff =
            m.alpha_mode == AlphaMode::Mask ? std::optional<float>(m.alpha_cutoff) : std::nullopt;
        add(m.base_color, kRoleColor, cutoff);
        add(m.emissive, kRoleColor, std::nullopt);
        add(m.metallic_roughness, kRoleLinear, std::nullopt);
        add(m.occlusion, kRoleLinear, std::nullopt);
        add(m.normal, kRoleNormal, std::nullopt);
        // Specular is sRGB colour and glossiness linear alpha: an sRGB format
        // decodes exactly that.
        if (m.specular_glossiness)
            add(m.specular_glossiness->specular_glossiness, kRoleColor, std::nullopt);
        // KHR_materials_specular, where it is drawn (as gpu::build_material_extensions
        // decides: not on unlit or specular-glossiness materials): the weight in a
        // linear alpha, the colour in sRGB.
        if (m.specular && !m.unlit && !m.specular_glossiness) {
            add(m.specular->specular, kRoleLinear, std::nullopt);
            add(m.specular->specular_color, kRoleColor, std::nullopt);
        }
        // The transmission family, on the same materials: factors in linear channels,
        // the diffuse transmission colour in sRGB.
        if (!m.unlit && !m.specular_glossiness) {
            if (m.transmission) add(m.transmission->texture, kRoleLinear, std::nullopt);
            if (m.volume) add(m.volume->thickness, kRoleLinear, std::nullopt);
            if (m.diffuse_transmission) {
                add(m.diffuse_transmission->texture, kRoleLinear, std::nullopt);
                add(m.diffuse_transmission->color, kRoleColor, std::nullopt);
            }
        }
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

std::int32_t PreparedTextureSet::find(std::int32_t texture, TextureRole role) const {
    for (std::size_t i = 0; i < textures.size(); ++i)
        if (textures[i].role == role &&
            std::find(textures[i].textures.begin(), textures[i].textures.end(), texture) !=
                textures[i].textures.end())
            return static_cast<std::int32_t>(i);
    return -1;
}

GPUMaterialData resolve_material(const MaterialInstance& material, const PreparedTextureSet& set,
                                 std::span<const std::uint32_t> bindless_slot) {
    GPUMaterialData gpu = to_gpu_material(material);
    auto slot = [&](const TextureSlot& s, TextureRole role) {
        const std::int32_t i = s.present() ? set.find(s.texture, role) : -1;
        if (i < 0 || std::size_t(i) >= bindless_slot.size() || set.textures[std::size_t(i)].failed)
            return kTextureSentinel;
        return bindless_slot[std::size_t(i)];
    };
    gpu.base_color_tex = slot(material.base_color, kRoleColor);
    gpu.emissive_tex = slot(material.emissive, kRoleColor);
    gpu.metallic_roughness_tex = slot(material.metallic_roughness, kRoleLinear);
    gpu.occlusion_tex = slot(material.occlusion, kRoleLinear);
    gpu.normal_tex = slot(material.normal, kRoleNormal);
    return gpu;
}

} // namespace sherpa::tex
