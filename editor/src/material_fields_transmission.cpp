// The material dock's rows of the transmission family (KHR_materials_transmission,
// _volume, _diffuse_transmission, _dispersion): each field of the material's blocks
// with its byte offset in the extension buffer, values from the CPU record.
#include "material_fields_model.h"

#include <cstddef>
#include <limits>

#include "format_values.h"

#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/material_extensions.h>

namespace sherpa::editor {

void MaterialFieldsModel::appendTransmissionRows(const render::MaterialExtensionPlace& place,
                                                 const scene::MaterialInstance& m) {
    const int word = int(render::kExtensionWordBytes);
    auto words = [](std::uint32_t w) {
        return w == render::kNoExtension ? tr("absent") : QString::number(w);
    };
    auto texture = [this](const scene::TextureSlot& slot) {
        return slot.present() ? chain(slot.texture) : tr("default texture");
    };
    auto add = [&](std::uint32_t block, std::size_t offset, const char* field, const char* property,
                   const char* type, const QString& value,
                   const scene::TextureSlot* slot = nullptr) {
        extension_rows_.push_back({int(block) * word + int(offset), QString::fromLatin1(field),
                                   QString::fromLatin1(property), QString::fromLatin1(type), value,
                                   slot && slot->present() ? slot->texture : -1});
    };
    if (place.transmission == render::kNoExtension && place.volume == render::kNoExtension &&
        place.diffuse_transmission == render::kNoExtension &&
        place.dispersion == render::kNoExtension)
        return;
    add(place.index, offsetof(render::GPUExtensionIndex, transmission), "ext.index.transmission",
        "GPUExtensionIndex word 1", "uvec4",
        tr("transmission %1, volume %2, diffuse transmission %3, dispersion %4")
            .arg(words(place.transmission), words(place.volume), words(place.diffuse_transmission),
                 words(place.dispersion)));
    if (const auto& t = m.transmission; t && place.transmission != render::kNoExtension) {
        add(place.transmission, offsetof(render::GPUTransmissionBlock, factor),
            "ext.transmission.factor", "KHR_materials_transmission.transmissionFactor", "float",
            format::number(t->factor));
        add(place.transmission, offsetof(render::GPUTransmissionBlock, texture),
            "ext.transmission.texture", "KHR_materials_transmission.transmissionTexture", "uint",
            texture(t->texture), &t->texture);
    }
    if (const auto& v = m.volume; v && place.volume != render::kNoExtension) {
        const bool infinite = v->attenuation_distance == std::numeric_limits<float>::infinity();
        add(place.volume, offsetof(render::GPUVolumeBlock, attenuation), "ext.volume.attenuation",
            "KHR_materials_volume.attenuationColor, attenuationDistance", "vec4",
            format::vec(
                glm::vec4(v->attenuation_color, infinite ? 0.0f : v->attenuation_distance)) +
                (infinite ? tr(" (distance infinite: none)") : QString()));
        add(place.volume, offsetof(render::GPUVolumeBlock, thickness_factor),
            "ext.volume.thickness_factor", "KHR_materials_volume.thicknessFactor", "float",
            format::number(v->thickness_factor));
        add(place.volume, offsetof(render::GPUVolumeBlock, thickness_tex),
            "ext.volume.thickness_tex", "KHR_materials_volume.thicknessTexture", "uint",
            texture(v->thickness), &v->thickness);
    }
    if (const auto& d = m.diffuse_transmission;
        d && place.diffuse_transmission != render::kNoExtension) {
        add(place.diffuse_transmission, offsetof(render::GPUDiffuseTransmissionBlock, color_factor),
            "ext.diffuse_transmission.color_factor",
            "KHR_materials_diffuse_transmission.diffuseTransmissionColorFactor, "
            "diffuseTransmissionFactor",
            "vec4", format::vec(glm::vec4(d->color_factor, d->factor)));
        add(place.diffuse_transmission, offsetof(render::GPUDiffuseTransmissionBlock, texture),
            "ext.diffuse_transmission.texture",
            "KHR_materials_diffuse_transmission.diffuseTransmissionTexture", "uint",
            texture(d->texture), &d->texture);
        add(place.diffuse_transmission, offsetof(render::GPUDiffuseTransmissionBlock, color_tex),
            "ext.diffuse_transmission.color_tex",
            "KHR_materials_diffuse_transmission.diffuseTransmissionColorTexture", "uint",
            texture(d->color), &d->color);
    }
    if (m.dispersion && place.dispersion != render::kNoExtension)
        add(place.dispersion, offsetof(render::GPUDispersionBlock, dispersion),
            "ext.dispersion.dispersion", "KHR_materials_dispersion.dispersion", "float",
            format::number(*m.dispersion));
}

} // namespace sherpa::editor
