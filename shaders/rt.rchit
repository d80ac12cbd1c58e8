#version 460
#extension GL_GOOGLE_include_directive : require
// The closest hit's debug view, from the same formulas as forward.frag
// (surface_views.glsl) over the interpolated vertex data, and the hit point and
// normals raygen's shadow and occlusion rays start from.
#define SHERPA_NO_DERIVATIVES
#include "rt_hit.glsl"
#include "sherpa_default_textures.glsl"
#include "debug_views.glsl"
#include "material_sampling.glsl"
#include "surface_views.glsl"

layout(location = 0) rayPayloadInEXT RayPayload payload;
hitAttributeEXT vec2 bary;

void main() {
    const SurfaceHit h = interpolate_hit(bary);
    const GPUMaterialData m = materials[h.material];
    const GPUMaterialExtra x = material_extras[h.material];
    const vec4 base = base_color(m, x, h.color, h.uv0, h.uv1);
    vec3 n, t, b;
    shading_frame(h.normal, h.tangent, m.double_sided != 0u && !h.front, n, t, b);
    vec3 c;
    // The renderer refuses views this shader has no formula for; magenta if one slips by.
    // The shadow, ao and shadow-error views are drawn by raygen from the hit point.
    if (!surface_view_color(pc.view, m, x, base, n, t, b, h.tangent.w, h.uv0, h.uv1, h.flags, c))
        c = vec3(1.0, 0.0, 1.0);
    const bool colour = pc.view == VIEW_BASE_COLOR || pc.view == VIEW_EMISSIVE;
    payload.color = vec4(c, colour ? 1.0 : 0.0);
    payload.position = h.position;
    payload.hit = 1u;
    const vec3 g = dot(h.geometric, h.geometric) > 0.0 ? normalize(h.geometric) : -gl_WorldRayDirectionEXT;
    payload.geometric = dot(g, gl_WorldRayDirectionEXT) > 0.0 ? -g : g;
    payload.normal = m.double_sided != 0u && !h.front ? -h.normal : h.normal;
}
