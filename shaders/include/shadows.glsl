// Cascaded shadow lookup for the main directional light. The cascade is picked by
// view depth; the shadow-map position is computed here from the world position
// (normal offset against acne included) rather than interpolated: three vec3
// varyings per cascade set cost more in triangle setup and interpolation on a CPU
// rasterizer than one selected matrix product per pixel. The comparison sampler
// filters 2x2 texels per tap; params.w taps: 1, 4 (a 2x2 grid half a texel apart)
// or 16 (4x4), FrameRequest::shadow_pcf_taps (default 1 on CPU devices, 4 on GPUs).
// Needs `frame` (frame_block.glsl) and `shadow_map` declared by the includer.
#ifndef SHERPA_SHADOWS_GLSL
#define SHERPA_SHADOWS_GLSL
// The map has one mip level: explicit zero gradients keep the lookup free of
// derivatives, so it may sit in non-uniform control flow.
float shadow_tap(vec2 uv, uint cascade, float depth) {
    return textureGrad(shadow_map, vec4(uv, float(cascade), depth), vec2(0.0), vec2(0.0));
}

// normal: the interpolated vertex normal (world) of the side being shaded (flipped on
// the back of a double-sided surface), any length; a zero one (degenerate
// input) gets no normal offset rather than NaN coordinates.
float sun_shadow(vec3 world, vec3 normal, float view_depth) {
    uint cascades = frame.params.z;
    if (frame.sun_direction.w < 0.5 || cascades == 0u) return 1.0;
    vec3 n = dot(normal, normal) > 0.0 ? normalize(normal) : vec3(0.0);
    vec4 splits = frame.cascade_splits;
    uint c = min(view_depth > splits.x ? (view_depth > splits.y ? 2u : 1u) : 0u, cascades - 1u);
    // Per-pixel selects of uniform values; indexing the array with c would gather.
    mat4 m = c == 0u ? frame.shadow_view_proj[0]
           : c == 1u ? frame.shadow_view_proj[1] : frame.shadow_view_proj[2];
    float texel = c == 0u ? frame.cascade_texel.x : c == 1u ? frame.cascade_texel.y : frame.cascade_texel.z;
    // Normal offset against shadow acne, scaled by the cascade's texel size.
    vec3 p = (m * vec4(world + n * (texel * 1.5), 1.0)).xyz;
    // The shadow pass uses the same flipped viewport as the camera: +Y is the top row.
    vec2 uv = vec2(0.5 + 0.5 * p.x, 0.5 - 0.5 * p.y);
    if (p.z > 1.0) return 1.0; // beyond the light's far plane; outside x/y the border is lit
    if (frame.params.w < 4u) return shadow_tap(uv, c, p.z);
    vec2 texel_uv = 1.0 / vec2(textureSize(shadow_map, 0).xy);
    if (frame.params.w < 16u) {
        vec2 step_uv = 0.5 * texel_uv;
        float lit = 0.0;
        lit += shadow_tap(uv + vec2(-step_uv.x, -step_uv.y), c, p.z);
        lit += shadow_tap(uv + vec2(step_uv.x, -step_uv.y), c, p.z);
        lit += shadow_tap(uv + vec2(-step_uv.x, step_uv.y), c, p.z);
        lit += shadow_tap(uv + vec2(step_uv.x, step_uv.y), c, p.z);
        return lit * 0.25;
    }
    float lit = 0.0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            lit += shadow_tap(uv + (vec2(x, y) - 1.5) * texel_uv, c, p.z);
    return lit * (1.0 / 16.0);
}

// The shadow view's visibility of the sun through the cascades. A surface whose
// normal (the interpolated one of the side shown) faces away from the sun is in
// shadow whatever the maps hold: the ray tracer applies the same rule before its
// shadow rays (rt.rgen), so the two views agree on it.
float sun_visibility(vec3 world, vec3 normal, float view_depth) {
    if (dot(normal, frame.sun_direction.xyz) >= 0.0) return 0.0;
    return sun_shadow(world, normal, view_depth);
}
#endif
