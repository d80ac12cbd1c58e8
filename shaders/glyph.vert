#version 460
#extension GL_GOOGLE_include_directive : require
// Per-vertex line glyphs: two vertices per mesh vertex, the second offset along
// the world-space normal, tangent or bitangent by the adjustable length.
#include "common.glsl"

layout(location = 0) out vec4 out_color;

void main() {
    uint i = uint(gl_VertexIndex) >> 1;
    bool tip = (gl_VertexIndex & 1) != 0;
    GPUInstanceData inst = pc.instances.v[pc.instance_ids.v[gl_InstanceIndex]];
    vec3 p = (inst.model * vec4(pc.positions.v[i], 1.0)).xyz;
    vec3 n = normalize(normal_matrix(inst) * fetch_normal(i));
    vec4 t4 = fetch_tangent(i);
    vec3 t = normalize(mat3(inst.model) * t4.xyz);
    uint kind = (pc.mesh_flags >> GLYPH_KIND_SHIFT) & 3u;
    vec3 dir = kind == 0u ? n : kind == 1u ? t : normalize(cross(n, t) * t4.w);
    if (tip) p += dir * pc.glyph_length;
    out_color = pc.color;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
