// The transmission family of material extensions, read from the extension buffer
// (material_ext.glsl) by the raster (forward.frag, refraction.glsl) and the path tracer
// (pt.rchit): KHR_materials_transmission, _volume, _diffuse_transmission, _dispersion.
//
// Stable functions:
//   float material_transmission(GPUExtensionIndex e, uv0, uv1)   factor x texture.r; 0 absent
//   float material_thickness(e, uv0, uv1)      thicknessFactor x texture.g (local units); 0 absent
//   vec4 material_attenuation(e)               rgb attenuationColor, a attenuationDistance (inf)
//   vec4 material_diffuse_transmission(e, uv0, uv1)  rgb colour, a factor; (1, 0) absent
//   float material_dispersion(e)               0 absent
//   vec3 beer_lambert(vec4 attenuation, float distance)   transmittance over `distance`
//   vec3 dispersion_iors(float ior, float dispersion)     per-channel ior (r, g, b)
//   vec3 attenuation_view_color(vec4 attenuation)  the attenuation debug view
// Needs material_ext.glsl (and sample_transformed()).
#ifndef SHERPA_TRANSMISSION_GLSL
#define SHERPA_TRANSMISSION_GLSL
#include "material_ext.glsl"
#include "volume.glsl" // beer_lambert, dispersion_iors

vec4 ext_word(uint word) { return uintBitsToFloat(material_ext[word]); }

GPUTransmissionBlock transmission_block(uint word) {
    uvec4 a = material_ext[word];
    return GPUTransmissionBlock(uintBitsToFloat(a.x), a.y, a.z, a.w, transform_words(word + 1u));
}

GPUVolumeBlock volume_block(uint word) {
    uvec4 b = material_ext[word + 1u];
    return GPUVolumeBlock(ext_word(word), uintBitsToFloat(b.x), b.y, b.z, b.w, transform_words(word + 2u));
}

GPUDiffuseTransmissionBlock diffuse_transmission_block(uint word) {
    uvec4 b = material_ext[word + 1u];
    return GPUDiffuseTransmissionBlock(ext_word(word), b.x, b.y, b.z, b.w, transform_words(word + 2u),
                                       transform_words(word + 4u));
}

float material_transmission(GPUExtensionIndex e, vec2 uv0, vec2 uv1) {
    if (e.transmission == NO_EXTENSION) return 0.0;
    GPUTransmissionBlock b = transmission_block(e.transmission);
    float t = b.factor;
    if (b.texture != TEX_WHITE && t > 0.0) t *= sample_transformed(b.uv, b.texture, uv0, uv1).r;
    return clamp(t, 0.0, 1.0);
}

float material_thickness(GPUExtensionIndex e, vec2 uv0, vec2 uv1) {
    if (e.volume == NO_EXTENSION) return 0.0;
    GPUVolumeBlock b = volume_block(e.volume);
    float t = b.thickness_factor;
    if (b.thickness_tex != TEX_WHITE && t > 0.0)
        t *= sample_transformed(b.thickness_uv, b.thickness_tex, uv0, uv1).g;
    return max(t, 0.0);
}

vec4 material_attenuation(GPUExtensionIndex e) {
    if (e.volume == NO_EXTENSION) return vec4(1.0, 1.0, 1.0, uintBitsToFloat(0x7f800000u));
    return ext_word(e.volume);
}

vec4 material_diffuse_transmission(GPUExtensionIndex e, vec2 uv0, vec2 uv1) {
    if (e.diffuse_transmission == NO_EXTENSION) return vec4(1.0, 1.0, 1.0, 0.0);
    GPUDiffuseTransmissionBlock b = diffuse_transmission_block(e.diffuse_transmission);
    vec4 d = b.color_factor;
    if (b.texture != TEX_WHITE && d.a > 0.0) d.a *= sample_transformed(b.uv, b.texture, uv0, uv1).a;
    if (b.color_tex != TEX_WHITE) d.rgb *= sample_transformed(b.color_uv, b.color_tex, uv0, uv1).rgb;
    return clamp(d, 0.0, 1.0);
}

float material_dispersion(GPUExtensionIndex e) {
    return e.dispersion == NO_EXTENSION ? 0.0 : ext_word(e.dispersion).x;
}

// The attenuation view: the transmittance after one attenuationDistance (its colour)
// where the distance is finite, white where it is infinite (no attenuation).
vec3 attenuation_view_color(vec4 attenuation) {
    return isinf(attenuation.w) ? vec3(1.0) : attenuation.rgb;
}
#endif
