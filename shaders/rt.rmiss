#version 460
#extension GL_GOOGLE_include_directive : require
// Nothing hit: the clear colour, as the rasterizer clears its target.
#define SHERPA_RT_RAYGEN
#include "rt_hit.glsl"

layout(location = 0) rayPayloadInEXT vec4 payload;

void main() { payload = vec4(pc.clear_color.rgb, 1.0); }
