// GLSL twin of GPUMaterialExtra (engine/render/include/sherpa/render/gpu_structs.h):
// what GPUMaterialData (material.glsl) has no room for. Offsets are pinned by
// static_asserts on the C++ side; keep the field order identical.
#ifndef SHERPA_MATERIAL_EXTRA_GLSL
#define SHERPA_MATERIAL_EXTRA_GLSL

#include "sherpa_texture_slots.glsl" // SLOT_*, WORKFLOW_*, generated: slots of GPUMaterialExtra.uv

// KHR_texture_transform as two rows of the 2x3 affine UV matrix; row0.w holds the
// TEXCOORD set the slot reads (0 or 1).
struct GPUTextureTransform {
    vec4 row0;
    vec4 row1;
};

struct GPUMaterialExtra {
    GPUTextureTransform uv[SLOT_COUNT]; // 0
    uint unlit;                         // 192: KHR_materials_unlit
    uint workflow;                      // 196: WORKFLOW_*
    uint specular_glossiness_tex;       // 200: KHR_materials_pbrSpecularGlossiness texture
    uint extensions;                    // 204: GPUExtensionIndex word (material_ext.glsl), or NO_EXTENSION
    vec4 specular_glossiness;           // 208: xyz specularFactor, w glossinessFactor
};

vec2 transform_uv(GPUTextureTransform t, vec2 uv0, vec2 uv1) {
    vec3 uv = vec3(t.row0.w > 0.5 ? uv1 : uv0, 1.0);
    return vec2(dot(t.row0.xyz, uv), dot(t.row1.xyz, uv));
}

#endif
