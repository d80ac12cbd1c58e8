// GLSL twins of the transmission family's extension blocks (GPUTransmissionBlock,
// GPUVolumeBlock, GPUDiffuseTransmissionBlock, GPUDispersionBlock in
// engine/render/include/sherpa/render/gpu_structs.h): 16-byte words, offsets pinned
// there and checked by tests/gpu/struct_twins_test.cpp. transmission.glsl reads them.
#ifndef SHERPA_TRANSMISSION_STRUCTS_GLSL
#define SHERPA_TRANSMISSION_STRUCTS_GLSL
#include "material_extra.glsl" // GPUTextureTransform

struct GPUTransmissionBlock {
    float factor;           // 0: transmissionFactor
    uint texture;           // 4: R channel
    uint pad0;              // 8
    uint pad1;              // 12
    GPUTextureTransform uv; // 16
};

struct GPUVolumeBlock {
    vec4 attenuation;                 // 0: xyz attenuationColor, w attenuationDistance (inf: none)
    float thickness_factor;           // 16
    uint thickness_tex;               // 20: G channel
    uint pad0;                        // 24
    uint pad1;                        // 28
    GPUTextureTransform thickness_uv; // 32
};

struct GPUDiffuseTransmissionBlock {
    vec4 color_factor;             // 0: xyz colour factor, w diffuseTransmissionFactor
    uint texture;                  // 16: A channel
    uint color_tex;                // 20: RGB, sRGB
    uint pad0;                     // 24
    uint pad1;                     // 28
    GPUTextureTransform uv;        // 32
    GPUTextureTransform color_uv;  // 64
};

struct GPUDispersionBlock {
    float dispersion;
    float pad0;
    float pad1;
    float pad2;
};
#endif
