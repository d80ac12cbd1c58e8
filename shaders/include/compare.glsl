// Shared by compare.comp (difference statistics) and compare.frag (the composited
// image): the two side images, the push constants (GPUComparePush in
// engine/render/include/sherpa/render/gpu_structs.h, pinned there) and the
// per-pixel difference with its heat colour (heat_colour() in comparison.cpp is the
// CPU twin; the legends use it).
#extension GL_EXT_scalar_block_layout : require

layout(set = 0, binding = 0) uniform sampler2D side_a;
layout(set = 0, binding = 1) uniform sampler2D side_b;

const uint COMPARE_SINGLE = 0u;     // side A only (a presented ray-traced frame)
const uint COMPARE_SPLIT = 1u;      // A | divider | B
const uint COMPARE_DIFFERENCE = 2u; // heat map of |A - B|

layout(push_constant, scalar) uniform ComparePush {
    uvec2 side_size;   // both side images
    uvec2 target_size; // the composited target
    uint mode;         // COMPARE_*
    uint target_srgb;  // 1: the target encodes what the fragment shader writes
    float divider_px;  // Split: the divider's x in target pixels
    float heat_max;    // Difference: this byte difference and above is full heat
} pc;

// The sides are read through UNORM views: the sRGB-encoded bytes as stored (what
// render() reads back), so no shader converts them to compare them.
ivec3 bytes_a(ivec2 p) { return ivec3(round(texelFetch(side_a, p, 0).rgb * 255.0)); }
ivec3 bytes_b(ivec2 p) { return ivec3(round(texelFetch(side_b, p, 0).rgb * 255.0)); }

// Black, blue, red, yellow, white over t in 0..1, as bytes.
vec3 heat_bytes(float t) {
    const vec3 stops[5] = vec3[5](vec3(0.0), vec3(0.0, 0.0, 255.0), vec3(255.0, 0.0, 0.0),
                                  vec3(255.0, 255.0, 0.0), vec3(255.0));
    t = clamp(t, 0.0, 1.0) * 4.0;
    const int i = min(3, int(t));
    const float f = t - float(i);
    return floor(stops[i] + f * (stops[i + 1] - stops[i]) + 0.5);
}
