#version 460
#extension GL_GOOGLE_include_directive : require
// World-space line lists built on the CPU (instance bounding boxes).
#include "common.glsl"

layout(location = 0) out vec4 out_color;

void main() {
    LineVertex v = pc.lines.v[gl_VertexIndex];
    out_color = v.color;
    gl_Position = frame.view_proj * vec4(v.position.xyz, 1.0);
}
