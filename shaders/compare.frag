#version 460
// The composited target of a comparison (comparison_pass.cpp): side A alone (a
// presented ray-traced frame), Split (A left of the divider, B right of it, a
// two-pixel line between) or Difference (heat of the largest byte difference over
// R, G, B, full at pc.heat_max). Sides are fetched nearest (a reduced-resolution
// frame scales up as a nearest blit does); output is written as the bytes the
// sides hold, decoded for sRGB targets so that the target encodes them back.
#extension GL_GOOGLE_include_directive : require
#include "compare.glsl"

layout(location = 0) out vec4 out_color;

const vec3 DIVIDER = vec3(255.0, 200.0, 40.0); // amber bytes

float decode_srgb(float e) {
    return e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4);
}

void main() {
    const vec2 at = gl_FragCoord.xy;
    const ivec2 p = min(ivec2(at * vec2(pc.side_size) / vec2(pc.target_size)),
                        ivec2(pc.side_size) - 1);
    vec3 bytes;
    if (pc.mode == COMPARE_DIFFERENCE) {
        const ivec3 d = abs(bytes_a(p) - bytes_b(p));
        bytes = heat_bytes(float(max(d.r, max(d.g, d.b))) / max(pc.heat_max, 1e-6));
    } else if (pc.mode == COMPARE_SPLIT && abs(at.x - pc.divider_px) < 1.0) {
        bytes = DIVIDER;
    } else if (pc.mode == COMPARE_SPLIT && at.x >= pc.divider_px) {
        bytes = vec3(bytes_b(p));
    } else {
        bytes = vec3(bytes_a(p));
    }
    vec3 c = bytes / 255.0;
    if (pc.target_srgb != 0u) c = vec3(decode_srgb(c.r), decode_srgb(c.g), decode_srgb(c.b));
    out_color = vec4(c, 1.0);
}
