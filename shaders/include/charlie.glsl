// The Charlie sheen microfacet distribution (Estevez and Kulla 2017) and the
// KHR_materials_sheen specification's fitted visibility: the one copy, read by the
// environment's lookup table (ibl_lut.comp via ibl_sampling.glsl) and by the sheen's
// shading (sheen.glsl). `a` is the roughness squared. No dependencies.
#ifndef SHERPA_CHARLIE_GLSL
#define SHERPA_CHARLIE_GLSL
const float CHARLIE_PI = 3.14159265358979;

// Charlie sheen distribution (Estevez and Kulla), a = roughness^2.
float ibl_d_charlie(float n_dot_h, float a) {
    float inv_r = 1.0 / max(a, 1e-4);
    float sin2 = max(1.0 - n_dot_h * n_dot_h, 0.0);
    return (2.0 + inv_r) * pow(sin2, inv_r * 0.5) / (2.0 * CHARLIE_PI);
}

// KHR_materials_sheen's visibility: Charlie's Lambda, fitted (a = roughness^2).
float sheen_l(float x, float a) {
    float t = (1.0 - a) * (1.0 - a);
    float p = mix(21.5473, 25.3245, t), q = mix(3.82987, 3.32435, t), r = mix(0.19823, 0.16801, t);
    float s = mix(-1.97760, -1.27393, t), u = mix(-4.32054, -4.85967, t);
    return p / (1.0 + q * pow(x, r)) + s * x + u;
}
float sheen_lambda(float cos_t, float a) {
    return abs(cos_t) < 0.5 ? exp(sheen_l(cos_t, a)) : exp(2.0 * sheen_l(0.5, a) - sheen_l(1.0 - cos_t, a));
}
float ibl_v_charlie(float n_dot_l, float n_dot_v, float a) {
    return clamp(1.0 / ((1.0 + sheen_lambda(n_dot_v, a) + sheen_lambda(n_dot_l, a)) *
                        (4.0 * n_dot_v * n_dot_l)), 0.0, 1.0);
}
#endif
