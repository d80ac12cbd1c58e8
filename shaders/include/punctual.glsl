// KHR_lights_punctual: the radiance a light sends to a point, shared by the raster's
// lit shading (forward.frag) and the path tracer's next-event estimation (pt.rgen).
// Needs frame_block.glsl (GPULight).
#ifndef SHERPA_PUNCTUAL_GLSL
#define SHERPA_PUNCTUAL_GLSL

// Radiance (irradiance on a surface facing it) from `light` at `pos`; `l` the unit
// direction toward the light, `dist` its distance (1e30 for directional lights).
vec3 punctual_incident(GPULight light, vec3 pos, out vec3 l, out float dist) {
    uint type = uint(light.direction_type.w);
    vec3 radiance = light.color_intensity.rgb * light.color_intensity.w;
    dist = 1e30;
    if (type == 0u) {
        l = -normalize(light.direction_type.xyz);
        return radiance;
    }
    vec3 d = light.position_range.xyz - pos;
    float dist2 = max(dot(d, d), 1e-8);
    dist = sqrt(dist2);
    l = d * inversesqrt(dist2);
    float range = light.position_range.w;
    // KHR_lights_punctual recommended range falloff.
    float falloff = range > 0.0 ? clamp(1.0 - pow(dist2 / (range * range), 2.0), 0.0, 1.0) : 1.0;
    radiance *= falloff / dist2;
    if (type == 2u) {
        float cd = dot(normalize(light.direction_type.xyz), -l);
        float t = clamp((cd - light.cone.x) / max(light.cone.y - light.cone.x, 1e-4), 0.0, 1.0);
        radiance *= t * t;
    }
    return radiance;
}
#endif
