// Sampling of brdf.glsl's glTF BRDF for the path tracer: the density of a direction
// and a way to draw one, so that brdf_times_cos(s, l) / bsdf_pdf(s, l) is an unbiased
// estimate of the BRDF's integral. Two lobes drawn by one-sample mixture: the GGX
// specular by its distribution of visible normals (Heitz 2018, "Sampling the GGX
// Distribution of Visible Normals") and the diffuse by the cosine; the mixture's
// density covers every direction where the BRDF is non-zero.
// Needs brdf.glsl (Surface, d_ggx, fresnel_schlick).
#ifndef SHERPA_BSDF_SAMPLING_GLSL
#define SHERPA_BSDF_SAMPLING_GLSL

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// PCG hash (Jarzynski and Olano 2020): the path tracer's only source of randomness,
// so a pixel's samples depend on its position, the sample index and the seed alone.
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Uniform in [0, 1).
float next_random(inout uint state) {
    state = pcg_hash(state);
    return float(state >> 8u) * (1.0 / 16777216.0);
}

// The roughness brdf_times_cos evaluates GGX with.
float bsdf_alpha(Surface s) { return max(s.roughness * s.roughness, 1e-3); }

// Probability of drawing the specular lobe: its Fresnel-weighted share at n.v.
float specular_probability(Surface s) {
    float n_dot_v = clamp(dot(s.n, s.v), 1e-4, 1.0);
    vec3 f = fresnel_schlick(s.f0, n_dot_v);
    float ws = luminance(f), wd = luminance(s.diffuse * (1.0 - f));
    if (wd <= 0.0) return 1.0;
    if (ws <= 0.0) return 0.0;
    return clamp(ws / (ws + wd), 0.1, 0.9);
}

// Smith G1 of GGX for the view direction.
float smith_g1(float n_dot_v, float a) {
    float a2 = a * a;
    return 2.0 * n_dot_v / (n_dot_v + sqrt(a2 + (1.0 - a2) * n_dot_v * n_dot_v));
}

// Density (per solid angle) of drawing l from surface s.
float bsdf_pdf(Surface s, vec3 l) {
    float n_dot_l = dot(s.n, l);
    if (n_dot_l <= 0.0) return 0.0;
    float n_dot_v = clamp(abs(dot(s.n, s.v)), 1e-4, 1.0);
    vec3 h = normalize(l + s.v);
    float n_dot_h = clamp(dot(s.n, h), 0.0, 1.0);
    float p_spec = specular_probability(s);
    float spec;
    if (s.anisotropy.w > 0.0) { // KHR_materials_anisotropy: D(h) G1(v) / (4 n.v) as well
        vec3 t = anisotropy_direction(s), b = cross(s.n, t);
        vec2 a = anisotropic_alpha(s.roughness, s.anisotropy.w);
        float lambda_v = length(vec3(a.x * dot(t, s.v), a.y * dot(b, s.v), n_dot_v));
        float g1 = 2.0 * n_dot_v / (n_dot_v + lambda_v);
        spec = d_ggx_anisotropic(vec3(dot(t, h), dot(b, h), n_dot_h), a) * g1 / (4.0 * n_dot_v);
    } else {
        float a = bsdf_alpha(s);
        spec = d_ggx(n_dot_h, a) * smith_g1(n_dot_v, a) / (4.0 * n_dot_v);
    }
    return p_spec * spec + (1.0 - p_spec) * n_dot_l / PI;
}

// A visible normal in the local frame (z the normal) for local view ve, with alpha
// a.x along x and a.y along y (Heitz 2018; anisotropic where they differ).
vec3 sample_ggx_vndf(vec3 ve, vec2 a, vec2 u) {
    vec3 vh = normalize(vec3(a.x * ve.x, a.y * ve.y, ve.z));
    float len2 = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = len2 > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(len2) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u.x), phi = 2.0 * PI * u.y;
    float p1 = r * cos(phi), p2 = r * sin(phi);
    float blend = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - blend) * sqrt(max(0.0, 1.0 - p1 * p1)) + blend * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return normalize(vec3(a.x * nh.x, a.y * nh.y, max(0.0, nh.z)));
}

vec3 sample_ggx_vndf(vec3 ve, float a, vec2 u) {
    return sample_ggx_vndf(ve, vec2(a), u);
}

// Draws a direction from s (false: none, e.g. a reflection below the surface).
bool sample_bsdf(Surface s, vec3 t, vec3 b, inout uint rng, out vec3 l) {
    float choose = next_random(rng);
    vec2 u = vec2(next_random(rng), next_random(rng));
    if (choose < specular_probability(s)) {
        vec2 a = vec2(bsdf_alpha(s));
        if (s.anisotropy.w > 0.0) { // the anisotropy's own frame and alphas
            t = anisotropy_direction(s);
            b = cross(s.n, t);
            a = anisotropic_alpha(s.roughness, s.anisotropy.w);
        }
        vec3 ve = vec3(dot(s.v, t), dot(s.v, b), dot(s.v, s.n));
        vec3 m = sample_ggx_vndf(ve, a, u);
        vec3 h = m.x * t + m.y * b + m.z * s.n;
        l = reflect(-s.v, h);
    } else {
        float r = sqrt(u.x), phi = 2.0 * PI * u.y;
        l = r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u.x)) * s.n;
    }
    return dot(s.n, l) > 0.0;
}

// Power heuristic (beta 2) weight of a strategy of density a against one of density b.
float mis_weight(float a, float b) {
    float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}
#endif
