// Emissive triangles as lights (the path tracer's raygen; C++ side and twin of the
// record: sherpa/render/emissive_lights.h): a triangle drawn in proportion to its power
// (its emissive texture's mean over it included) through the CDF in p0_cdf.w, a point
// uniformly on it. Partially bound: read only while
// pc.light_inv_power > 0 (a scene with a light list).
#ifndef SHERPA_EMISSIVE_LIGHTS_GLSL
#define SHERPA_EMISSIVE_LIGHTS_GLSL

struct GPUEmissiveTriangle {
    vec4 p0_cdf;     // xyz first corner (world), w CDF up to and including this triangle
    vec4 e1_density; // xyz p1 - p0, w density per area of drawing a point on it
    vec4 e2;         // xyz p2 - p0
    vec4 emission;   // x material luminance (the MIS weights' density), y estimated luminance
};

layout(set = 1, binding = 10, std430) readonly buffer EmissiveTriangleBlock {
    GPUEmissiveTriangle emissive_triangles[];
};

bool has_emissive_lights() {
    return pc.light_inv_power > 0.0;
}

// A point `y` on an emissive triangle drawn by power, its unit face normal, its density
// per area (the probability of its triangle over the triangle's area), the density per
// area the multiple-importance weights use (its material's luminance over the list's
// material power: what the closest hit computes for a BSDF-sampled hit; any pair of
// weights that sums to 1 keeps the estimate unbiased) and the triangle's estimated
// emitted luminance.
void sample_emissive(inout uint rng, out vec3 y, out vec3 normal, out float density, out float mis_density,
                     out float emitted) {
    const float u = next_random(rng);
    uint lo = 0u, hi = uint(emissive_triangles.length()) - 1u;
    while (lo < hi) {
        const uint mid = (lo + hi) / 2u;
        if (emissive_triangles[mid].p0_cdf.w <= u) lo = mid + 1u;
        else hi = mid;
    }
    const GPUEmissiveTriangle t = emissive_triangles[lo];
    const float su = sqrt(next_random(rng)), v = next_random(rng);
    y = t.p0_cdf.xyz + (1.0 - v) * su * t.e1_density.xyz + v * su * t.e2.xyz;
    normal = normalize(cross(t.e1_density.xyz, t.e2.xyz));
    density = t.e1_density.w;
    mis_density = t.emission.x * pc.light_inv_power;
    emitted = t.emission.y;
}

// The density per solid angle of reaching a point of emitted luminance `lum` through
// light sampling, `dist2` away, seen at cosine `cos_light` to its face.
float emissive_pdf(float lum, float dist2, float cos_light) {
    return cos_light > 0.0 ? lum * pc.light_inv_power * dist2 / cos_light : 0.0;
}

// The power heuristic without overflow: a / (a + b) of squares.
float power_weight(float a, float b) {
    if (!(a > 0.0)) return 0.0;
    const float r = b / a;
    return 1.0 / (1.0 + r * r);
}
#endif
