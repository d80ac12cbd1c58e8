#version 460
#extension GL_GOOGLE_include_directive : require
// The split-sum table of KHR_materials_anisotropy's GGX (made only for scenes with an
// anisotropic material; environment_lut.h): the directional albedo's scale and bias on
// F0 (E_ss = F0 * r + F90 * g, as ibl_lut.comp's for the isotropic GGX), which for the
// anisotropic lobe depends on n.v, alpha_t, alpha_b and the view's azimuth about the
// normal, measured from the anisotropy direction.
//   x: n.v at texel centres; y: perceptual roughness (alpha_b = roughness^2) at texel
//   centres; layer = strength node * AZIMUTHS + azimuth node, where strength node i is
//   strength^2 = i / (STRENGTHS - 1) (alpha_t = mix(alpha_b, 1, strength^2) is linear
//   in it) and azimuth node j is |cos(azimuth)| = j / (AZIMUTHS - 1) (1: the view along
//   the direction). The albedo bends sharply where the view lies across the direction
//   at grazing angles; nodes even in |cos| follow it closer than nodes even in angle.
// Integrated by the visible normals of the anisotropic lobe (Heitz 2018): each sample
// weighs F G2 / G1(v), with brdf.glsl's height-correlated Smith.
// C++ twin of the sizes: AnisotropicBrdfLut (environment_lut.h); the
// reader: ibl_brdf_lut_anisotropic (ibl.glsl).
#include "brdf.glsl"
#include "bsdf_sampling.glsl"
#include "ibl_sampling.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, rgba16f) writeonly uniform image2DArray lut;

const uint ROUGHNESSES = 16u, STRENGTHS = 8u, AZIMUTHS = 6u; // n.v: push.face_size

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.face_size || id.y >= ROUGHNESSES) return;
    float n_dot_v = (float(id.x) + 0.5) / float(push.face_size);
    float roughness = (float(id.y) + 0.5) / float(ROUGHNESSES);
    float strength2 = float(id.z / AZIMUTHS) / float(STRENGTHS - 1u);
    float cos_phi = float(id.z % AZIMUTHS) / float(AZIMUTHS - 1u);
    vec2 a = anisotropic_alpha(roughness, sqrt(strength2));
    float sin_theta = sqrt(1.0 - n_dot_v * n_dot_v);
    vec3 v = vec3(sin_theta * cos_phi, sin_theta * sqrt(1.0 - cos_phi * cos_phi), n_dot_v);
    float g1_v = 2.0 * n_dot_v / (n_dot_v + length(vec3(a.x * v.x, a.y * v.y, v.z)));
    float scale = 0.0, bias = 0.0;
    for (uint i = 0u; i < push.samples; ++i) {
        vec3 h = sample_ggx_vndf(v, a, hammersley(i, push.samples));
        float v_dot_h = max(dot(v, h), 0.0);
        vec3 l = 2.0 * v_dot_h * h - v;
        if (l.z <= 0.0) continue;
        // F D V n.l / pdf, pdf = G1(v) D / (4 n.v): F 4 V n.l n.v / G1(v).
        float g = 4.0 * v_smith_ggx_anisotropic(v, l, a) * l.z * n_dot_v / g1_v;
        float fc = pow5(1.0 - v_dot_h);
        scale += (1.0 - fc) * g;
        bias += fc * g;
    }
    float n = float(push.samples);
    imageStore(lut, ivec3(id), vec4(scale / n, bias / n, 0.0, 1.0));
}
