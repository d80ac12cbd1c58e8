// The path tracer's environment: radiance from any direction and importance sampling
// of it by its luminance (C++ side: environment_sampling.h builds the distribution from
// the equirectangular image at load). Radiance is read from level 0 of the specular
// cube (the sharp environment, what the raster's background shows), times the
// intensity, turned by the rotation (ibl.glsl's env_direction). Without an environment
// the raster's sky/ground ambient term (brdf.glsl's hemisphere()) is the sky.
// Needs frame_block.glsl, brdf.glsl, pt push constants (pc.env_size).
#ifndef SHERPA_ENV_SAMPLING_GLSL
#define SHERPA_ENV_SAMPLING_GLSL

layout(set = 1, binding = 5) uniform samplerCube env_cube;
// Row marginal CDF (rows + 1 values, rows top first), then each row's conditional CDF
// over its columns (columns + 1 values each). Texel weights are luminance x sin(theta).
layout(set = 1, binding = 8, std430) readonly buffer EnvironmentDistribution {
    float env_cdf[];
};

bool has_environment() { return frame.environment.y > 0.0; }

vec3 env_direction(vec3 d) {
    float c = frame.environment.z, s = frame.environment.w;
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

vec3 world_direction(vec3 e) { // env_direction's inverse
    float c = frame.environment.z, s = frame.environment.w;
    return vec3(c * e.x + s * e.z, e.y, -s * e.x + c * e.z);
}

// Radiance arriving along -dir (what a ray toward dir sees), at a specular level.
vec3 environment_radiance(vec3 dir, float level) {
    if (!has_environment()) return hemisphere(dir, frame.ambient.rgb);
    return textureLod(env_cube, env_direction(dir), level).rgb * frame.environment.x;
}

bool env_importance() { return has_environment() && pc.env_size.x > 0u && pc.env_size.y > 0u; }

// First index i in [first, first + count) with env_cdf[i + 1] > x (a CDF segment).
uint cdf_segment(uint first, uint count, float x) {
    uint lo = 0u, hi = count - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (env_cdf[first + mid + 1u] > x) hi = mid;
        else lo = mid + 1u;
    }
    return lo;
}

// Density per solid angle of environment_sample() drawing world direction dir.
float environment_pdf(vec3 dir) {
    if (!env_importance()) return 0.0;
    const uint w = pc.env_size.x, h = pc.env_size.y;
    vec3 e = env_direction(dir);
    float u = atan(e.z, e.x) / (2.0 * PI) + 0.5;
    float theta = acos(clamp(e.y, -1.0, 1.0)); // 0 at the top row
    uint col = min(uint(u * float(w)), w - 1u), row = min(uint(theta / PI * float(h)), h - 1u);
    float p_row = env_cdf[row + 1u] - env_cdf[row];
    uint base = h + 1u + row * (w + 1u);
    float p_col = env_cdf[base + col + 1u] - env_cdf[base + col];
    float sin_theta = sin(theta);
    if (sin_theta <= 0.0) return 0.0;
    return p_row * p_col * float(w * h) / (2.0 * PI * PI * sin_theta);
}

// A world direction drawn in proportion to the environment's luminance.
vec3 environment_sample(inout uint rng, out float pdf) {
    const uint w = pc.env_size.x, h = pc.env_size.y;
    float x = next_random(rng), y = next_random(rng);
    uint row = cdf_segment(0u, h, x);
    uint base = h + 1u + row * (w + 1u);
    uint col = cdf_segment(base, w, y);
    // Uniform within the texel (the density is constant over it in (u, v)).
    float u = (float(col) + next_random(rng)) / float(w);
    float theta = PI * (float(row) + next_random(rng)) / float(h);
    float phi = 2.0 * PI * (u - 0.5);
    vec3 e = vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
    vec3 dir = world_direction(e);
    pdf = environment_pdf(dir);
    return dir;
}
#endif
