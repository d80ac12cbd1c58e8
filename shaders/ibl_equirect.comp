#version 460
#extension GL_GOOGLE_include_directive : require
// Equirectangular radiance -> level 0 of the radiance cube.
#include "ibl_sampling.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D equirect;
layout(set = 0, binding = 1, rgba16f) writeonly uniform image2DArray cube;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.face_size || id.y >= push.face_size) return;
    vec3 d = cube_direction(id.z, (vec2(id.xy) + 0.5) / float(push.face_size));
    // Clamped to the cube's half-float range (a 32-bit source is uploaded as it is).
    vec3 c = min(textureLod(equirect, equirect_uv(d), push.equirect_lod).rgb, vec3(65504.0));
    imageStore(cube, ivec3(id), vec4(c, 1.0));
}
