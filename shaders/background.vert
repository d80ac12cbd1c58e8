#version 460
#extension GL_GOOGLE_include_directive : require
// One triangle over the screen at the far plane (reverse-Z depth 0): the background
// where no surface is. Each corner carries its world view direction; directions are
// affine in screen space, so interpolating them and normalising per pixel is exact.
#include "common.glsl"
layout(location = 0) out vec3 out_direction;

void main() {
    vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2)) * 2.0 - 1.0;
    gl_Position = vec4(p, 0.0, 1.0);
    // A point on the near plane (reverse-Z depth 1) through this corner.
    vec4 near = inverse(frame.view_proj) * vec4(p, 1.0, 1.0);
    out_direction = near.xyz / near.w - frame.camera_position.xyz;
}
