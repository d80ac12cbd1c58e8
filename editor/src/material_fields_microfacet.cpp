// The material dock's rows of the extensions that shape the base's microfacets
// (KHR_materials_anisotropy, KHR_materials_iridescence): each field of the material's block with
// its byte offset in the extension buffer, values from the CPU record.
#include "material_fields_model.h"

#include <cmath>
#include <cstddef>

#include "format_values.h"

#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/material_extensions.h>

namespace sherpa::editor {

void MaterialFieldsModel::appendMicrofacetRows(const render::MaterialExtensionPlace& place,
                                               const scene::MaterialInstance& m) {
    if (place.anisotropy == render::kNoExtension && place.iridescence == render::kNoExtension)
        return;
    const int word = int(render::kExtensionWordBytes);
    auto words = [](std::uint32_t w) {
        return w == render::kNoExtension ? tr("absent") : QString::number(w);
    };
    auto add = [&](std::uint32_t block, std::size_t offset, const char* field, const char* property,
                   const char* type, const QString& value,
                   const scene::TextureSlot* slot = nullptr) {
        extension_rows_.push_back({int(block) * word + int(offset), QString::fromLatin1(field),
                                   QString::fromLatin1(property), QString::fromLatin1(type), value,
                                   slot && slot->present() ? slot->texture : -1});
    };
    add(place.index, offsetof(render::GPUExtensionIndex, anisotropy), "ext.index.anisotropy",
        "GPUExtensionIndex word 2", "uvec4",
        tr("anisotropy %1, iridescence %2").arg(words(place.anisotropy), words(place.iridescence)));
    if (const auto& a = m.anisotropy; a && place.anisotropy != render::kNoExtension) {
        add(place.anisotropy, offsetof(render::GPUAnisotropyBlock, factors),
            "ext.anisotropy.factors",
            "KHR_materials_anisotropy.anisotropyStrength, cos, sin (anisotropyRotation)", "vec4",
            format::vec(
                glm::vec4(a->strength, std::cos(a->rotation), std::sin(a->rotation), 0.0f)));
        add(place.anisotropy, offsetof(render::GPUAnisotropyBlock, texture),
            "ext.anisotropy.texture", "KHR_materials_anisotropy.anisotropyTexture", "uint",
            a->texture.present() ? chain(a->texture.texture) : tr("default texture"), &a->texture);
    }
    if (const auto& i = m.iridescence; i && place.iridescence != render::kNoExtension) {
        add(place.iridescence, offsetof(render::GPUIridescenceBlock, factors),
            "ext.iridescence.factors",
            "KHR_materials_iridescence.iridescenceFactor, iridescenceIor, "
            "iridescenceThicknessMinimum, iridescenceThicknessMaximum",
            "vec4",
            format::vec(glm::vec4(i->factor, i->ior, i->thickness_minimum, i->thickness_maximum)));
        add(place.iridescence, offsetof(render::GPUIridescenceBlock, texture),
            "ext.iridescence.texture", "KHR_materials_iridescence.iridescenceTexture", "uint",
            i->texture.present() ? chain(i->texture.texture) : tr("default texture"), &i->texture);
        add(place.iridescence, offsetof(render::GPUIridescenceBlock, thickness_tex),
            "ext.iridescence.thickness_tex",
            "KHR_materials_iridescence.iridescenceThicknessTexture", "uint",
            i->thickness.present() ? chain(i->thickness.texture) : tr("default texture"),
            &i->thickness);
    }
}

} // namespace sherpa::editor
