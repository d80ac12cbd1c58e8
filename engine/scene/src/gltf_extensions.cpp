#include <sherpa/scene/gltf_extensions.h>

#include <algorithm>
#include <array>

#include <sherpa/scene/pointer_target.h>
#include <sherpa/scene/scene.h>

namespace sherpa::scene {
namespace {

// The one table: flipping an extension to supported is one line here.
constexpr std::array<std::string_view, 25> kSupported{
    "EXT_mesh_gpu_instancing",    // one engine instance per row (gltf_instancing.cpp)
    "EXT_meshopt_compression",    // our decoder (meshopt_codec.h)
    "EXT_texture_webp",           // through OpenImageIO
    "KHR_draco_mesh_compression", // through Debian's Draco
    "KHR_meshopt_compression",    // vertex bitstream versions 0 and 1
    "KHR_animation_pointer", // material, texture transform, light, camera and visibility channels
    "KHR_lights_punctual",
    "KHR_materials_anisotropy", // anisotropic GGX (shaders/include/anisotropy.glsl)
    "KHR_materials_clearcoat",  // a coat over the material (shaders/include/clearcoat.glsl)
    "KHR_materials_emissive_strength",
    "KHR_materials_iridescence",          // thin-film Fresnel (shaders/include/iridescence.glsl)
    "KHR_materials_ior",                  // F0 from the ior (brdf.glsl's dielectric_f0)
    "KHR_materials_specular",             // F0 colour and F90 weight (brdf.glsl)
    "KHR_materials_transmission",         // refraction (TransmissionPass; the path tracer's BTDF)
    "KHR_materials_volume",               // thickness, Beer-Lambert attenuation (transmission.glsl)
    "KHR_materials_dispersion",           // per-channel ior (refraction.glsl; the path tracer)
    "KHR_materials_diffuse_transmission", // lit from behind (diffuse_transmission.glsl)
    "KHR_materials_unlit",
    "KHR_materials_variants", // a switch of the primitives' materials (material_variants.h)
    "KHR_materials_pbrSpecularGlossiness", // shaded by its own definition (forward.frag)
    "KHR_node_visibility",                 // the renderer's node visibility (animatable)
    "KHR_materials_sheen",                 // Charlie sheen (shaders/include/sheen.glsl)
    "KHR_mesh_quantization",               // every accessor component type is decoded
    "KHR_texture_basisu",                  // KTX2 (ETC1S / UASTC), engine/texture's transcoder
    "KHR_texture_transform",
};

std::string material_label(const Scene& scene, std::uint32_t m) {
    const MaterialInstance& mat = scene.materials[m];
    std::string out = "materials[" + std::to_string(mat.gltf_index) + "]";
    if (!mat.name.empty()) out += " \"" + mat.name + "\"";
    return out;
}

// "materials[0] "Glass", materials[2]" (at most `limit` named, then "and N more").
std::string material_list(const Scene& scene, const std::vector<std::uint32_t>& materials) {
    constexpr std::size_t limit = 4;
    std::string out;
    for (std::size_t i = 0; i < materials.size() && i < limit; ++i)
        out += (i ? ", " : "") + material_label(scene, materials[i]);
    if (materials.size() > limit)
        out += " and " + std::to_string(materials.size() - limit) + " more";
    return out;
}

} // namespace

std::span<const std::string_view> supported_gltf_extensions() {
    return kSupported;
}

bool is_supported_gltf_extension(std::string_view name) {
    return std::find(kSupported.begin(), kSupported.end(), name) != kSupported.end();
}

std::vector<ExtensionUse> extension_uses(const Scene& scene) {
    std::vector<ExtensionUse> out;
    for (std::size_t i = 0; i < scene.extensions_used.size(); ++i) {
        ExtensionUse use;
        use.name = scene.extensions_used[i];
        use.used_index = static_cast<std::uint32_t>(i);
        use.required = std::find(scene.extensions_required.begin(), scene.extensions_required.end(),
                                 use.name) != scene.extensions_required.end();
        use.supported = is_supported_gltf_extension(use.name);
        for (std::size_t m = 0; m < scene.materials.size(); ++m) {
            const auto& names = scene.materials[m].extensions;
            if (std::find(names.begin(), names.end(), use.name) != names.end())
                use.materials.push_back(static_cast<std::uint32_t>(m));
        }
        out.push_back(std::move(use));
    }
    return out;
}

std::vector<std::string> unsupported_extensions(const MaterialInstance& material) {
    std::vector<std::string> out;
    for (const std::string& name : material.extensions)
        if (!is_supported_gltf_extension(name)) out.push_back(name);
    return out;
}

std::vector<ValidationMessage> unsupported_extension_messages(const Scene& scene) {
    std::vector<ValidationMessage> out;
    for (const ExtensionUse& use : extension_uses(scene)) {
        if (use.supported) continue;
        std::string text = "extensionsUsed[" + std::to_string(use.used_index) + "] " + use.name +
                           " is not implemented by Sherpa: ";
        text += use.materials.empty()
                    ? "what it adds is not drawn"
                    : material_list(scene, use.materials) +
                          (use.materials.size() == 1 ? " is" : " are") + " drawn without it";
        out.push_back({std::string(kExtensionNotDrawnCode), std::move(text),
                       "/extensionsUsed/" + std::to_string(use.used_index), Severity::Warning});
    }
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const MaterialInstance& mat = scene.materials[m];
        if (mat.gltf_index < 0) continue; // Sherpa's default material
        for (const std::string& name : unsupported_extensions(mat))
            out.push_back({std::string(kMaterialExtensionNotDrawnCode),
                           material_label(scene, static_cast<std::uint32_t>(m)) +
                               " is drawn without " + name + ", which Sherpa does not implement",
                           "/materials/" + std::to_string(mat.gltf_index) + "/extensions/" +
                               json_pointer_token(name),
                           Severity::Warning});
    }
    return out;
}

std::vector<std::string> unsupported_extension_warnings(const Scene& scene) {
    // The same words as the messages (the importer turns warnings without a message
    // of the same text into messages of their own): one per name of extensionsUsed,
    // and one per material naming an extension that extensionsUsed does not declare
    // (an invalid file, still not drawn).
    std::vector<std::string> out;
    for (ValidationMessage& m : unsupported_extension_messages(scene)) {
        const bool declared_elsewhere =
            m.code == kMaterialExtensionNotDrawnCode &&
            std::any_of(scene.extensions_used.begin(), scene.extensions_used.end(),
                        [&m](const std::string& name) {
                            return m.pointer.ends_with("/extensions/" + json_pointer_token(name));
                        });
        if (!declared_elsewhere) out.push_back(std::move(m.message));
    }
    return out;
}

} // namespace sherpa::scene
