#version 460
#extension GL_GOOGLE_include_directive : require
// One mip level of the radiance cube from the level above: a bilinear tap at the
// centre of each destination texel averages its 2x2 source texels.
#include "ibl_sampling.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform samplerCube source;
layout(set = 0, binding = 1, rgba16f) writeonly uniform image2DArray cube;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.face_size || id.y >= push.face_size) return;
    vec3 d = cube_direction(id.z, (vec2(id.xy) + 0.5) / float(push.face_size));
    imageStore(cube, ivec3(id), vec4(textureLod(source, d, float(push.source_lod)).rgb, 1.0));
}
