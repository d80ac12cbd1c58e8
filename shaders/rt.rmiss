#version 460
#extension GL_GOOGLE_include_directive : require
// Nothing hit: the clear colour, as the rasterizer clears its target; a shadow or
// occlusion ray that reaches here is unblocked.
#define SHERPA_RT_RAYGEN
#include "rt_hit.glsl"

layout(location = 0) rayPayloadInEXT RayPayload payload;

void main() {
    payload.color = vec4(pc.clear_color.rgb, 1.0);
    payload.hit = 0u;
}
