// GLSL twin of sherpa::GPUMaterialData (engine/scene/include/sherpa/scene/material.h)
// and sherpa::gpu::GPUMaterialExtra (engine/gpu/include/sherpa/gpu/gpu_structs.h).
// Offsets are pinned by static_asserts on the C++ side; keep the field order identical.
#ifndef SHERPA_MATERIAL_GLSL
#define SHERPA_MATERIAL_GLSL

struct GPUMaterialData {
    vec4 base_color_factor;      // 0
    vec4 emissive_factor;        // 16: xyz factor, w = emissive strength
    float metallic_factor;       // 32
    float roughness_factor;      // 36
    float normal_scale;          // 40
    float occlusion_strength;    // 44
    uint base_color_tex;         // 48: bindless index (never the sentinel on the GPU)
    uint emissive_tex;           // 52
    uint metallic_roughness_tex; // 56
    uint normal_tex;             // 60
    uint occlusion_tex;          // 64
    float alpha_cutoff;          // 68
    uint alpha_mode;             // 72: 0 opaque, 1 mask, 2 blend
    uint double_sided;           // 76
};

// Texture slots of GPUMaterialExtra.uv, in this order.
const uint SLOT_BASE_COLOR = 0;
const uint SLOT_METALLIC_ROUGHNESS = 1;
const uint SLOT_NORMAL = 2;
const uint SLOT_OCCLUSION = 3;
const uint SLOT_EMISSIVE = 4;

// KHR_texture_transform as two rows of the 2x3 affine UV matrix; row0.w holds the
// TEXCOORD set the slot reads (0 or 1).
struct GPUTextureTransform {
    vec4 row0;
    vec4 row1;
};

struct GPUMaterialExtra {
    GPUTextureTransform uv[5]; // 0
    uint unlit;                // 160: KHR_materials_unlit
    uint pad0, pad1, pad2;     // 164..176
};

#endif
