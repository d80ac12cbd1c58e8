// GLSL twins of the material extension records (GPUExtensionIndex, GPUIorBlock,
// GPUSpecularBlock, GPUClearcoatBlock, GPUSheenBlock, GPUAnisotropyBlock, GPUIridescenceBlock in
// engine/render/include/sherpa/render/gpu_material_ext_structs.h): 16-byte words,
// field order and offsets pinned there and checked by tests/gpu/struct_twins_test.cpp.
// material_ext.glsl reads them from the extension buffer.
#ifndef SHERPA_MATERIAL_EXT_STRUCTS_GLSL
#define SHERPA_MATERIAL_EXT_STRUCTS_GLSL
#include "material_extra.glsl"      // GPUTextureTransform
#include "sherpa_material_ext.glsl" // NO_EXTENSION (generated from gpu_structs.h)
#include "transmission_structs.glsl" // the transmission family's blocks

struct GPUExtensionIndex {
    uint ior;      // GPUIorBlock word, or NO_EXTENSION
    uint specular; // GPUSpecularBlock word, or NO_EXTENSION
    uint clearcoat; // GPUClearcoatBlock word, or NO_EXTENSION
    uint sheen;     // GPUSheenBlock word, or NO_EXTENSION
    // Second word: the transmission family (transmission_structs.glsl).
    uint transmission;         // GPUTransmissionBlock word, or NO_EXTENSION
    uint volume;               // GPUVolumeBlock word, or NO_EXTENSION
    uint diffuse_transmission; // GPUDiffuseTransmissionBlock word, or NO_EXTENSION
    uint dispersion;           // GPUDispersionBlock word, or NO_EXTENSION
    // Third word: the microfacet's own shape and film.
    uint anisotropy;  // GPUAnisotropyBlock word, or NO_EXTENSION
    uint iridescence; // GPUIridescenceBlock word, or NO_EXTENSION
    uint pad0;
    uint pad1;
};

struct GPUIorBlock {
    float ior;
    float pad0;
    float pad1;
    float pad2;
};

struct GPUSpecularBlock {
    vec4 color_factor;               // 0: xyz specularColorFactor, w specularFactor
    uint specular_tex;               // 16: A channel
    uint specular_color_tex;         // 20: RGB, sRGB
    uint pad0;                       // 24
    uint pad1;                       // 28
    GPUTextureTransform specular_uv; // 32
    GPUTextureTransform color_uv;    // 64
};

struct GPUClearcoatBlock {
    vec4 factors;                      // 0: x clearcoatFactor, y roughness factor, z normal scale
    uint clearcoat_tex;                // 16: R channel
    uint roughness_tex;                // 20: G channel
    uint normal_tex;                   // 24: tangent-space normal
    uint pad0;                         // 28
    GPUTextureTransform clearcoat_uv;  // 32
    GPUTextureTransform roughness_uv;  // 64
    GPUTextureTransform normal_uv;     // 96
};

struct GPUSheenBlock {
    vec4 factors;                     // 0: xyz sheenColorFactor, w sheenRoughnessFactor
    uint color_tex;                   // 16: RGB, sRGB
    uint roughness_tex;               // 20: A channel
    uint pad0;                        // 24
    uint pad1;                        // 28
    GPUTextureTransform color_uv;     // 32
    GPUTextureTransform roughness_uv; // 64
};

struct GPUIridescenceBlock {
    vec4 factors;                     // 0: x iridescenceFactor, y iridescenceIor, z thickness min, w max (nm)
    uint texture;                     // 16: R channel
    uint thickness_tex;               // 20: G channel
    uint pad0;                        // 24
    uint pad1;                        // 28
    GPUTextureTransform uv;           // 32
    GPUTextureTransform thickness_uv; // 64
};

struct GPUAnisotropyBlock {
    vec4 factors;           // 0: x anisotropyStrength, y cos(anisotropyRotation), z sin(...)
    uint texture;           // 16: RG direction, B strength
    uint pad0;              // 20
    uint pad1;              // 24
    uint pad2;              // 28
    GPUTextureTransform uv; // 32
};

#endif
