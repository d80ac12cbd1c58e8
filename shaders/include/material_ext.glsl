// Material extensions in the raster shaders: the blocks of material_ext_structs.glsl,
// read from one buffer of 16-byte words where only materials that use an extension
// have any. Each block is read word by word in its field order.
//
// Stable functions for every shader that shades materials:
//   GPUExtensionIndex extension_index(GPUMaterialExtra x)
//   GPUIorBlock ior_block(uint word), GPUSpecularBlock specular_block(uint word)
//   float material_ior(GPUExtensionIndex e)                 KHR_materials_ior (1.5 absent)
//   vec4 material_specular(GPUExtensionIndex e, uv0, uv1)   KHR_materials_specular:
//        rgb specular colour, a specular weight (1, 1 absent)
//   void dielectric_fresnel(GPUExtensionIndex e, uv0, uv1, out vec3 f0, out float f90)
//        the dielectric F0 and F90 (brdf.glsl's dielectric_f0) for metal_rough_surface
//   vec3 ior_view_color(float ior)                          the ior debug view
// Needs common.glsl and bindings.glsl; declares set 1, binding 8 unless
// SHERPA_MATERIAL_EXT_DECLARED is defined (a shader that binds the buffer elsewhere
// declares `uvec4 material_ext[]` itself).
#ifndef SHERPA_MATERIAL_EXT_GLSL
#define SHERPA_MATERIAL_EXT_GLSL
#include "material_ext_structs.glsl" // GPUExtensionIndex, GPU*Block, NO_EXTENSION
#include "brdf.glsl"

#ifndef SHERPA_MATERIAL_EXT_DECLARED
// Partially bound: a scene without extensions binds nothing here, and nothing reads it.
layout(set = 1, binding = 8, std430) readonly buffer MaterialExtensionBlock {
    uvec4 material_ext[];
};
#endif

GPUExtensionIndex extension_index(GPUMaterialExtra x) {
    uvec4 w = uvec4(NO_EXTENSION), w1 = uvec4(NO_EXTENSION), w2 = uvec4(NO_EXTENSION);
    if (x.extensions != NO_EXTENSION) {
        w = material_ext[x.extensions];
        w1 = material_ext[x.extensions + 1u];
        w2 = material_ext[x.extensions + 2u];
    }
    return GPUExtensionIndex(w.x, w.y, w.z, w.w, w1.x, w1.y, w1.z, w1.w, w2.x, w2.y, w2.z, w2.w);
}

GPUIorBlock ior_block(uint word) {
    vec4 w = uintBitsToFloat(material_ext[word]);
    return GPUIorBlock(w.x, w.y, w.z, w.w);
}

GPUTextureTransform transform_words(uint word) {
    return GPUTextureTransform(uintBitsToFloat(material_ext[word]), uintBitsToFloat(material_ext[word + 1u]));
}

GPUSpecularBlock specular_block(uint word) {
    uvec4 t = material_ext[word + 1u];
    return GPUSpecularBlock(uintBitsToFloat(material_ext[word]), t.x, t.y, t.z, t.w, transform_words(word + 2u),
                            transform_words(word + 4u));
}

float material_ior(GPUExtensionIndex e) {
    return e.ior == NO_EXTENSION ? 1.5 : ior_block(e.ior).ior;
}

// rgb: specularColorFactor x specularColorTexture.rgb; a: specularFactor x specularTexture.a.
vec4 material_specular(GPUExtensionIndex e, vec2 uv0, vec2 uv1) {
    if (e.specular == NO_EXTENSION) return vec4(1.0);
    GPUSpecularBlock b = specular_block(e.specular);
    vec4 s = b.color_factor;
    if (b.specular_tex != TEX_WHITE) s.a *= sample_transformed(b.specular_uv, b.specular_tex, uv0, uv1).a;
    if (b.specular_color_tex != TEX_WHITE)
        s.rgb *= sample_transformed(b.color_uv, b.specular_color_tex, uv0, uv1).rgb;
    return s;
}

// The dielectric's F0 and F90: 0.04 and 1 without either extension.
void dielectric_fresnel(GPUExtensionIndex e, vec2 uv0, vec2 uv1, out vec3 f0, out float f90) {
    vec4 s = material_specular(e, uv0, uv1);
    f0 = dielectric_f0(material_ior(e), s.a, s.rgb);
    f90 = s.a;
}

// The ior view's colour (data, shown as stored bytes): grey (ior - 1) / 2, ior 0 flagged.
vec3 ior_view_color(float ior) {
    return ior == 0.0 ? SPEC_GLOSS_FLAG : vec3(clamp((ior - 1.0) * 0.5, 0.0, 1.0));
}
#endif
