// Shared by the environment's compute passes (ibl_*.comp): cube-face texel directions,
// the equirectangular mapping, low-discrepancy points and the importance sampling of
// the GGX, Lambert and Charlie lobes. Convention: sherpa/render/environment.h.
#ifndef SHERPA_IBL_SAMPLING_GLSL
#define SHERPA_IBL_SAMPLING_GLSL
const float IBL_PI = 3.14159265358979;

// Distributions the prefilter pass integrates (constant DISTRIBUTION).
const uint IBL_GGX = 0u;
const uint IBL_LAMBERT = 1u;
const uint IBL_CHARLIE = 2u;

// C++ twin: GPUIblPush (environment_passes.h).
layout(push_constant, std430) uniform IblPush {
    uint face_size;      // destination texels per side
    uint source_lod;     // downsample: the level read
    float roughness;     // prefilter: perceptual roughness of the level
    uint samples;        // prefilter / LUT: samples per texel
    float source_size;   // prefilter: texels per side of the source cube's level 0
    float source_levels; // prefilter: mip levels of the source cube
    float equirect_lod;  // equirect pass: the source level that matches the face size
    uint pad;
} push;

// Unit direction through texel centre `uv` (0..1) of cube face `face` (+X, -X, +Y,
// -Y, +Z, -Z), as Vulkan's cube sampling selects faces.
vec3 cube_direction(uint face, vec2 uv) {
    vec2 p = uv * 2.0 - 1.0;
    vec3 d;
    switch (face) {
    case 0u: d = vec3(1.0, -p.y, -p.x); break;
    case 1u: d = vec3(-1.0, -p.y, p.x); break;
    case 2u: d = vec3(p.x, 1.0, p.y); break;
    case 3u: d = vec3(p.x, -1.0, -p.y); break;
    case 4u: d = vec3(p.x, -p.y, 1.0); break;
    default: d = vec3(-p.x, -p.y, -1.0); break;
    }
    return normalize(d);
}

// Texture coordinates of direction d in the equirectangular image (row 0 = top, +Y).
vec2 equirect_uv(vec3 d) {
    float u = atan(d.z, d.x) / (2.0 * IBL_PI) + 0.5;
    float v = asin(clamp(d.y, -1.0, 1.0)) / IBL_PI + 0.5;
    return vec2(u, 1.0 - v);
}

vec2 hammersley(uint i, uint n) {
    uint b = bitfieldReverse(i);
    return vec2(float(i) / float(n), float(b) * 2.3283064365386963e-10);
}

// A frame around n: columns tangent, bitangent, n.
mat3 frame_around(vec3 n) {
    vec3 up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = normalize(cross(up, n));
    return mat3(t, cross(n, t), n);
}

float ibl_d_ggx(float n_dot_h, float a) {
    float a2 = a * a;
    float d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (IBL_PI * d * d);
}

#include "charlie.glsl" // ibl_d_charlie, ibl_v_charlie (shared with sheen.glsl)


// Tangent-space half vector (GGX, Charlie) or light direction (Lambert) for sample
// xi, with its solid-angle pdf in w (of the half vector for the microfacet lobes).
vec4 importance_sample(uint distribution, vec2 xi, float a) {
    float cos_t, sin_t, pdf;
    if (distribution == IBL_LAMBERT) {
        cos_t = sqrt(1.0 - xi.y);
        sin_t = sqrt(xi.y);
        pdf = cos_t / IBL_PI;
    } else if (distribution == IBL_GGX) {
        cos_t = clamp(sqrt((1.0 - xi.y) / (1.0 + (a * a - 1.0) * xi.y)), 0.0, 1.0);
        sin_t = sqrt(1.0 - cos_t * cos_t);
        pdf = ibl_d_ggx(cos_t, a) * cos_t;
    } else {
        sin_t = pow(xi.y, a / (2.0 * a + 1.0));
        cos_t = sqrt(1.0 - sin_t * sin_t);
        pdf = ibl_d_charlie(cos_t, a) * cos_t;
    }
    float phi = 2.0 * IBL_PI * xi.x;
    return vec4(sin_t * cos(phi), sin_t * sin(phi), cos_t, pdf);
}

// Height-correlated Smith visibility for GGX (brdf.glsl's v_smith_ggx).
float ibl_v_ggx(float n_dot_l, float n_dot_v, float a) {
    float a2 = a * a;
    float gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
    float gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
    float s = gv + gl;
    return s > 0.0 ? 0.5 / s : 0.0;
}

#endif
