#version 460
#extension GL_GOOGLE_include_directive : require
// Nothing hit: the ray leaves to the environment (pt.rgen reads it), a shadow ray
// reaches its light.
#define SHERPA_PATH_TRACE
#define SHERPA_RT_RAYGEN
#include "rt_hit.glsl"
#include "path_payload.glsl"

layout(location = 0) rayPayloadInEXT PathPayload payload;

void main() { payload.hit = 0u; }
