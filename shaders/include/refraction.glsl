// Screen-space refraction of the raster's lit view (KHR_materials_transmission, with
// KHR_materials_volume's thickness and KHR_materials_dispersion), as the Khronos Sample
// Viewer and three.js draw it: TransmissionPass renders the opaque scene (transmissive
// materials left out) as linear radiance into a mip-mapped target first; a transmissive
// surface samples it where the refracted ray leaves its volume (thickness along the
// refracted direction, scaled by the model; at the surface itself when thin), at a mip
// level that grows with roughness (three.js's log2(width) * roughness * clamp(2 ior - 2,
// 0, 1)). Where the target holds no surface (alpha 0) the environment along the
// refracted ray shows through when the background is the environment.
// Needs common.glsl (frame), ibl.glsl, transmission.glsl.
#ifndef SHERPA_REFRACTION_GLSL
#define SHERPA_REFRACTION_GLSL

// Partially bound: written only in frames whose scene has a transmissive material.
layout(set = 1, binding = 9) uniform sampler2D transmission_background;

float refraction_lod(float roughness, float ior) {
    float width = float(textureSize(transmission_background, 0).x);
    return log2(width) * roughness * clamp(ior * 2.0 - 2.0, 0.0, 1.0);
}

// Where the refracted ray leaves the volume: `thickness` (local units) along the
// refracted direction, each world axis scaled by the model's scale as three.js does.
vec3 refraction_exit(vec3 pos, vec3 n, vec3 v, float ior, float thickness, vec3 model_scale, out vec3 dir) {
    dir = normalize(refract(-v, n, 1.0 / ior));
    return pos + dir * thickness * model_scale;
}

// The transmission background's radiance (rgb) seen through `exit` at `roughness`.
vec3 refraction_sample(vec3 exit, vec3 dir, float roughness, float ior) {
    vec4 clip = frame.view_proj * vec4(exit, 1.0);
    // Clip-space +Y is up (the viewport flips it, draw.cpp's set_viewport); row 0 is the top.
    vec2 uv = vec2(0.5, -0.5) * clip.xy / clip.w + 0.5;
    vec4 t = textureLod(transmission_background, uv, refraction_lod(roughness, ior));
    // The target is cleared to alpha 0 (rgb: the solid background colour, or 0 where
    // the background is the environment, which is added here along the ray).
    if (frame.display.w >= 0.0 && has_environment()) t.rgb += (1.0 - t.a) * ibl_specular(dir, roughness);
    return t.rgb;
}

// Light transmitted through the surface towards the eye before the surface's Fresnel
// and transmission weights: the refracted background times the base colour and the
// volume's Beer-Lambert attenuation over the refracted path (three.js's
// getIBLVolumeRefraction without its (1 - F), which the caller applies).
vec3 refracted_light(vec3 pos, vec3 n, vec3 v, float roughness, float ior, float thickness,
                     vec3 model_scale, vec4 attenuation, float dispersion, vec3 base) {
    vec3 light;
    vec3 dir;
    if (dispersion > 0.0) {
        vec3 iors = dispersion_iors(ior, dispersion);
        for (int i = 0; i < 3; ++i) {
            vec3 exit = refraction_exit(pos, n, v, iors[i], thickness, model_scale, dir);
            light[i] = refraction_sample(exit, dir, roughness, iors[i])[i];
        }
    } else {
        vec3 exit = refraction_exit(pos, n, v, ior, thickness, model_scale, dir);
        light = refraction_sample(exit, dir, roughness, ior);
    }
    float path = length(dir * thickness * model_scale);
    return light * base * beer_lambert(attenuation, path);
}

// The split-sum specular albedo the transmitted light loses to reflection (three.js's
// EnvironmentBRDF): from the environment's table where one is loaded, else Schlick.
vec3 transmission_fresnel(Surface s) {
    float n_dot_v = clamp(dot(s.n, s.v), 1e-4, 1.0);
    if (!has_environment()) return fresnel_schlick(s.f0, s.f90, n_dot_v);
    vec3 lut = ibl_brdf_lut(n_dot_v, clamp(s.roughness, 0.0, 1.0));
    return s.f0 * lut.r + s.f90 * lut.g;
}
#endif
