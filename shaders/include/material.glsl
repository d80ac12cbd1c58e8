// GLSL twin of sherpa::scene::GPUMaterialData (engine/scene/include/sherpa/scene/material.h).
// std430, 80 bytes; the C++ side pins every offset with static_assert.
#ifndef SHERPA_MATERIAL_GLSL
#define SHERPA_MATERIAL_GLSL

#include "sherpa_alpha_modes.glsl" // SHERPA_ALPHA_*, generated from sherpa::scene::AlphaMode

struct GPUMaterialData {
    vec4 base_color_factor;      // 0
    vec4 emissive_factor;        // 16: xyz factor, w = emissive strength
    float metallic_factor;       // 32
    float roughness_factor;      // 36
    float normal_scale;          // 40
    float occlusion_strength;    // 44
    uint base_color_tex;         // 48: bindless index
    uint emissive_tex;           // 52
    uint metallic_roughness_tex; // 56
    uint normal_tex;             // 60
    uint occlusion_tex;          // 64
    float alpha_cutoff;          // 68
    uint alpha_mode;             // 72
    uint double_sided;           // 76
};

#endif
