#pragma once
// C++ twins of the material extension buffer's structures
// (shaders/include/material_ext_structs.glsl), pinned like those of gpu_structs.h and
// checked by tests/gpu/struct_twins_test.cpp; sherpa_glsl_constants generates
// kNoExtension for the shaders from here.
#include <cstdint>

#include <sherpa/render/gpu_structs.h> // GPUTextureTransform

namespace sherpa::render {

// Material extensions (shaders/include/material_ext.glsl): one storage buffer of
// 16-byte words (set 1, binding 8) that holds, for each material using at least one
// drawn extension, a GPUExtensionIndex and then one block per extension it uses. A
// scene where no material uses one has no buffer at all; a material that uses only
// KHR_materials_ior pays 64 bytes (the 48-byte index and its block). Offsets are in 16-byte words
// from the buffer's start; every block is a whole number of words, read by the shader word by word
// in field order (the GLSL twins are checked by tests/gpu/struct_twins_test.cpp).
inline constexpr std::uint32_t kNoExtension = 0xffffffffu;
inline constexpr std::uint32_t kExtensionWordBytes = 16;

struct GPUExtensionIndex {
    std::uint32_t ior;       // GPUIorBlock, or kNoExtension
    std::uint32_t specular;  // GPUSpecularBlock, or kNoExtension
    std::uint32_t clearcoat; // GPUClearcoatBlock, or kNoExtension
    std::uint32_t sheen;     // GPUSheenBlock, or kNoExtension
    // Second word: the transmission family (shaders/include/transmission.glsl).
    std::uint32_t transmission;         // GPUTransmissionBlock, or kNoExtension
    std::uint32_t volume;               // GPUVolumeBlock, or kNoExtension
    std::uint32_t diffuse_transmission; // GPUDiffuseTransmissionBlock, or kNoExtension
    std::uint32_t dispersion;           // GPUDispersionBlock, or kNoExtension
    // Third word: the microfacet's own shape and film.
    std::uint32_t anisotropy;  // GPUAnisotropyBlock, or kNoExtension
    std::uint32_t iridescence; // GPUIridescenceBlock, or kNoExtension
    std::uint32_t pad0, pad1;
};
static_assert(offsetof(GPUExtensionIndex, specular) == 4);
static_assert(offsetof(GPUExtensionIndex, clearcoat) == 8);
static_assert(offsetof(GPUExtensionIndex, sheen) == 12);
static_assert(offsetof(GPUExtensionIndex, transmission) == 16);
static_assert(offsetof(GPUExtensionIndex, volume) == 20);
static_assert(offsetof(GPUExtensionIndex, diffuse_transmission) == 24);
static_assert(offsetof(GPUExtensionIndex, dispersion) == 28);
static_assert(offsetof(GPUExtensionIndex, anisotropy) == 32);
static_assert(offsetof(GPUExtensionIndex, iridescence) == 36);
static_assert(sizeof(GPUExtensionIndex) == 48);

// KHR_materials_ior.
struct GPUIorBlock {
    float ior;
    float pad0, pad1, pad2;
};
static_assert(sizeof(GPUIorBlock) == 16);

// KHR_materials_specular. Textures are bindless slots (white where absent).
struct GPUSpecularBlock {
    glm::vec4 color_factor;           // xyz specularColorFactor, w specularFactor
    std::uint32_t specular_tex;       // A channel, linear
    std::uint32_t specular_color_tex; // RGB, sRGB
    std::uint32_t pad0, pad1;
    GPUTextureTransform specular_uv; // KHR_texture_transform of specularTexture
    GPUTextureTransform color_uv;    // ... of specularColorTexture
};
static_assert(offsetof(GPUSpecularBlock, specular_tex) == 16);
static_assert(offsetof(GPUSpecularBlock, specular_color_tex) == 20);
static_assert(offsetof(GPUSpecularBlock, specular_uv) == 32);
static_assert(offsetof(GPUSpecularBlock, color_uv) == 64);
static_assert(sizeof(GPUSpecularBlock) == 96);

// KHR_materials_clearcoat: the coat's weight, roughness and normal map. Textures are
// bindless slots (white, or the flat normal, where absent).
struct GPUClearcoatBlock {
    glm::vec4 factors;           // x clearcoatFactor, y clearcoatRoughnessFactor, z normal scale
    std::uint32_t clearcoat_tex; // R channel, linear
    std::uint32_t roughness_tex; // G channel, linear
    std::uint32_t normal_tex;    // tangent-space normal (kFlatNormalTexture where absent)
    std::uint32_t pad0;
    GPUTextureTransform clearcoat_uv; // KHR_texture_transform of clearcoatTexture
    GPUTextureTransform roughness_uv; // ... of clearcoatRoughnessTexture
    GPUTextureTransform normal_uv;    // ... of clearcoatNormalTexture
};
static_assert(offsetof(GPUClearcoatBlock, clearcoat_tex) == 16);
static_assert(offsetof(GPUClearcoatBlock, roughness_tex) == 20);
static_assert(offsetof(GPUClearcoatBlock, normal_tex) == 24);
static_assert(offsetof(GPUClearcoatBlock, clearcoat_uv) == 32);
static_assert(offsetof(GPUClearcoatBlock, roughness_uv) == 64);
static_assert(offsetof(GPUClearcoatBlock, normal_uv) == 96);
static_assert(sizeof(GPUClearcoatBlock) == 128);

// KHR_materials_sheen. Textures are bindless slots (white where absent).
struct GPUSheenBlock {
    glm::vec4 factors;           // xyz sheenColorFactor, w sheenRoughnessFactor
    std::uint32_t color_tex;     // RGB, sRGB
    std::uint32_t roughness_tex; // A channel, linear
    std::uint32_t pad0, pad1;
    GPUTextureTransform color_uv;     // KHR_texture_transform of sheenColorTexture
    GPUTextureTransform roughness_uv; // ... of sheenRoughnessTexture
};
static_assert(offsetof(GPUSheenBlock, color_tex) == 16);
static_assert(offsetof(GPUSheenBlock, roughness_tex) == 20);
static_assert(offsetof(GPUSheenBlock, color_uv) == 32);
static_assert(offsetof(GPUSheenBlock, roughness_uv) == 64);
static_assert(sizeof(GPUSheenBlock) == 96);

// KHR_materials_transmission (shaders/include/transmission_structs.glsl).
struct GPUTransmissionBlock {
    float factor;          // transmissionFactor
    std::uint32_t texture; // R channel, linear (white where absent)
    std::uint32_t pad0, pad1;
    GPUTextureTransform uv; // KHR_texture_transform of transmissionTexture
};
static_assert(offsetof(GPUTransmissionBlock, texture) == 4);
static_assert(offsetof(GPUTransmissionBlock, uv) == 16);
static_assert(sizeof(GPUTransmissionBlock) == 48);

// KHR_materials_volume.
struct GPUVolumeBlock {
    glm::vec4 attenuation;       // xyz attenuationColor, w attenuationDistance (inf: none)
    float thickness_factor;      // local units of the mesh
    std::uint32_t thickness_tex; // G channel, linear
    std::uint32_t pad0, pad1;
    GPUTextureTransform thickness_uv;
};
static_assert(offsetof(GPUVolumeBlock, thickness_factor) == 16);
static_assert(offsetof(GPUVolumeBlock, thickness_tex) == 20);
static_assert(offsetof(GPUVolumeBlock, thickness_uv) == 32);
static_assert(sizeof(GPUVolumeBlock) == 64);

// KHR_materials_diffuse_transmission.
struct GPUDiffuseTransmissionBlock {
    glm::vec4 color_factor;  // xyz diffuseTransmissionColorFactor, w diffuseTransmissionFactor
    std::uint32_t texture;   // A channel, linear
    std::uint32_t color_tex; // RGB, sRGB
    std::uint32_t pad0, pad1;
    GPUTextureTransform uv;       // of diffuseTransmissionTexture
    GPUTextureTransform color_uv; // of diffuseTransmissionColorTexture
};
static_assert(offsetof(GPUDiffuseTransmissionBlock, texture) == 16);
static_assert(offsetof(GPUDiffuseTransmissionBlock, color_tex) == 20);
static_assert(offsetof(GPUDiffuseTransmissionBlock, uv) == 32);
static_assert(offsetof(GPUDiffuseTransmissionBlock, color_uv) == 64);
static_assert(sizeof(GPUDiffuseTransmissionBlock) == 96);

// KHR_materials_dispersion.
struct GPUDispersionBlock {
    float dispersion; // 20 / Abbe number
    float pad0, pad1, pad2;
};
static_assert(sizeof(GPUDispersionBlock) == 16);

// KHR_materials_anisotropy (shaders/include/anisotropy.glsl). The rotation is stored as
// its cosine and sine (the direction's rotation matrix).
struct GPUAnisotropyBlock {
    glm::vec4 factors;     // x anisotropyStrength, y cos(anisotropyRotation), z sin(...)
    std::uint32_t texture; // RG direction, B strength, linear (white where absent)
    std::uint32_t pad0, pad1, pad2;
    GPUTextureTransform uv; // KHR_texture_transform of anisotropyTexture
};
static_assert(offsetof(GPUAnisotropyBlock, texture) == 16);
static_assert(offsetof(GPUAnisotropyBlock, uv) == 32);
static_assert(sizeof(GPUAnisotropyBlock) == 64);

// KHR_materials_iridescence (shaders/include/iridescence.glsl).
struct GPUIridescenceBlock {
    glm::vec4 factors; // x iridescenceFactor, y iridescenceIor, z thickness minimum, w maximum (nm)
    std::uint32_t texture;       // R channel, linear (white where absent)
    std::uint32_t thickness_tex; // G channel, linear (white where absent)
    std::uint32_t pad0, pad1;
    GPUTextureTransform uv;           // KHR_texture_transform of iridescenceTexture
    GPUTextureTransform thickness_uv; // ... of iridescenceThicknessTexture
};
static_assert(offsetof(GPUIridescenceBlock, texture) == 16);
static_assert(offsetof(GPUIridescenceBlock, thickness_tex) == 20);
static_assert(offsetof(GPUIridescenceBlock, uv) == 32);
static_assert(offsetof(GPUIridescenceBlock, thickness_uv) == 64);
static_assert(sizeof(GPUIridescenceBlock) == 96);

} // namespace sherpa::render
