#include <sherpa/scene/material_extension_slots.h>

namespace sherpa::scene {

bool draws_material_extensions(const MaterialInstance& m) {
    return !m.unlit && !m.specular_glossiness;
}

std::vector<ExtensionTextureSlot> extension_texture_slots(const MaterialInstance& m) {
    std::vector<ExtensionTextureSlot> out;
    if (!draws_material_extensions(m)) return out;
    auto add = [&](const TextureSlot& slot, TextureRole role, const char* name) {
        if (slot.present()) out.push_back({&slot, role, name});
    };
    if (const auto& s = m.specular) {
        add(s->specular, kRoleLinear, "KHR_materials_specular.specularTexture");
        add(s->specular_color, kRoleColor, "KHR_materials_specular.specularColorTexture");
    }
    if (const auto& c = m.clearcoat) {
        add(c->clearcoat, kRoleLinear, "KHR_materials_clearcoat.clearcoatTexture");
        add(c->roughness, kRoleLinear, "KHR_materials_clearcoat.clearcoatRoughnessTexture");
        add(c->normal, kRoleNormal, "KHR_materials_clearcoat.clearcoatNormalTexture");
    }
    if (const auto& s = m.sheen) {
        add(s->color, kRoleColor, "KHR_materials_sheen.sheenColorTexture");
        add(s->roughness, kRoleLinear, "KHR_materials_sheen.sheenRoughnessTexture");
    }
    // The transmission family: factors in linear channels, the diffuse transmission
    // colour in sRGB.
    if (const auto& t = m.transmission)
        add(t->texture, kRoleLinear, "KHR_materials_transmission.transmissionTexture");
    if (const auto& v = m.volume)
        add(v->thickness, kRoleLinear, "KHR_materials_volume.thicknessTexture");
    if (const auto& d = m.diffuse_transmission) {
        add(d->texture, kRoleLinear,
            "KHR_materials_diffuse_transmission.diffuseTransmissionTexture");
        add(d->color, kRoleColor,
            "KHR_materials_diffuse_transmission.diffuseTransmissionColorTexture");
    }
    if (const auto& a = m.anisotropy)
        add(a->texture, kRoleLinear, "KHR_materials_anisotropy.anisotropyTexture");
    if (const auto& i = m.iridescence) {
        add(i->texture, kRoleLinear, "KHR_materials_iridescence.iridescenceTexture");
        add(i->thickness, kRoleLinear, "KHR_materials_iridescence.iridescenceThicknessTexture");
    }
    return out;
}

bool reads_normal_map(const MaterialInstance& m) {
    return m.normal.present() ||
           (draws_material_extensions(m) && m.clearcoat && m.clearcoat->normal.present());
}

bool draws_anisotropy(const MaterialInstance& m) {
    return draws_material_extensions(m) && m.anisotropy.has_value();
}

bool needs_tangents(const MaterialInstance& m) {
    return reads_normal_map(m) || draws_anisotropy(m);
}

std::uint32_t tangent_uv_set(const MaterialInstance& m) {
    if (m.normal.present()) return m.normal.tex_coord;
    if (draws_material_extensions(m) && m.clearcoat && m.clearcoat->normal.present())
        return m.clearcoat->normal.tex_coord;
    if (draws_anisotropy(m) && m.anisotropy->texture.present())
        return m.anisotropy->texture.tex_coord;
    return 0;
}

} // namespace sherpa::scene
