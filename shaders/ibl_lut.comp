#version 460
#extension GL_GOOGLE_include_directive : require
// The split-sum lookup table over (n.v, perceptual roughness), texel centres:
// r, g: the GGX directional albedo's scale and bias on F0 (Karis), so that
// E_ss = F0 * r + F90 * g; b: the Charlie sheen directional albedo (KHR_materials_sheen).
#include "ibl_sampling.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, rgba16f) writeonly uniform image2DArray lut;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.face_size || id.y >= push.face_size) return;
    float n_dot_v = (float(id.x) + 0.5) / float(push.face_size);
    float roughness = (float(id.y) + 0.5) / float(push.face_size);
    float a = roughness * roughness;
    vec3 v = vec3(sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
    float scale = 0.0, bias = 0.0, sheen = 0.0;
    for (uint i = 0u; i < push.samples; ++i) {
        vec2 xi = hammersley(i, push.samples);
        // GGX: importance-sampled half vectors.
        vec3 h = importance_sample(IBL_GGX, xi, a).xyz;
        vec3 l = 2.0 * dot(v, h) * h - v;
        float n_dot_l = l.z, n_dot_h = max(h.z, 0.0), v_dot_h = max(dot(v, h), 0.0);
        if (n_dot_l > 0.0 && n_dot_h > 0.0) {
            // brdf * cos / pdf = D V cos / (D n.h / (4 v.h)) = 4 V cos v.h / n.h
            float g = 4.0 * ibl_v_ggx(n_dot_l, n_dot_v, a) * n_dot_l * v_dot_h / n_dot_h;
            float fc = pow(1.0 - v_dot_h, 5.0);
            scale += (1.0 - fc) * g;
            bias += fc * g;
        }
        // Charlie: uniform hemisphere directions (pdf 1 / 2pi).
        float ct = 1.0 - xi.y, st = sqrt(1.0 - ct * ct), phi = 2.0 * IBL_PI * xi.x;
        vec3 lu = vec3(st * cos(phi), st * sin(phi), ct);
        vec3 hu = normalize(lu + v);
        if (lu.z > 0.0)
            sheen += ibl_d_charlie(hu.z, a) * ibl_v_charlie(lu.z, n_dot_v, a) * lu.z * 2.0 * IBL_PI;
    }
    float n = float(push.samples);
    imageStore(lut, ivec3(id.xy, 0), vec4(scale / n, bias / n, sheen / n, 1.0));
}
