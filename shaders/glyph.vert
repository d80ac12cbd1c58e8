#version 460
#extension GL_GOOGLE_include_directive : require
// Per-vertex line glyphs: two vertices per mesh vertex, the second offset along
// the world-space normal, tangent or bitangent by the adjustable length (of the
// skinned and morphed vertex on moving meshes).
#include "common.glsl"
#include "motion.glsl"

layout(location = 0) out vec4 out_color;

void main() {
    uint i = uint(gl_VertexIndex) >> 1;
    bool tip = (gl_VertexIndex & 1) != 0;
    GPUInstanceData inst = pc.instances.v[pc.instance_ids.v[gl_InstanceIndex]];
    Deformed d = deform(i, inst, true);
    vec3 p = d.position;
    vec3 n = normalize(d.normal);
    vec3 t = normalize(d.tangent.xyz);
    uint kind = (pc.mesh_flags >> GLYPH_KIND_SHIFT) & 3u;
    vec3 dir = kind == 0u ? n : kind == 1u ? t : normalize(cross(n, t) * d.tangent.w);
    if (tip) p += dir * pc.glyph_length;
    out_color = pc.color;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
