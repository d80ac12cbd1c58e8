#version 460
#extension GL_GOOGLE_include_directive : require
// One level of a prefiltered cube: the radiance cube integrated against a lobe
// (constant DISTRIBUTION: GGX specular, Lambert irradiance, Charlie sheen) around
// each texel's direction, with n = v = r (split-sum). Filtered importance sampling
// (Krivanek and Colbert): each sample reads the source level whose texel covers its
// share of the solid angle, so few samples give a smooth result. The weights are
// normalised: a uniform environment stays exactly uniform (the furnace test). GGX at
// roughness 0 (the sharp level) is a copy of the source, made by EnvironmentMap.
#include "ibl_sampling.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const uint DISTRIBUTION = IBL_GGX;
layout(set = 0, binding = 0) uniform samplerCube source;
layout(set = 0, binding = 1, rgba16f) writeonly uniform image2DArray cube;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.face_size || id.y >= push.face_size) return;
    vec3 n = cube_direction(id.z, (vec2(id.xy) + 0.5) / float(push.face_size));
    float a = push.roughness * push.roughness;
    mat3 tbn = frame_around(n);
    // Solid angle of one source texel at level 0.
    float texel_solid_angle = 4.0 * IBL_PI / (6.0 * push.source_size * push.source_size);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (uint i = 0u; i < push.samples; ++i) {
        vec4 s = importance_sample(DISTRIBUTION, hammersley(i, push.samples), a);
        vec3 l;
        float pdf, w;
        if (DISTRIBUTION == IBL_LAMBERT) {
            l = tbn * s.xyz;
            pdf = s.w;
            w = 1.0; // cosine-distributed: the plain mean is the cosine-weighted mean
        } else {
            vec3 h = tbn * s.xyz;
            l = 2.0 * dot(n, h) * h - n;
            float n_dot_l = dot(n, l);
            if (n_dot_l <= 0.0) continue;
            pdf = s.w / 4.0; // of l, with v = n: pdf_h / (4 v.h), v.h = n.h
            w = n_dot_l;
        }
        float sample_solid_angle = 1.0 / (float(push.samples) * max(pdf, 1e-6));
        float lod = clamp(0.5 * log2(sample_solid_angle / texel_solid_angle) + 1.0, 0.0,
                          push.source_levels - 1.0);
        sum += textureLod(source, l, lod).rgb * w;
        weight += w;
    }
    imageStore(cube, ivec3(id), vec4(weight > 0.0 ? sum / weight : vec3(0.0), 1.0));
}
