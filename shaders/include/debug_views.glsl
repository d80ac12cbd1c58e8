// Colour encodings of the debug views. Vectors show as 0.5 + 0.5 * v.
#ifndef SHERPA_DEBUG_VIEWS_GLSL
#define SHERPA_DEBUG_VIEWS_GLSL
vec3 encode_vector(vec3 v) { return 0.5 + 0.5 * v; }

// Data views (vectors, UVs, scalars) must show their values as stored bytes, the
// way tools display normal maps; the sRGB target encodes on write, so decode first.
vec3 display_to_linear(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

#ifndef SHERPA_NO_DERIVATIVES // ray-tracing stages have no fwidth
// The uv checker, `density` checks per UV unit, box-filtered over the pixel's UV
// footprint (fwidth): the analytic integral of the square wave, so far or
// minified checks fade to their mean instead of aliasing into moiré. 0 or 1 on
// magnified checks, as mod(floor(u) + floor(v), 2) would be. Call in uniform control flow.
float checker(vec2 uv, float density) {
    vec2 p = uv * density;
    vec2 w = max(fwidth(p), vec2(1e-4));
    vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
    return 0.5 - 0.5 * i.x * i.y;
}

vec3 checker_color(vec2 uv, float density) {
    float k = checker(uv, density);
    // The tint shows which way U (red) and V (green) grow.
    vec3 tint = vec3(fract(uv), 0.0) * 0.5 + 0.25;
    return mix(vec3(0.1), tint + 0.5, k);
}
#endif

// Authored: green, generated: yellow, defaulted: red (render::kProvenanceColors).
vec3 provenance_color(uint p) {
    return PROVENANCE_COLORS[min(p, 2u)];
}

// Angle between geometric and shading normal: blue (0) -> yellow (45) -> red (90+).
vec3 angle_ramp(float radians_) {
    float t = clamp(radians_ / (0.5 * 3.14159265), 0.0, 1.0);
    return t < 0.5 ? mix(vec3(0.1, 0.2, 0.8), vec3(1.0, 0.9, 0.1), t * 2.0)
                   : mix(vec3(1.0, 0.9, 0.1), vec3(0.9, 0.1, 0.05), t * 2.0 - 1.0);
}
// Weight of the selected joint: dark blue 0 -> cyan -> yellow -> red 1.
vec3 heat_ramp(float w) {
    float t = clamp(w, 0.0, 1.0);
    return t < 0.33 ? mix(vec3(0.05, 0.05, 0.35), vec3(0.1, 0.7, 0.9), t / 0.33)
         : t < 0.66 ? mix(vec3(0.1, 0.7, 0.9), vec3(1.0, 0.9, 0.1), (t - 0.33) / 0.33)
                    : mix(vec3(1.0, 0.9, 0.1), vec3(0.9, 0.1, 0.05), (t - 0.66) / 0.34);
}
#endif
