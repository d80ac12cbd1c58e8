#pragma once
// Materials: the CPU-side MaterialInstance and its GPU twin GPUMaterialData
// (shaders/include/material.glsl must stay byte-identical).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sherpa::scene {

enum class AlphaMode : std::uint32_t { Opaque = 0, Mask = 1, Blend = 2 };
std::string_view to_string(AlphaMode m);

// Unresolved texture index: the GPU layer replaces it by a default texture
// (white for colour/linear roles, flat normal for normals, black for emissive).
inline constexpr std::uint32_t kTextureSentinel = std::numeric_limits<std::uint32_t>::max();

// KHR_texture_transform. `present` is false when the extension is absent.
struct TextureTransform {
    bool present = false;
    glm::vec2 offset{0.0f};
    glm::vec2 scale{1.0f};
    float rotation = 0.0f; // radians, counter-clockwise in UV space
    // UV transform as the extension defines it: T * R * S.
    glm::mat3 matrix() const;
};

struct TextureSlot {
    std::int32_t texture = -1;   // index into Scene::textures, -1 = none
    std::uint32_t tex_coord = 0; // effective TEXCOORD_n set (after KHR_texture_transform override)
    TextureTransform transform;
    bool present() const { return texture >= 0; }
};

// KHR_materials_pbrSpecularGlossiness, shaded by its own definition: its diffuse
// (diffuseFactor, diffuseTexture) is held in MaterialInstance::base_color_factor and
// base_color (same role: sRGB colour with alpha for coverage), and F0 = specular,
// roughness = 1 - glossiness, diffuse reflectance = diffuse * (1 - max(specular)).
struct SpecularGlossiness {
    glm::vec3 specular_factor{1.0f};
    float glossiness_factor = 1.0f;
    TextureSlot specular_glossiness; // RGB specular (sRGB), A glossiness (linear)
};

// KHR_materials_specular: the strength (specularFactor x specularTexture.a) and the F0
// colour (specularColorFactor x specularColorTexture.rgb, sRGB) of the dielectric's
// specular reflection; metals are unaffected.
struct MaterialSpecular {
    float specular_factor = 1.0f;
    glm::vec3 specular_color_factor{1.0f};
    TextureSlot specular;       // A channel, linear
    TextureSlot specular_color; // RGB, sRGB
};

// KHR_materials_transmission: the fraction of the dielectric's non-reflected light that
// passes through the surface (transmissionFactor x transmissionTexture.r) instead of
// being scattered diffusely. Thin-walled (no refraction) unless KHR_materials_volume.
struct MaterialTransmission {
    float factor = 0.0f;
    TextureSlot texture; // R channel, linear
};

// KHR_materials_volume: the volume under the surface. Thickness (thicknessFactor x
// thicknessTexture.g, in the mesh's local units) is what the raster offsets the
// refracted ray by; attenuation is Beer-Lambert: colour^(distance / attenuationDistance).
struct MaterialVolume {
    float thickness_factor = 0.0f;
    TextureSlot thickness; // G channel, linear
    float attenuation_distance = std::numeric_limits<float>::infinity();
    glm::vec3 attenuation_color{1.0f};
};

// KHR_materials_diffuse_transmission: the fraction of the diffuse lobe that scatters to
// the other side (factor x texture.a), tinted by colour (factor x texture.rgb, sRGB).
struct MaterialDiffuseTransmission {
    float factor = 0.0f;
    TextureSlot texture; // A channel, linear
    glm::vec3 color_factor{1.0f};
    TextureSlot color; // RGB, sRGB
};

// KHR_materials_clearcoat: a dielectric coat (F0 0.04) over the material, weighted by
// clearcoatFactor x clearcoatTexture.r, its roughness clearcoatRoughnessFactor x
// clearcoatRoughnessTexture.g, its own normal map (none: the geometry's normal).
struct MaterialClearcoat {
    float factor = 0.0f;
    float roughness_factor = 0.0f;
    float normal_scale = 1.0f; // clearcoatNormalTexture.scale
    TextureSlot clearcoat;     // R channel, linear
    TextureSlot roughness;     // G channel, linear
    TextureSlot normal;        // tangent-space normal map
};

// KHR_materials_sheen: a Charlie sheen over the material, its colour
// sheenColorFactor x sheenColorTexture.rgb (sRGB; black: no sheen) and its roughness
// sheenRoughnessFactor x sheenRoughnessTexture.a.
struct MaterialSheen {
    glm::vec3 color_factor{0.0f};
    float roughness_factor = 0.0f;
    TextureSlot color;     // RGB, sRGB
    TextureSlot roughness; // A channel, linear
};

// KHR_materials_anisotropy: anisotropic GGX whose roughness along the anisotropy
// direction is mix(alpha, 1, strength^2) (alpha across it). The strength is
// anisotropyStrength x anisotropyTexture.b; the direction is anisotropyTexture.rg
// (2 x rg - 1 in the tangent frame; +x without a texture) rotated counter-clockwise by
// anisotropyRotation (radians). Drawn with tangents (generated where the mesh has none).
struct MaterialAnisotropy {
    float strength = 0.0f;
    float rotation = 0.0f; // radians
    TextureSlot texture;   // RG direction, B strength, linear
};

// KHR_materials_iridescence: a thin dielectric film over the base whose interference
// colours the specular reflection (the Fresnel term), weighted by iridescenceFactor x
// iridescenceTexture.r. The film's index is iridescenceIor and its thickness in
// nanometres mix(thicknessMinimum, thicknessMaximum, iridescenceThicknessTexture.g)
// (thicknessMaximum without the texture).
struct MaterialIridescence {
    float factor = 0.0f;
    float ior = 1.3f;
    float thickness_minimum = 100.0f; // nm
    float thickness_maximum = 400.0f; // nm
    TextureSlot texture;              // R channel, linear
    TextureSlot thickness;            // G channel, linear
};

// KHR_materials_ior's default, which is also the core glTF dielectric (F0 = 0.04).
inline constexpr float kDefaultIor = 1.5f;

struct MaterialInstance {
    std::string name;
    std::int32_t gltf_index = -1; // -1: Sherpa's default material
    glm::vec4 base_color_factor{1.0f};
    glm::vec3 emissive_factor{0.0f};
    float emissive_strength = 1.0f; // KHR_materials_emissive_strength
    float metallic_factor = 1.0f;
    float roughness_factor = 1.0f;
    float normal_scale = 1.0f;
    float occlusion_strength = 1.0f;
    float alpha_cutoff = 0.5f;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    bool double_sided = false;
    bool unlit = false; // KHR_materials_unlit
    // Set when the material uses KHR_materials_pbrSpecularGlossiness (then the
    // metallic-roughness fields are its fallback and are not shaded).
    std::optional<SpecularGlossiness> specular_glossiness;
    // Material extensions, each set only when the material uses it (and then drawn with
    // a block of its own in the GPU extension buffer; absent ones cost nothing).
    std::optional<float> ior;                         // KHR_materials_ior: >= 1, or 0 (F0 = 1)
    std::optional<MaterialSpecular> specular;         // KHR_materials_specular
    std::optional<MaterialClearcoat> clearcoat;       // KHR_materials_clearcoat
    std::optional<MaterialSheen> sheen;               // KHR_materials_sheen
    std::optional<MaterialTransmission> transmission; // KHR_materials_transmission
    std::optional<MaterialVolume> volume;             // KHR_materials_volume
    std::optional<MaterialDiffuseTransmission> diffuse_transmission; // ..._diffuse_transmission
    std::optional<float> dispersion; // KHR_materials_dispersion: Abbe-number scale, >= 0
    std::optional<MaterialAnisotropy> anisotropy;   // KHR_materials_anisotropy
    std::optional<MaterialIridescence> iridescence; // KHR_materials_iridescence
    // The names in the material's `extensions` object, as written (sorted): what
    // marks a material that uses an extension Sherpa does not draw.
    std::vector<std::string> extensions;
    TextureSlot base_color, metallic_roughness, normal, occlusion, emissive;
};

// std430, 80 bytes, Himalaya's field order. Texture fields hold bindless indices once
// the GPU layer resolves them; straight from the importer they hold glTF texture
// indices or kTextureSentinel.
struct alignas(16) GPUMaterialData {
    glm::vec4 base_color_factor;          // 0
    glm::vec4 emissive_factor;            // 16: xyz factor, w = KHR_materials_emissive_strength
    float metallic_factor;                // 32
    float roughness_factor;               // 36
    float normal_scale;                   // 40
    float occlusion_strength;             // 44
    std::uint32_t base_color_tex;         // 48
    std::uint32_t emissive_tex;           // 52
    std::uint32_t metallic_roughness_tex; // 56
    std::uint32_t normal_tex;             // 60
    std::uint32_t occlusion_tex;          // 64
    float alpha_cutoff;                   // 68
    std::uint32_t alpha_mode;             // 72: AlphaMode
    std::uint32_t double_sided;           // 76
};
static_assert(sizeof(GPUMaterialData) == 80);
static_assert(alignof(GPUMaterialData) == 16);
static_assert(offsetof(GPUMaterialData, base_color_factor) == 0);
static_assert(offsetof(GPUMaterialData, emissive_factor) == 16);
static_assert(offsetof(GPUMaterialData, metallic_factor) == 32);
static_assert(offsetof(GPUMaterialData, roughness_factor) == 36);
static_assert(offsetof(GPUMaterialData, normal_scale) == 40);
static_assert(offsetof(GPUMaterialData, occlusion_strength) == 44);
static_assert(offsetof(GPUMaterialData, base_color_tex) == 48);
static_assert(offsetof(GPUMaterialData, emissive_tex) == 52);
static_assert(offsetof(GPUMaterialData, metallic_roughness_tex) == 56);
static_assert(offsetof(GPUMaterialData, normal_tex) == 60);
static_assert(offsetof(GPUMaterialData, occlusion_tex) == 64);
static_assert(offsetof(GPUMaterialData, alpha_cutoff) == 68);
static_assert(offsetof(GPUMaterialData, alpha_mode) == 72);
static_assert(offsetof(GPUMaterialData, double_sided) == 76);

// GPU record with glTF texture indices (or the sentinel) in the texture fields.
GPUMaterialData to_gpu_material(const MaterialInstance& m);

} // namespace sherpa::scene
