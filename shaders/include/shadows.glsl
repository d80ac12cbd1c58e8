// Cascaded shadow lookup for the main directional light. The vertex stage gives
// the shadow-map position in every cascade (normal offset included); the cascade
// is picked by view depth. The comparison sampler filters 2x2 texels per tap;
// 1 tap on CPU devices, 4 on GPUs (params.w).
#ifndef SHERPA_SHADOWS_GLSL
#define SHERPA_SHADOWS_GLSL
float sun_shadow(vec3 shadow_pos[SHADOW_CASCADES], float view_depth) {
    uint cascades = frame.params.z;
    if (frame.sun_direction.w < 0.5 || cascades == 0u) return 1.0;
    vec4 splits = frame.cascade_splits;
    uint c = min(view_depth > splits.x ? (view_depth > splits.y ? 2u : 1u) : 0u, cascades - 1u);
    vec3 p = c == 0u ? shadow_pos[0] : c == 1u ? shadow_pos[1] : shadow_pos[2];
    // The shadow pass uses the same flipped viewport as the camera: +Y is the top row.
    vec2 uv = vec2(0.5 + 0.5 * p.x, 0.5 - 0.5 * p.y);
    if (p.z > 1.0) return 1.0; // beyond the light's far plane; outside x/y the border is lit
    if (frame.params.w < 4u) return texture(shadow_map, vec4(uv, float(c), p.z));
    vec2 step_uv = 0.5 / vec2(textureSize(shadow_map, 0).xy);
    float lit = 0.0;
    lit += texture(shadow_map, vec4(uv + vec2(-step_uv.x, -step_uv.y), float(c), p.z));
    lit += texture(shadow_map, vec4(uv + vec2(step_uv.x, -step_uv.y), float(c), p.z));
    lit += texture(shadow_map, vec4(uv + vec2(-step_uv.x, step_uv.y), float(c), p.z));
    lit += texture(shadow_map, vec4(uv + vec2(step_uv.x, step_uv.y), float(c), p.z));
    return lit * 0.25;
}
#endif
