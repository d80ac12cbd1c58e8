// Cascaded shadow lookup for the main directional light: the cascade is chosen by
// view depth, the comparison sampler filters 2x2 texels per tap; 1 tap on CPU
// devices, 4 on GPUs (params.w).
#ifndef SHERPA_SHADOWS_GLSL
#define SHERPA_SHADOWS_GLSL
float sun_shadow(vec3 world_pos, vec3 geo_normal, float view_depth) {
    uint cascades = pc.frame.params.z;
    if (pc.frame.sun_direction.w < 0.5 || cascades == 0u) return 1.0;
    uint c = 0u;
    while (c + 1u < cascades && view_depth > pc.frame.cascade_splits[c]) ++c;
    // Normal offset grows with the cascade's texel size: row 0 of the matrix is the
    // light's unit x axis divided by the cascade's half width.
    mat4 m = pc.frame.shadow_view_proj[c];
    float texel = 2.0 / (length(vec3(m[0][0], m[1][0], m[2][0])) * float(textureSize(shadow_map, 0).x));
    vec3 p = world_pos + geo_normal * texel * 1.5;
    vec4 clip = pc.frame.shadow_view_proj[c] * vec4(p, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    // The shadow pass uses the same flipped viewport as the camera: +Y is the top row.
    vec2 uv = vec2(0.5 + 0.5 * ndc.x, 0.5 - 0.5 * ndc.y);
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
    // One comparison tap already filters 2x2 texels; four taps (GPUs) soften more.
    if (pc.frame.params.w < 4u) return texture(shadow_map, vec4(uv, float(c), ndc.z));
    vec2 step_uv = 0.5 / vec2(textureSize(shadow_map, 0).xy);
    float lit = 0.0;
    lit += texture(shadow_map, vec4(uv + vec2(-step_uv.x, -step_uv.y), float(c), ndc.z));
    lit += texture(shadow_map, vec4(uv + vec2(step_uv.x, -step_uv.y), float(c), ndc.z));
    lit += texture(shadow_map, vec4(uv + vec2(-step_uv.x, step_uv.y), float(c), ndc.z));
    lit += texture(shadow_map, vec4(uv + vec2(step_uv.x, step_uv.y), float(c), ndc.z));
    return lit * 0.25;
}
#endif
