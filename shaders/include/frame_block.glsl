// The per-frame constants (C++ twin: GPUFrameData, gpu_structs.h): set 1, binding 0
// in the raster shaders (common.glsl); the ray tracer binds the rasterizer's frame of
// the same camera at SHERPA_FRAME_BINDING to compare against its shadow maps.
#ifndef SHERPA_FRAME_BLOCK_GLSL
#define SHERPA_FRAME_BLOCK_GLSL
#ifndef SHERPA_FRAME_BINDING
#define SHERPA_FRAME_BINDING 0
#endif

// sherpa_*.glsl: generated at build time from the C++ definitions (gpu_structs.h,
// debug_views.h) by engine/gpu/tools/glsl_constants.cpp.
#include "sherpa_frame_limits.glsl" // MAX_LIGHTS, MAX_CASCADES, SHADOW_CASCADES

struct GPULight {
    vec4 position_range;  // xyz world position, w range (0 = infinite)
    vec4 direction_type;  // xyz direction the light points, w type (0 dir, 1 point, 2 spot)
    vec4 color_intensity; // rgb colour, w intensity
    vec4 cone;            // x cos(outer), y cos(inner)
};

// Per-frame constants and materials come through descriptors, not buffer device
// addresses: a CPU rasterizer (lavapipe) turns these uniform-indexed loads into one
// scalar load per draw, where a pointer load costs a gather per pixel.
layout(set = 1, binding = SHERPA_FRAME_BINDING, std140) uniform FrameBlock {
    mat4 view;                              // 0
    mat4 proj;                              // 64
    mat4 view_proj;                         // 128
    mat4 shadow_view_proj[MAX_CASCADES];    // 192
    vec4 camera_position;                   // 448
    vec4 cascade_splits;                    // 464: view depth where each cascade ends
    vec4 sun_direction;                     // 480: xyz direction light travels, w 1 = shadowed
    vec4 sun_radiance;                      // 496: rgb colour * intensity
    vec4 ambient;                           // 512: rgb ambient radiance
    uvec4 params;                           // 528: x view, y lights, z cascades, w shadow taps
    vec4 overlay;                           // 544: x glyph length, y uv checks per unit, z texture LOD
    vec4 cascade_texel;                     // 560: world size of a shadow texel per cascade
    GPULight lights[MAX_LIGHTS];            // 576
    // After the lights: x intensity, y specular levels (0: no environment), z, w
    // cos and sin of its rotation about +Y (ibl.glsl).
    vec4 environment;
    // x exposure scale 2^EV, y tone map (TONE_MAP_*), z 1 = energy compensation on,
    // w the background's specular level (< 0: a solid colour, no background pass).
    vec4 display;
    // Irradiance / pi as 9 SH coefficients (rgb), read instead of the irradiance cube
    // where irradiance_sh[0].w is 1 (ibl.glsl's ibl_irradiance); irradiance_sh[1].w is
    // KHR_materials_anisotropy's lighting (ibl.glsl's anisotropy_lighting).
    vec4 irradiance_sh[9];
} frame;
#endif
