#version 460
#extension GL_GOOGLE_include_directive : require
// The path tracer's closest hit: the surface's BRDF inputs from the same functions the
// raster's lit shading calls (forward.frag): base colour, metallic-roughness or
// specular-glossiness, the normal map, emission, and the material extensions' blocks
// (KHR_materials_ior / _specular's F0 and F90, KHR_materials_clearcoat's coat,
// KHR_materials_sheen's sheen). The
// occlusion texture is not read: the path tracer traces occlusion.
#define SHERPA_PATH_TRACE
#define SHERPA_NO_DERIVATIVES
#include "rt_hit.glsl"
#include "sherpa_default_textures.glsl"
#include "debug_views.glsl"
#include "material_sampling.glsl"
#include "surface_views.glsl"
#include "brdf.glsl"
#include "path_payload.glsl"
// The extension blocks at binding 9 here (8 is the environment's distribution).
#define SHERPA_MATERIAL_EXT_DECLARED
layout(set = 1, binding = 9, std430) readonly buffer MaterialExtensionBlock {
    uvec4 material_ext[];
};
#include "material_ext.glsl"
#include "clearcoat.glsl"
#include "sheen.glsl"

layout(location = 0) rayPayloadInEXT PathPayload payload;
hitAttributeEXT vec2 bary;

void main() {
    const SurfaceHit h = interpolate_hit(bary);
    const GPUMaterialData m = materials[h.material];
    const GPUMaterialExtra x = material_extras[h.material];
    const vec4 base = base_color(m, x, h.color, h.uv0, h.uv1);
    vec3 n, t, b;
    shading_frame(h.normal, h.tangent, m.double_sided != 0u && !h.front, n, t, b);
    const vec3 v = -gl_WorldRayDirectionEXT;
    const vec3 g = dot(h.geometric, h.geometric) > 0.0 ? normalize(h.geometric) : v;
    payload.position = h.position;
    payload.hit = 1u;
    payload.geometric = dot(g, v) < 0.0 ? -g : g;
    payload.flags = 0u;
    // Lines and points have no surface: unlit, as the raster draws them.
    if (x.unlit != 0u || (h.flags & (MESH_LINES | MESH_POINTS)) != 0u) {
        payload.flags = PATH_HIT_UNLIT;
        payload.emission = base.rgb;
        return;
    }
    const vec3 sn = mapped_normal(m, x, t, b, n, h.uv0, h.uv1);
    Surface s;
    if (x.workflow == WORKFLOW_SPECULAR_GLOSSINESS) {
        const vec4 sg = specular_glossiness(x, h.uv0, h.uv1);
        s = spec_gloss_surface(base.rgb, sg.rgb, sg.a, sn, v);
    } else {
        const vec2 mr = metallic_roughness(m, metallic_roughness_texel(m, x, h.uv0, h.uv1));
        if (x.extensions == NO_EXTENSION) {
            s = metal_rough_surface(base.rgb, mr.x, mr.y, sn, v);
        } else { // KHR_materials_ior, KHR_materials_specular
            vec3 f0;
            float f90;
            dielectric_fresnel(extension_index(x), h.uv0, h.uv1, f0, f90);
            s = metal_rough_surface(base.rgb, mr.x, mr.y, f0, f90, sn, v);
        }
    }
    // KHR_materials_clearcoat (factor 0 without it): the coat, and the emission under it.
    const Clearcoat cc = material_clearcoat(extension_index(x), t, b, n, h.uv0, h.uv1);
    payload.clearcoat = cc.factor;
    payload.clearcoat_roughness = cc.roughness;
    payload.clearcoat_normal = cc.n;
    // KHR_materials_sheen (black without it).
    const Sheen sh = material_sheen(extension_index(x), h.uv0, h.uv1);
    payload.sheen_color = sh.color;
    payload.sheen_roughness = sh.roughness;
    payload.normal = s.n;
    payload.roughness = s.roughness;
    payload.diffuse = s.diffuse;
    payload.f0 = s.f0;
    payload.f90 = s.f90;
    // Emission under the sheen and the coat, as the rasterizer layers it.
    payload.emission = clearcoat_over(cc, v, sheen_over(sh, sn, v, emission(m, x, h.uv0, h.uv1), vec3(0.0)), vec3(0.0));
}
