#version 460
#extension GL_GOOGLE_include_directive : require
// The environment behind the scene (sharp, or prefiltered at a roughness: blurred),
// tone-mapped as the lit surfaces are.
#include "common.glsl"
#include "brdf.glsl"
#include "ibl.glsl"
#include "tonemap.glsl"
layout(location = 0) in vec3 in_direction;
layout(location = 0) out vec4 out_color;

void main() {
    vec3 d = env_direction(normalize(in_direction));
    vec3 c = textureLod(ibl_specular_cube, d, frame.display.w).rgb * frame.environment.x;
    out_color = vec4(tone_map(c, uint(frame.display.y), frame.display.x), 1.0);
}
