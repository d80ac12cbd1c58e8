// GLSL twins of the material extension records (GPUExtensionIndex, GPUIorBlock,
// GPUSpecularBlock in engine/render/include/sherpa/render/gpu_structs.h): 16-byte words,
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
    uint pad0;
    uint pad1;
    // Second word: the transmission family (transmission_structs.glsl).
    uint transmission;         // GPUTransmissionBlock word, or NO_EXTENSION
    uint volume;               // GPUVolumeBlock word, or NO_EXTENSION
    uint diffuse_transmission; // GPUDiffuseTransmissionBlock word, or NO_EXTENSION
    uint dispersion;           // GPUDispersionBlock word, or NO_EXTENSION
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

#endif
