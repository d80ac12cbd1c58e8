#version 460
#extension GL_GOOGLE_include_directive : require
// The path tracer's closest hit: the surface's BRDF inputs from the same functions the
// raster's lit shading calls (forward.frag): base colour, metallic-roughness or
// specular-glossiness, the normal map, emission, and the material extensions' blocks
// (KHR_materials_ior / _specular's F0 and F90 as the raster's dielectric_fresnel, the
// transmission family, KHR_materials_clearcoat's coat, KHR_materials_sheen's sheen).
// The occlusion texture is not read: the path tracer traces occlusion.
#define SHERPA_PATH_TRACE
#define SHERPA_NO_DERIVATIVES
#include "rt_hit.glsl"
#include "sherpa_default_textures.glsl"
#include "debug_views.glsl"
#include "material_sampling.glsl"
#include "surface_views.glsl"
#include "brdf.glsl"
#include "path_payload.glsl"
#include "pt_material_ext.glsl"
#include "material_layers.glsl"
#include "anisotropy.glsl"
#include "iridescence.glsl"

layout(location = 0) rayPayloadInEXT PathPayload payload;
hitAttributeEXT vec2 bary;

void main() {
    const SurfaceHit h = interpolate_hit(bary);
    const GPUMaterialData m = materials[h.material];
    const GPUMaterialExtra x = material_extras[h.material];
    const vec4 base = base_color(m, x, h.color, h.uv0, h.uv1);
    // Extension blocks only where the material has some (KHR_materials_ior, _specular,
    // the transmission family: transmission.glsl).
    const GPUExtensionIndex ext = extension_index(x);
    // A volume's back faces are its boundary whatever doubleSided says (pt.rahit).
    const bool volume = ext.volume != NO_EXTENSION &&
                        (ext.transmission != NO_EXTENSION || ext.diffuse_transmission != NO_EXTENSION);
    vec3 n, t, b;
    shading_frame(h.normal, h.tangent, (m.double_sided != 0u || volume) && !h.front, n, t, b);
    const vec3 v = -gl_WorldRayDirectionEXT;
    const vec3 g = dot(h.geometric, h.geometric) > 0.0 ? normalize(h.geometric) : v;
    payload.position = h.position;
    payload.hit = 1u;
    payload.geometric = dot(g, v) < 0.0 ? -g : g;
    payload.flags = 0u;
    payload.light_luminance = 0.0;
    payload.front = h.front ? 1u : 0u;
    // Lines and points have no surface: unlit, as the raster draws them.
    if (x.unlit != 0u || (h.flags & (MESH_LINES | MESH_POINTS)) != 0u) {
        payload.flags = PATH_HIT_UNLIT;
        payload.emission = base.rgb;
        return;
    }
    const vec3 sn = mapped_normal(m, x, t, b, n, h.uv0, h.uv1);
    // The extension fields of the payload only where the material has extension blocks.
    const bool extended = x.extensions != NO_EXTENSION;
    if (extended) {
        payload.flags = PATH_HIT_EXTENDED;
        payload.transmission_tint = vec3(0.0);
        payload.diffuse_transmission_tint = vec3(0.0);
    }
    Surface s;
    if (x.workflow == WORKFLOW_SPECULAR_GLOSSINESS) {
        const vec4 sg = specular_glossiness(x, h.uv0, h.uv1);
        s = spec_gloss_surface(base.rgb, sg.rgb, sg.a, sn, v);
    } else {
        const vec2 mr = metallic_roughness(m, metallic_roughness_texel(m, x, h.uv0, h.uv1));
        if (x.extensions == NO_EXTENSION) {
            s = metal_rough_surface(base.rgb, mr.x, mr.y, sn, v);
        } else {
            vec3 f0;
            float f90;
            dielectric_fresnel(ext, h.uv0, h.uv1, f0, f90);
            s = metal_rough_surface(base.rgb, mr.x, mr.y, f0, f90, sn, v);
            s.anisotropy = material_anisotropy(ext, t, b, sn, h.uv0, h.uv1);
            s.iridescence = surface_iridescence(ext, h.uv0, h.uv1, s.f0, dot(sn, v));
            const float transmission = material_transmission(ext, h.uv0, h.uv1);
            // The base colour tints the light once, where it enters a volume (or at a
            // thin wall); leaving, the lobe is untinted.
            payload.transmission_tint = transmission * (volume && !h.front ? vec3(1.0 - mr.x) : s.diffuse);
            // KHR_materials_diffuse_transmission: that share of the rest scatters through.
            const vec4 dt = material_diffuse_transmission(ext, h.uv0, h.uv1);
            payload.diffuse_transmission_tint = (1.0 - transmission) * dt.a * dt.rgb * s.diffuse;
            s.diffuse *= (1.0 - transmission) * (1.0 - dt.a);
            payload.ior = material_ior(ext);
            payload.attenuation = volume ? material_attenuation(ext) : vec4(-1.0);
            payload.dispersion = material_dispersion(ext);
        }
    }
    payload.normal = s.n;
    payload.roughness = s.roughness;
    payload.diffuse = s.diffuse;
    payload.f0 = s.f0;
    payload.f90 = s.f90;
    payload.emission = emission(m, x, h.uv0, h.uv1);
    if (extended) {
        // KHR_materials_clearcoat (factor 0 without it): the coat, and the emission under it.
        const Clearcoat cc = material_clearcoat(ext, t, b, n, h.uv0, h.uv1);
        payload.clearcoat = cc.factor;
        payload.clearcoat_roughness = cc.roughness;
        payload.clearcoat_normal = cc.n;
        // KHR_materials_sheen (black without it).
        const Sheen sh = material_sheen(ext, h.uv0, h.uv1);
        payload.sheen_color = sh.color;
        payload.sheen_roughness = sh.roughness;
        payload.anisotropy = s.anisotropy;
        payload.iridescence = s.iridescence;
        // Emission under the sheen and the coat, as the rasterizer layers it (light
        // sampling reads it through a ray too; only its choice of triangle uses the bare
        // emission).
        payload.emission = layers_over(cc, sh, sn, v, payload.emission, vec3(0.0), vec3(0.0));
    }
    // The light list's rule (emissive_lights.cpp): static meshes whose material emits,
    // below the luminance cap; its density for multiple importance sampling.
    if (pc.light_inv_power > 0.0 && (h.flags & MESH_MOTION) == 0u && m.emissive_tex != TEX_BLACK) {
        const vec3 e = m.emissive_factor.rgb * m.emissive_factor.w;
        const float lum = dot(e, vec3(0.2126, 0.7152, 0.0722));
        payload.light_luminance = lum > 0.0 && lum <= 1e20 ? lum : 0.0;
    }
}
