// The path tracer's transmission lobe (KHR_materials_transmission, with
// KHR_materials_volume and KHR_materials_dispersion): the glTF layering
//   F spec_brdf + (1 - F) [(1 - T) diffuse + T base spec_btdf]
// where the diffuse is already weighted by (1 - T) in Surface::diffuse and this file
// draws the T base spec_btdf part. A microfacet normal is drawn from GGX's visible
// normals (bsdf_sampling.glsl) and the ray
// - thin-walled (no volume): passes straight on, the reflected direction mirrored
//   through the surface (the specification's thin BTDF), at the same roughness;
// - through a volume: refracts with Snell's law at the ior (entering: 1 / ior; leaving:
//   ior), and is reflected where it cannot leave (total internal reflection).
// The weight of a sample of this lobe is tint (1 - F) G2 / G1, the usual result for
// visible-normal sampling of a microfacet BTDF (Walter et al. 2007; the radiance
// scaling by eta^2 is not applied, as in Cycles' camera paths). F is Schlick at the
// material's F0 and F90, at the angle on the outside of the interface.
// Needs brdf.glsl, bsdf_sampling.glsl.
#ifndef SHERPA_TRANSMISSION_SAMPLING_GLSL
#define SHERPA_TRANSMISSION_SAMPLING_GLSL
#include "volume.glsl"

// Probability of drawing the transmission lobe: its share of the Fresnel-weighted
// albedos at n.v; 0 where the material transmits nothing.
float transmission_probability(Surface s, vec3 tint) {
    if (!any(greaterThan(tint, vec3(0.0)))) return 0.0;
    float n_dot_v = clamp(dot(s.n, s.v), 1e-4, 1.0);
    vec3 f = fresnel_schlick(s.f0, s.f90, n_dot_v);
    float wt = luminance(tint * (1.0 - f));
    float wr = luminance(f) + luminance(s.diffuse * (1.0 - f));
    if (wr <= 0.0) return 1.0; // nothing else to draw
    return clamp(wt / (wt + wr), 0.05, 0.95);
}

float smith_lambda(float n_dot_x, float a) {
    float c2 = max(n_dot_x * n_dot_x, 1e-8);
    return 0.5 * (sqrt(1.0 + a * a * (1.0 - c2) / c2) - 1.0);
}

// A direction through the surface (or, at total internal reflection, back from it) and
// its weight. `ior` is the material's (per wavelength where dispersive); `volume`
// whether light refracts into a volume; `entering` whether the ray arrives from the
// outside (the front face). False: no sample (a microfacet facing away).
bool sample_transmission(Surface s, vec3 tint, float ior, bool volume, bool entering, vec3 t, vec3 b,
                         inout uint rng, out vec3 l, out vec3 weight) {
    vec2 u = vec2(next_random(rng), next_random(rng));
    float a = bsdf_alpha(s);
    vec3 ve = vec3(dot(s.v, t), dot(s.v, b), dot(s.v, s.n));
    vec3 m = sample_ggx_vndf(ve, a, u);
    vec3 h = m.x * t + m.y * b + m.z * s.n;
    float v_dot_h = dot(s.v, h);
    if (v_dot_h <= 0.0) return false;
    float n_dot_v = clamp(dot(s.n, s.v), 1e-4, 1.0);
    float g1 = 1.0 / (1.0 + smith_lambda(n_dot_v, a));
    if (!volume) {
        vec3 r = reflect(-s.v, h);
        float n_dot_r = dot(s.n, r);
        if (n_dot_r <= 0.0) return false;
        l = r - 2.0 * n_dot_r * s.n; // mirrored to the other side
        float g2 = 1.0 / (1.0 + smith_lambda(n_dot_v, a) + smith_lambda(n_dot_r, a));
        weight = tint * (1.0 - fresnel_schlick(s.f0, s.f90, v_dot_h)) * (g2 / g1);
        return true;
    }
    float eta = entering ? 1.0 / ior : ior;
    vec3 refracted = refract(-s.v, h, eta);
    // Schlick on the outer side: the incident angle entering, the transmitted one leaving.
    float c = v_dot_h;
    if (!entering) {
        float sin2_t = eta * eta * (1.0 - v_dot_h * v_dot_h);
        c = sin2_t < 1.0 ? sqrt(1.0 - sin2_t) : 0.0;
    }
    vec3 one_minus_f = 1.0 - fresnel_schlick(s.f0, s.f90, c);
    if (dot(refracted, refracted) == 0.0) { // total internal reflection: it all comes back
        l = reflect(-s.v, h);
        one_minus_f = vec3(1.0);
        if (dot(s.n, l) <= 0.0) return false;
    } else {
        l = normalize(refracted);
        if (dot(s.n, l) >= 0.0) return false;
    }
    float n_dot_l = abs(dot(s.n, l));
    float g2 = 1.0 / (1.0 + smith_lambda(n_dot_v, a) + smith_lambda(n_dot_l, a));
    weight = tint * one_minus_f * (g2 / g1);
    return true;
}

// KHR_materials_diffuse_transmission's BTDF times the cosine for light arriving from l
// on the other side (0 on the viewer's side).
vec3 diffuse_transmission_times_cos(Surface s, vec3 tint, vec3 l) {
    vec3 f = fresnel_schlick(s.f0, s.f90, clamp(dot(s.n, s.v), 1e-4, 1.0));
    return (1.0 - f) * tint * max(-dot(s.n, l), 0.0) / PI;
}

// KHR_materials_diffuse_transmission: a cosine-distributed direction on the other side
// (about -n), weighted by the lobe's tint and (1 - F) at n.v.
bool sample_diffuse_transmission(Surface s, vec3 tint, vec3 t, vec3 b, inout uint rng, out vec3 l,
                                 out vec3 weight) {
    vec2 u = vec2(next_random(rng), next_random(rng));
    float r = sqrt(u.x), phi = 2.0 * PI * u.y;
    l = r * cos(phi) * t + r * sin(phi) * b - sqrt(max(0.0, 1.0 - u.x)) * s.n;
    weight = tint * (1.0 - fresnel_schlick(s.f0, s.f90, clamp(dot(s.n, s.v), 1e-4, 1.0)));
    return dot(s.n, l) < 0.0;
}
#endif
