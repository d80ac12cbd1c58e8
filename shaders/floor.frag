#version 460
#extension GL_GOOGLE_include_directive : require
// The trivial shader: one constant colour (benchmark floor, wireframe overlay).
#include "common.glsl"

layout(location = 0) out vec4 out_color;

void main() { out_color = pc.color; }
