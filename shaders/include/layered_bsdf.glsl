// The path tracer's BSDF with the material's layers (pt.rgen): the base (brdf.glsl,
// sampled by bsdf_sampling.glsl), under KHR_materials_sheen (sheen.glsl), under
// KHR_materials_clearcoat (clearcoat.glsl), layered exactly as the rasterizer does
// (forward.frag), with one lobe per layer drawn by a one-sample mixture: the coat's
// GGX by its visible normals (Heitz 2018), the sheen by the cosine (the Charlie lobe
// is broad), else the base's lobes; the mixture's density is the sum, for MIS.
// Without layers (coat factor 0, sheen black) every function is the base's alone and
// draws the same random numbers.
// Needs bsdf_sampling.glsl, material_layers.glsl.
#ifndef SHERPA_LAYERED_BSDF_GLSL
#define SHERPA_LAYERED_BSDF_GLSL
#include "material_layers.glsl"

struct Layers {
    Clearcoat coat;
    Sheen sheen;
};

// What the sheen and the coat let through of light `under` that leaves the base toward
// the viewer (their albedos at v), as forward.frag layers the base's radiance: the
// weight of the base's transmission lobes under the layers.
vec3 under_layers(Surface s, Layers y, vec3 under) {
    return layers_over(y.coat, y.sheen, s.n, s.v, under, vec3(0.0), vec3(0.0));
}

vec3 layered_brdf_times_cos(Surface s, Layers y, vec3 l) {
    vec3 f = brdf_times_cos(s, l);
    return layers_over(y.coat, y.sheen, s.n, s.v, f, sheen_times_cos(y.sheen, s.n, s.v, l),
                       vec3(clearcoat_times_cos(y.coat, s.v, l)));
}

// Probability of drawing the coat's lobe: its Fresnel-weighted share, at least a
// fraction of the factor (the coat's sharp highlight is small but bright).
float clearcoat_probability(Clearcoat c, vec3 v) {
    if (c.factor <= 0.0) return 0.0;
    return clamp(c.factor * max(2.0 * clearcoat_fresnel(c, v), 0.2), 0.0, 0.5);
}

// ... and the sheen's (of what the coat leaves).
float sheen_probability(Sheen sh) {
    return max3(sh.color) > 0.0 ? 0.25 : 0.0;
}

float clearcoat_pdf(Clearcoat c, vec3 v, vec3 l) {
    if (dot(c.n, l) <= 0.0) return 0.0;
    float n_dot_v = clamp(abs(dot(c.n, v)), 1e-4, 1.0);
    float a = max(c.roughness * c.roughness, 1e-3);
    float n_dot_h = clamp(dot(c.n, normalize(l + v)), 0.0, 1.0);
    return d_ggx(n_dot_h, a) * smith_g1(n_dot_v, a) / (4.0 * n_dot_v);
}

float layered_pdf(Surface s, Layers y, vec3 l) {
    float pc = clearcoat_probability(y.coat, s.v), ps = sheen_probability(y.sheen);
    float pdf = (1.0 - pc) * (1.0 - ps) * bsdf_pdf(s, l);
    if (pc > 0.0) pdf += pc * clearcoat_pdf(y.coat, s.v, l);
    if (ps > 0.0) pdf += (1.0 - pc) * ps * max(dot(s.n, l), 0.0) / PI;
    return pdf;
}

bool sample_layered(Surface s, Layers y, vec3 t, vec3 b, inout uint rng, out vec3 l) {
    Clearcoat c = y.coat;
    if (c.factor > 0.0 && next_random(rng) < clearcoat_probability(c, s.v)) {
        vec3 ct = t - c.n * dot(c.n, t);
        if (dot(ct, ct) < 1e-8) ct = cross(c.n, abs(c.n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0));
        ct = normalize(ct);
        vec3 cb = cross(c.n, ct);
        vec2 u = vec2(next_random(rng), next_random(rng));
        vec3 ve = vec3(dot(s.v, ct), dot(s.v, cb), dot(s.v, c.n));
        vec3 m = sample_ggx_vndf(ve, max(c.roughness * c.roughness, 1e-3), u);
        l = reflect(-s.v, m.x * ct + m.y * cb + m.z * c.n);
        return dot(c.n, l) > 0.0;
    }
    if (max3(y.sheen.color) > 0.0 && next_random(rng) < sheen_probability(y.sheen)) {
        vec2 u = vec2(next_random(rng), next_random(rng));
        float r = sqrt(u.x), phi = 2.0 * PI * u.y;
        l = r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u.x)) * s.n;
        return dot(s.n, l) > 0.0;
    }
    return sample_bsdf(s, t, b, rng, l);
}
#endif
