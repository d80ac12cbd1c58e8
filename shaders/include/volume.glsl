// KHR_materials_volume and KHR_materials_dispersion as pure functions, shared by the
// raster (refraction.glsl) and the path tracer (pt.rgen):
//   vec3 beer_lambert(vec4 attenuation, float distance)   transmittance over `distance`
//   vec3 dispersion_iors(float ior, float dispersion)     per-channel ior (r, g, b)
#ifndef SHERPA_VOLUME_GLSL
#define SHERPA_VOLUME_GLSL
// Beer-Lambert: attenuationColor is the transmittance at attenuationDistance, so over
// `distance` it is colour^(distance / attenuationDistance). An infinite distance (the
// default) attenuates nothing; a zero colour channel absorbs all of that channel.
vec3 beer_lambert(vec4 attenuation, float distance) {
    if (isinf(attenuation.w) || distance <= 0.0) return vec3(1.0);
    return pow(max(attenuation.rgb, vec3(0.0)), vec3(distance / attenuation.w));
}

// KHR_materials_dispersion: the spread of ior over the visible range from the Abbe
// number V = 20 / dispersion, about the ior at the d line (587.6 nm), at the red
// (656.3 nm, C line), green (the d line) and blue (486.1 nm, F line) wavelengths:
// n(F) - n(C) = (n_d - 1) / V, split symmetrically: (ior - 1) * 0.025 * dispersion on
// each side, the spread three.js's getIBLVolumeRefraction uses.
vec3 dispersion_iors(float ior, float dispersion) {
    float half_spread = (ior - 1.0) * 0.025 * dispersion;
    return vec3(ior - half_spread, ior, ior + half_spread);
}

#endif
