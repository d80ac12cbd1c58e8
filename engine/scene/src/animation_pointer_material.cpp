// KHR_animation_pointer on materials: the glTF Object Model's material pointers (core
// factors, the ratified KHR_materials_* extensions' factors, KHR_texture_transform on
// every texture slot Sherpa draws), one table each, resolved against the material's
// own data: an extension pointer needs the material to draw that extension (its block
// in the GPU extension buffer exists), a texture pointer needs the texture.
#include "animation_pointer_material.h"

#include <sherpa/scene/material_extension_slots.h>
#include <sherpa/scene/scene.h>

#include <algorithm>

namespace sherpa::scene {
namespace {

constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";
constexpr const char* kIor = "KHR_materials_ior";
constexpr const char* kSpecular = "KHR_materials_specular";
constexpr const char* kClearcoat = "KHR_materials_clearcoat";
constexpr const char* kTransmission = "KHR_materials_transmission";
constexpr const char* kVolume = "KHR_materials_volume";
constexpr const char* kSheen = "KHR_materials_sheen";
constexpr const char* kIridescence = "KHR_materials_iridescence";
constexpr const char* kAnisotropy = "KHR_materials_anisotropy";
constexpr const char* kDispersion = "KHR_materials_dispersion";
constexpr const char* kDiffuseTransmission = "KHR_materials_diffuse_transmission";

struct Field {
    std::string_view path; // after "/materials/M/"
    PointerProperty property;
    const char* extension; // the extension the material must draw, or null
};

using P = PointerProperty;
constexpr Field kFields[] = {
    {"pbrMetallicRoughness/baseColorFactor", P::BaseColorFactor, nullptr},
    {"pbrMetallicRoughness/metallicFactor", P::MetallicFactor, nullptr},
    {"pbrMetallicRoughness/roughnessFactor", P::RoughnessFactor, nullptr},
    {"emissiveFactor", P::EmissiveFactor, nullptr},
    {"alphaCutoff", P::AlphaCutoff, nullptr},
    {"normalTexture/scale", P::NormalScale, nullptr},
    {"occlusionTexture/strength", P::OcclusionStrength, nullptr},
    {"extensions/KHR_materials_emissive_strength/emissiveStrength", P::EmissiveStrength,
     kEmissiveStrength},
    {"extensions/KHR_materials_ior/ior", P::Ior, kIor},
    {"extensions/KHR_materials_specular/specularFactor", P::SpecularFactor, kSpecular},
    {"extensions/KHR_materials_specular/specularColorFactor", P::SpecularColorFactor, kSpecular},
    {"extensions/KHR_materials_clearcoat/clearcoatFactor", P::ClearcoatFactor, kClearcoat},
    {"extensions/KHR_materials_clearcoat/clearcoatRoughnessFactor", P::ClearcoatRoughnessFactor,
     kClearcoat},
    {"extensions/KHR_materials_clearcoat/clearcoatNormalTexture/scale", P::ClearcoatNormalScale,
     kClearcoat},
    {"extensions/KHR_materials_transmission/transmissionFactor", P::TransmissionFactor,
     kTransmission},
    {"extensions/KHR_materials_volume/thicknessFactor", P::ThicknessFactor, kVolume},
    {"extensions/KHR_materials_volume/attenuationDistance", P::AttenuationDistance, kVolume},
    {"extensions/KHR_materials_volume/attenuationColor", P::AttenuationColor, kVolume},
    {"extensions/KHR_materials_sheen/sheenColorFactor", P::SheenColorFactor, kSheen},
    {"extensions/KHR_materials_sheen/sheenRoughnessFactor", P::SheenRoughnessFactor, kSheen},
    {"extensions/KHR_materials_iridescence/iridescenceFactor", P::IridescenceFactor, kIridescence},
    {"extensions/KHR_materials_iridescence/iridescenceIor", P::IridescenceIor, kIridescence},
    {"extensions/KHR_materials_iridescence/iridescenceThicknessMinimum",
     P::IridescenceThicknessMinimum, kIridescence},
    {"extensions/KHR_materials_iridescence/iridescenceThicknessMaximum",
     P::IridescenceThicknessMaximum, kIridescence},
    {"extensions/KHR_materials_anisotropy/anisotropyStrength", P::AnisotropyStrength, kAnisotropy},
    {"extensions/KHR_materials_anisotropy/anisotropyRotation", P::AnisotropyRotation, kAnisotropy},
    {"extensions/KHR_materials_dispersion/dispersion", P::Dispersion, kDispersion},
    {"extensions/KHR_materials_diffuse_transmission/diffuseTransmissionFactor",
     P::DiffuseTransmissionFactor, kDiffuseTransmission},
    {"extensions/KHR_materials_diffuse_transmission/diffuseTransmissionColorFactor",
     P::DiffuseTransmissionColorFactor, kDiffuseTransmission},
};

struct Slot {
    std::string_view path; // the textureInfo, after "/materials/M/"
    PointerTextureSlot slot;
    const char* extension;
};

using S = PointerTextureSlot;
constexpr Slot kSlots[] = {
    {"pbrMetallicRoughness/baseColorTexture", S::BaseColor, nullptr},
    {"pbrMetallicRoughness/metallicRoughnessTexture", S::MetallicRoughness, nullptr},
    {"normalTexture", S::Normal, nullptr},
    {"occlusionTexture", S::Occlusion, nullptr},
    {"emissiveTexture", S::Emissive, nullptr},
    {"extensions/KHR_materials_specular/specularTexture", S::Specular, kSpecular},
    {"extensions/KHR_materials_specular/specularColorTexture", S::SpecularColor, kSpecular},
    {"extensions/KHR_materials_clearcoat/clearcoatTexture", S::Clearcoat, kClearcoat},
    {"extensions/KHR_materials_clearcoat/clearcoatRoughnessTexture", S::ClearcoatRoughness,
     kClearcoat},
    {"extensions/KHR_materials_clearcoat/clearcoatNormalTexture", S::ClearcoatNormal, kClearcoat},
    {"extensions/KHR_materials_sheen/sheenColorTexture", S::SheenColor, kSheen},
    {"extensions/KHR_materials_sheen/sheenRoughnessTexture", S::SheenRoughness, kSheen},
    {"extensions/KHR_materials_transmission/transmissionTexture", S::Transmission, kTransmission},
    {"extensions/KHR_materials_volume/thicknessTexture", S::Thickness, kVolume},
    {"extensions/KHR_materials_diffuse_transmission/diffuseTransmissionTexture",
     S::DiffuseTransmission, kDiffuseTransmission},
    {"extensions/KHR_materials_diffuse_transmission/diffuseTransmissionColorTexture",
     S::DiffuseTransmissionColor, kDiffuseTransmission},
    {"extensions/KHR_materials_anisotropy/anisotropyTexture", S::Anisotropy, kAnisotropy},
    {"extensions/KHR_materials_iridescence/iridescenceTexture", S::Iridescence, kIridescence},
    {"extensions/KHR_materials_iridescence/iridescenceThicknessTexture", S::IridescenceThickness,
     kIridescence},
};

constexpr std::pair<std::string_view, PointerProperty> kTransform[] = {
    {"offset", P::TextureOffset},
    {"rotation", P::TextureRotation},
    {"scale", P::TextureScale},
};

// Whether `m` has `extension`'s data (set by the importer only where the material uses it).
bool has_extension_data(const MaterialInstance& m, std::string_view extension) {
    if (extension == kIor) return m.ior.has_value();
    if (extension == kSpecular) return m.specular.has_value();
    if (extension == kClearcoat) return m.clearcoat.has_value();
    if (extension == kTransmission) return m.transmission.has_value();
    if (extension == kVolume) return m.volume.has_value();
    if (extension == kSheen) return m.sheen.has_value();
    if (extension == kIridescence) return m.iridescence.has_value();
    if (extension == kAnisotropy) return m.anisotropy.has_value();
    if (extension == kDispersion) return m.dispersion.has_value();
    if (extension == kDiffuseTransmission) return m.diffuse_transmission.has_value();
    return false;
}

// Empty when `m` draws `extension` (for a block-backed one: its block is in the GPU
// extension buffer), else why not.
std::string check_extension(const MaterialInstance& m, std::uint32_t index,
                            std::string_view extension) {
    const std::string name = "materials[" + std::to_string(index) + "]";
    const bool named =
        std::find(m.extensions.begin(), m.extensions.end(), extension) != m.extensions.end();
    // emissive_strength lives in the material record itself, not in an extension block.
    if (extension == kEmissiveStrength)
        return named ? std::string() : name + " does not use " + std::string(extension);
    if (!named || !has_extension_data(m, extension))
        return name + " does not use " + std::string(extension);
    if (!draws_material_extensions(m))
        return name + " uses " + std::string(extension) + " but does not draw it (" +
               (m.unlit ? "unlit" : "specular-glossiness") + ")";
    return {};
}

TextureSlot* slot_of(MaterialInstance& m, PointerTextureSlot s) {
    auto opt = [](auto& o, auto member) -> TextureSlot* { return o ? &((*o).*member) : nullptr; };
    switch (s) {
    case S::BaseColor:
        return &m.base_color;
    case S::MetallicRoughness:
        return &m.metallic_roughness;
    case S::Normal:
        return &m.normal;
    case S::Occlusion:
        return &m.occlusion;
    case S::Emissive:
        return &m.emissive;
    case S::Specular:
        return opt(m.specular, &MaterialSpecular::specular);
    case S::SpecularColor:
        return opt(m.specular, &MaterialSpecular::specular_color);
    case S::Clearcoat:
        return opt(m.clearcoat, &MaterialClearcoat::clearcoat);
    case S::ClearcoatRoughness:
        return opt(m.clearcoat, &MaterialClearcoat::roughness);
    case S::ClearcoatNormal:
        return opt(m.clearcoat, &MaterialClearcoat::normal);
    case S::SheenColor:
        return opt(m.sheen, &MaterialSheen::color);
    case S::SheenRoughness:
        return opt(m.sheen, &MaterialSheen::roughness);
    case S::Transmission:
        return opt(m.transmission, &MaterialTransmission::texture);
    case S::Thickness:
        return opt(m.volume, &MaterialVolume::thickness);
    case S::DiffuseTransmission:
        return opt(m.diffuse_transmission, &MaterialDiffuseTransmission::texture);
    case S::DiffuseTransmissionColor:
        return opt(m.diffuse_transmission, &MaterialDiffuseTransmission::color);
    case S::Anisotropy:
        return opt(m.anisotropy, &MaterialAnisotropy::texture);
    case S::Iridescence:
        return opt(m.iridescence, &MaterialIridescence::texture);
    case S::IridescenceThickness:
        return opt(m.iridescence, &MaterialIridescence::thickness);
    }
    return nullptr;
}

std::string resolve_texture_transform(const MaterialInstance& m, std::uint32_t index,
                                      std::string_view rest, AnimatedTarget& out) {
    constexpr std::string_view kExt = "/extensions/KHR_texture_transform/";
    for (const Slot& s : kSlots) {
        if (rest.substr(0, s.path.size()) != s.path ||
            rest.substr(s.path.size(), kExt.size()) != kExt)
            continue;
        const std::string_view field = rest.substr(s.path.size() + kExt.size());
        for (const auto& [name, property] : kTransform) {
            if (field != name) continue;
            if (s.extension)
                if (std::string why = check_extension(m, index, s.extension); !why.empty())
                    return why;
            const TextureSlot* slot = slot_of(const_cast<MaterialInstance&>(m), s.slot);
            if (!slot || !slot->present())
                return "materials[" + std::to_string(index) + "] has no " + std::string(s.path);
            out.property = property;
            out.slot = s.slot;
            return {};
        }
    }
    return "not an animatable material property (supported: the glTF Object Model's material "
           "pointers: core factors, alphaCutoff, the ratified KHR_materials_* factors and "
           "KHR_texture_transform of every texture)";
}

} // namespace

std::string resolve_material_pointer(const MaterialInstance& m, std::uint32_t index,
                                     std::string_view rest, AnimatedTarget& out) {
    out.object = index;
    for (const Field& f : kFields) {
        if (rest != f.path) continue;
        if (f.extension)
            if (std::string why = check_extension(m, index, f.extension); !why.empty()) return why;
        // A textureInfo's own property exists only where the texture does.
        if (f.property == P::ClearcoatNormalScale && !m.clearcoat->normal.present())
            return "materials[" + std::to_string(index) +
                   "] has no extensions/KHR_materials_clearcoat/clearcoatNormalTexture";
        out.property = f.property;
        return {};
    }
    return resolve_texture_transform(m, index, rest, out);
}

std::string material_pointer_path(const AnimatedTarget& t) {
    if (t.property >= P::TextureOffset && t.property <= P::TextureScale) {
        for (const Slot& s : kSlots)
            if (s.slot == t.slot)
                for (const auto& [name, property] : kTransform)
                    if (property == t.property)
                        return std::string(s.path) + "/extensions/KHR_texture_transform/" +
                               std::string(name);
        return {};
    }
    for (const Field& f : kFields)
        if (f.property == t.property) return std::string(f.path);
    return {};
}

bool apply_material_property(const AnimatedProperty& p, MaterialInstance& m) {
    const float* v = p.value;
    const glm::vec3 v3(v[0], v[1], v[2]);
    switch (p.target.property) {
    case P::BaseColorFactor:
        m.base_color_factor = {v[0], v[1], v[2], v[3]};
        return true;
    case P::EmissiveFactor:
        m.emissive_factor = v3;
        return true;
    case P::MetallicFactor:
        m.metallic_factor = v[0];
        return true;
    case P::RoughnessFactor:
        m.roughness_factor = v[0];
        return true;
    case P::AlphaCutoff:
        m.alpha_cutoff = v[0];
        return true;
    case P::NormalScale:
        m.normal_scale = v[0];
        return true;
    case P::OcclusionStrength:
        m.occlusion_strength = v[0];
        return true;
    case P::EmissiveStrength:
        m.emissive_strength = v[0];
        return true;
    case P::Ior:
        if (m.ior) m.ior = v[0];
        return true;
    case P::SpecularFactor:
        if (m.specular) m.specular->specular_factor = v[0];
        return true;
    case P::SpecularColorFactor:
        if (m.specular) m.specular->specular_color_factor = v3;
        return true;
    case P::ClearcoatFactor:
        if (m.clearcoat) m.clearcoat->factor = v[0];
        return true;
    case P::ClearcoatRoughnessFactor:
        if (m.clearcoat) m.clearcoat->roughness_factor = v[0];
        return true;
    case P::ClearcoatNormalScale:
        if (m.clearcoat) m.clearcoat->normal_scale = v[0];
        return true;
    case P::TransmissionFactor:
        if (m.transmission) m.transmission->factor = v[0];
        return true;
    case P::ThicknessFactor:
        if (m.volume) m.volume->thickness_factor = v[0];
        return true;
    case P::AttenuationDistance:
        if (m.volume) m.volume->attenuation_distance = v[0];
        return true;
    case P::AttenuationColor:
        if (m.volume) m.volume->attenuation_color = v3;
        return true;
    case P::SheenColorFactor:
        if (m.sheen) m.sheen->color_factor = v3;
        return true;
    case P::SheenRoughnessFactor:
        if (m.sheen) m.sheen->roughness_factor = v[0];
        return true;
    case P::IridescenceFactor:
        if (m.iridescence) m.iridescence->factor = v[0];
        return true;
    case P::IridescenceIor:
        if (m.iridescence) m.iridescence->ior = v[0];
        return true;
    case P::IridescenceThicknessMinimum:
        if (m.iridescence) m.iridescence->thickness_minimum = v[0];
        return true;
    case P::IridescenceThicknessMaximum:
        if (m.iridescence) m.iridescence->thickness_maximum = v[0];
        return true;
    case P::AnisotropyStrength:
        if (m.anisotropy) m.anisotropy->strength = v[0];
        return true;
    case P::AnisotropyRotation:
        if (m.anisotropy) m.anisotropy->rotation = v[0];
        return true;
    case P::Dispersion:
        if (m.dispersion) m.dispersion = v[0];
        return true;
    case P::DiffuseTransmissionFactor:
        if (m.diffuse_transmission) m.diffuse_transmission->factor = v[0];
        return true;
    case P::DiffuseTransmissionColorFactor:
        if (m.diffuse_transmission) m.diffuse_transmission->color_factor = v3;
        return true;
    case P::TextureOffset:
    case P::TextureRotation:
    case P::TextureScale:
        break;
    default:
        return false;
    }
    TextureSlot* slot = slot_of(m, p.target.slot);
    if (!slot) return true; // resolved against this material: not reached
    if (p.target.property == P::TextureOffset) slot->transform.offset = {v[0], v[1]};
    if (p.target.property == P::TextureRotation) slot->transform.rotation = v[0];
    if (p.target.property == P::TextureScale) slot->transform.scale = {v[0], v[1]};
    slot->transform.present = true;
    return true;
}

} // namespace sherpa::scene
