#include <sherpa/render/material_extensions.h>

#include <sherpa/scene/material_extension_slots.h>

#include <cmath>
#include <cstring>

namespace sherpa::render {

GPUTextureTransform texture_transform(const scene::TextureSlot& slot) {
    const glm::mat3 m = slot.transform.present ? slot.transform.matrix() : glm::mat3(1.0f);
    // Rows of the 2x3 affine part (glm is column-major: m[column][row]); row0.w is the
    // TEXCOORD set.
    return {glm::vec4(m[0][0], m[1][0], m[2][0], float(slot.tex_coord)),
            glm::vec4(m[0][1], m[1][1], m[2][1], 0.0f)};
}

namespace {

// Appends a block (a whole number of 16-byte words) and returns its first word.
template <typename Block> std::uint32_t append(std::vector<glm::uvec4>& words, const Block& b) {
    static_assert(sizeof(Block) % kExtensionWordBytes == 0);
    const std::size_t first = words.size();
    words.resize(first + sizeof(Block) / kExtensionWordBytes);
    std::memcpy(&words[first], &b, sizeof(Block));
    return static_cast<std::uint32_t>(first);
}

// The transmission family's blocks of a shaded material (each only where it uses it).
void append_transmission_blocks(std::vector<glm::uvec4>& words, const scene::MaterialInstance& m,
                                MaterialExtensionPlace& place,
                                const ExtensionTextureSlot& texture_slot) {
    if (const auto& t = m.transmission) {
        GPUTransmissionBlock b{};
        b.factor = t->factor;
        b.texture = texture_slot(t->texture, scene::kRoleLinear);
        b.uv = texture_transform(t->texture);
        place.transmission = append(words, b);
    }
    if (const auto& v = m.volume) {
        GPUVolumeBlock b{};
        b.attenuation = glm::vec4(v->attenuation_color, v->attenuation_distance);
        b.thickness_factor = v->thickness_factor;
        b.thickness_tex = texture_slot(v->thickness, scene::kRoleLinear);
        b.thickness_uv = texture_transform(v->thickness);
        place.volume = append(words, b);
    }
    if (const auto& d = m.diffuse_transmission) {
        GPUDiffuseTransmissionBlock b{};
        b.color_factor = glm::vec4(d->color_factor, d->factor);
        b.texture = texture_slot(d->texture, scene::kRoleLinear);
        b.color_tex = texture_slot(d->color, scene::kRoleColor);
        b.uv = texture_transform(d->texture);
        b.color_uv = texture_transform(d->color);
        place.diffuse_transmission = append(words, b);
    }
    if (m.dispersion) place.dispersion = append(words, GPUDispersionBlock{*m.dispersion, 0, 0, 0});
}

} // namespace

MaterialExtensionBuffer
build_material_extensions(std::span<const scene::MaterialInstance> materials,
                          const ExtensionTextureSlot& texture_slot) {
    MaterialExtensionBuffer out;
    out.places.resize(materials.size());
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const scene::MaterialInstance& m = materials[i];
        // Specular-glossiness materials have no dielectric F0 to change; unlit ones no BRDF.
        if (!scene::draws_material_extensions(m)) continue;
        const bool ior = m.ior.has_value();
        const bool specular = m.specular.has_value();
        const bool clearcoat = m.clearcoat.has_value();
        const bool sheen = m.sheen.has_value();
        const bool transmission = m.transmission.has_value();
        if (!ior && !specular && !clearcoat && !sheen && !transmission && !m.volume &&
            !m.diffuse_transmission && !m.dispersion && !m.anisotropy && !m.iridescence)
            continue;
        MaterialExtensionPlace& place = out.places[i];
        GPUExtensionIndex index{};
        place.index = append(out.words, index); // written once the blocks are placed
        if (ior) place.ior = append(out.words, GPUIorBlock{*m.ior, 0.0f, 0.0f, 0.0f});
        if (specular) {
            const scene::MaterialSpecular& s = *m.specular;
            GPUSpecularBlock b{};
            b.color_factor = glm::vec4(s.specular_color_factor, s.specular_factor);
            b.specular_tex = texture_slot(s.specular, scene::kRoleLinear);
            b.specular_color_tex = texture_slot(s.specular_color, scene::kRoleColor);
            b.specular_uv = texture_transform(s.specular);
            b.color_uv = texture_transform(s.specular_color);
            place.specular = append(out.words, b);
        }
        if (clearcoat) {
            const scene::MaterialClearcoat& c = *m.clearcoat;
            GPUClearcoatBlock b{};
            b.factors = glm::vec4(c.factor, c.roughness_factor, c.normal_scale, 0.0f);
            b.clearcoat_tex = texture_slot(c.clearcoat, scene::kRoleLinear);
            b.roughness_tex = texture_slot(c.roughness, scene::kRoleLinear);
            b.normal_tex = texture_slot(c.normal, scene::kRoleNormal);
            b.clearcoat_uv = texture_transform(c.clearcoat);
            b.roughness_uv = texture_transform(c.roughness);
            b.normal_uv = texture_transform(c.normal);
            place.clearcoat = append(out.words, b);
        }
        if (sheen) {
            const scene::MaterialSheen& sh = *m.sheen;
            GPUSheenBlock b{};
            b.factors = glm::vec4(sh.color_factor, sh.roughness_factor);
            b.color_tex = texture_slot(sh.color, scene::kRoleColor);
            b.roughness_tex = texture_slot(sh.roughness, scene::kRoleLinear);
            b.color_uv = texture_transform(sh.color);
            b.roughness_uv = texture_transform(sh.roughness);
            place.sheen = append(out.words, b);
        }
        append_transmission_blocks(out.words, m, place, texture_slot);
        if (const auto& a = m.anisotropy) {
            GPUAnisotropyBlock b{};
            b.factors = glm::vec4(a->strength, std::cos(a->rotation), std::sin(a->rotation), 0.0f);
            b.texture = texture_slot(a->texture, scene::kRoleLinear);
            b.uv = texture_transform(a->texture);
            place.anisotropy = append(out.words, b);
            ++out.anisotropic_materials;
        }
        if (const auto& ir = m.iridescence) {
            GPUIridescenceBlock b{};
            b.factors =
                glm::vec4(ir->factor, ir->ior, ir->thickness_minimum, ir->thickness_maximum);
            b.texture = texture_slot(ir->texture, scene::kRoleLinear);
            b.thickness_tex = texture_slot(ir->thickness, scene::kRoleLinear);
            b.uv = texture_transform(ir->texture);
            b.thickness_uv = texture_transform(ir->thickness);
            place.iridescence = append(out.words, b);
        }
        if (transmission && m.transmission->factor > 0.0f) ++out.transmissive_materials;
        index = GPUExtensionIndex{place.ior,
                                  place.specular,
                                  place.clearcoat,
                                  place.sheen,
                                  place.transmission,
                                  place.volume,
                                  place.diffuse_transmission,
                                  place.dispersion,
                                  place.anisotropy,
                                  place.iridescence,
                                  0,
                                  0};
        std::memcpy(&out.words[place.index], &index, sizeof index);
    }
    return out;
}

} // namespace sherpa::render
