#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
// Forward shading of opaque, masked and blended materials, and every debug view.
#include "common.glsl"
#include "bindings.glsl"
#include "brdf.glsl"
#include "shadows.glsl"
#include "debug_views.glsl"
#include "material_sampling.glsl"
#include "surface_views.glsl"
#include "ibl.glsl"
#include "material_ext.glsl"
#include "transmission.glsl"
#include "refraction.glsl"
#include "material_layers.glsl"
#include "anisotropy.glsl"
#include "iridescence.glsl"
#include "tonemap.glsl"
#include "punctual.glsl"
#include "diffuse_transmission.glsl"

layout(location = 0) in vec3 in_world_pos;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_tangent;
layout(location = 3) in vec2 in_uv0;
layout(location = 4) in vec2 in_uv1;
layout(location = 5) in vec4 in_color;
layout(location = 6) in float in_joint_weight; // read only by the joint-influence view
layout(location = 7) flat in vec3 in_model_scale; // read only where a volume refracts

layout(location = 0) out vec4 out_color;

// The view is a specialization constant: each view gets its own pipeline, so the
// lit pipeline carries no debug-view code. On a SIMD CPU rasterizer a run-time
// switch would execute (masked) every case for every pixel.
layout(constant_id = 0) const uint VIEW = VIEW_LIT;
// The optional streams (HAS_TANGENT | HAS_UV0 | HAS_UV1 | HAS_COLOR) that the
// drawn meshes hold. An absent one reads its glTF default as a constant, so its
// varying is never set up or interpolated: on a CPU rasterizer each varying costs
// per triangle and per pixel. Tangents are read whenever the view shows them (an
// absent tangent stream means no material of the mesh has a normal map, so lit
// shading never uses them).
layout(constant_id = 1) const uint STREAMS = HAS_TANGENT | HAS_UV0 | HAS_UV1 | HAS_COLOR;
// Lines and points (MESH_LINES / MESH_POINTS in STREAMS) have no surface: they are
// shaded unlit, base colour times vertex colour, like KHR_materials_unlit.
// TransmissionPass's pipelines: linear radiance (no tone curve) with coverage in alpha,
// transmissive materials left out (what they refract is what lies behind them).
layout(constant_id = 2) const bool TRANSMISSION_BACKGROUND = false;
const bool UNLIT_TOPOLOGY = (STREAMS & (MESH_LINES | MESH_POINTS)) != 0u;
const bool READ_TANGENT = (STREAMS & HAS_TANGENT) != 0u || VIEW == VIEW_TANGENT ||
                          VIEW == VIEW_BITANGENT || VIEW == VIEW_TANGENT_W;

// `coat` and `sheen` gather the light a clearcoat and a sheen reflect (clearcoat.glsl,
// sheen.glsl; none without them).
vec3 punctual_light(Surface s, Clearcoat cc, Sheen sh, GPULight light, vec3 pos, inout vec3 coat,
                    inout vec3 sheen) {
    vec3 l;
    float dist;
    vec3 radiance = punctual_incident(light, pos, l, dist);
    coat += clearcoat_times_cos(cc, s.v, l) * radiance;
    sheen += sheen_times_cos(sh, s.n, s.v, l) * radiance;
    return brdf_times_cos(s, l) * radiance;
}

vec3 geometric_normal(vec3 v) {
    // Face normal from screen derivatives, turned towards the viewer.
    vec3 geo = normalize(cross(dFdx(in_world_pos), dFdy(in_world_pos)));
    return dot(geo, v) < 0.0 ? -geo : geo;
}

void main() {
    GPUMaterialData m = materials[pc.material_id];
    GPUMaterialExtra x = material_extras[pc.material_id];
    const uint view = VIEW;
    vec2 uv0 = (STREAMS & HAS_UV0) != 0u ? in_uv0 : vec2(0.0);
    vec2 uv1 = (STREAMS & HAS_UV1) != 0u ? in_uv1 : vec2(0.0);
    vec4 color = (STREAMS & HAS_COLOR) != 0u ? in_color : vec4(1.0);
    vec4 tangent = READ_TANGENT ? in_tangent : vec4(1.0, 0.0, 0.0, 1.0);

    // Alpha decides coverage in every view; other inputs only where a view shows them.
    bool need_base = view == VIEW_LIT || view == VIEW_BASE_COLOR || view == VIEW_SPECULAR ||
                     m.alpha_mode != SHERPA_ALPHA_OPAQUE;
    vec4 base = need_base ? base_color(m, x, color, uv0, uv1) : vec4(1.0);
    if (m.alpha_mode == SHERPA_ALPHA_MASK && base.a < m.alpha_cutoff) discard;

    vec3 v = normalize(frame.camera_position.xyz - in_world_pos);
    // Double-sided back faces shade with the frame flipped (shading_frame). The shadow
    // lookup offsets along the same side: offset along the unflipped normal, a back
    // face lit from its own side would look up behind itself and shadow itself.
    const bool flip = m.double_sided != 0u && !gl_FrontFacing;
    vec3 n, t, b;
    shading_frame(in_normal, tangent, flip, n, t, b);
    vec3 shadow_normal = flip ? -in_normal : in_normal;

    // Material extension blocks only where the material has some (a uniform branch).
    const GPUExtensionIndex ext = extension_index(x);
    vec3 c;
    // The specular (F0) view with KHR_materials_ior / _specular: their dielectric F0
    // (the ray tracer's shared formula knows the core one only).
    const bool ext_f0 = view == VIEW_SPECULAR && x.extensions != NO_EXTENSION &&
                        x.workflow == WORKFLOW_METALLIC_ROUGHNESS;
    if (ext_f0) {
        vec3 f0;
        float f90;
        dielectric_fresnel(ext, uv0, uv1, f0, f90);
        c = mix(f0, base.rgb, metallic_roughness(m, metallic_roughness_texel(m, x, uv0, uv1)).x);
    }
    if (!ext_f0 && !surface_view_color(view, m, x, base, n, t, b, tangent.w, uv0, uv1, pc.mesh_flags, c)) {
    switch (view) {
    case VIEW_UV0_CHECKER: c = checker_color(uv0, frame.overlay.y); break;
    case VIEW_UV1_CHECKER: c = checker_color(uv1, frame.overlay.y); break;
    case VIEW_GEOMETRIC_VS_SHADING: {
        vec3 sn = mapped_normal(m, x, t, b, n, uv0, uv1);
        c = angle_ramp(acos(clamp(dot(geometric_normal(v), sn), -1.0, 1.0)));
        break;
    }
    case VIEW_JOINT_INFLUENCE: c = heat_ramp(in_joint_weight); break;
    // KHR_materials_ior: grey (ior - 1) / 2 (1 black, 2 mid grey, 3 and above white),
    // ior 0 (F0 = 1) in the flag colour; materials without the extension show 1.5.
    case VIEW_IOR: c = ior_view_color(material_ior(ext)); break;
    // KHR_materials_specular: the weight (factor x texture alpha) and the F0 colour
    // (factor x texture rgb); 1 and white without the extension.
    case VIEW_SPECULAR_WEIGHT: c = vec3(material_specular(ext, uv0, uv1).a); break;
    case VIEW_SPECULAR_COLOR: c = material_specular(ext, uv0, uv1).rgb; break;
    // The transmission family (transmission.glsl): grey factor x texture; thickness in
    // local units, clipped at 1; the attenuation colour (white: none); 0 / black absent.
    case VIEW_TRANSMISSION: c = vec3(material_transmission(ext, uv0, uv1)); break;
    case VIEW_THICKNESS: c = vec3(clamp(material_thickness(ext, uv0, uv1), 0.0, 1.0)); break;
    case VIEW_ATTENUATION: c = attenuation_view_color(material_attenuation(ext)); break;
    case VIEW_DIFFUSE_TRANSMISSION: c = vec3(material_diffuse_transmission(ext, uv0, uv1).a); break;
    // KHR_materials_clearcoat: the coat's weight and roughness (factor x texture; 0
    // without the extension) and its normal (the geometry's without its own map).
    case VIEW_CLEARCOAT: c = vec3(material_clearcoat(ext, t, b, n, uv0, uv1).factor); break;
    case VIEW_CLEARCOAT_ROUGHNESS: c = vec3(material_clearcoat(ext, t, b, n, uv0, uv1).roughness); break;
    case VIEW_CLEARCOAT_NORMAL: c = encode_vector(material_clearcoat(ext, t, b, n, uv0, uv1).n); break;
    // KHR_materials_sheen: the sheen colour (linear, like base colour) and roughness.
    case VIEW_SHEEN_COLOR: c = material_sheen(ext, uv0, uv1).color; break;
    case VIEW_SHEEN_ROUGHNESS: c = vec3(material_sheen(ext, uv0, uv1).roughness); break;
    // KHR_materials_anisotropy: the strength (grey) and the direction in the world
    // (encoded as the normal view, along the normal-mapped frame); black without it.
    case VIEW_ANISOTROPY_STRENGTH: c = vec3(material_anisotropy_tangent(ext, uv0, uv1).z * float(ext.anisotropy != NO_EXTENSION)); break;
    // KHR_materials_iridescence: the factor (grey) and the film's thickness in
    // micrometres (grey, clipped at 1); 0 without the extension.
    case VIEW_IRIDESCENCE: c = vec3(material_iridescence(ext, uv0, uv1).x); break;
    case VIEW_IRIDESCENCE_THICKNESS: c = vec3(clamp(material_iridescence(ext, uv0, uv1).z / 1000.0, 0.0, 1.0)); break;
    case VIEW_ANISOTROPY_DIRECTION: {
        vec4 a = material_anisotropy(ext, t, b, mapped_normal(m, x, t, b, n, uv0, uv1), uv0, uv1);
        c = ext.anisotropy == NO_EXTENSION ? vec3(0.0) : encode_vector(a.w > 0.0 || dot(a.xyz, a.xyz) > 0.0 ? a.xyz : t);
        break;
    }
    case VIEW_SHADOW:
        c = vec3(sun_visibility(in_world_pos, shadow_normal, -(frame.view * vec4(in_world_pos, 1.0)).z));
        break;
    default: {
        if (x.unlit != 0u || UNLIT_TOPOLOGY) {
            c = base.rgb;
            break;
        }
        vec3 shading_n = mapped_normal(m, x, t, b, n, uv0, uv1);
        Surface s;
        float transmission = 0.0;
        vec4 diffuse_transmission = vec4(0.0); // rgb colour, a factor
        vec4 mr_texel = vec4(1.0);
        if (x.workflow == WORKFLOW_SPECULAR_GLOSSINESS) {
            vec4 sg = specular_glossiness(x, uv0, uv1);
            s = spec_gloss_surface(base.rgb, sg.rgb, sg.a, shading_n, v);
        } else {
            mr_texel = metallic_roughness_texel(m, x, uv0, uv1);
            vec2 mr = metallic_roughness(m, mr_texel);
            if (x.extensions == NO_EXTENSION) {
                s = metal_rough_surface(base.rgb, mr.x, mr.y, shading_n, v);
            } else { // KHR_materials_ior, KHR_materials_specular
                vec3 f0;
                float f90;
                dielectric_fresnel(ext, uv0, uv1, f0, f90);
                s = metal_rough_surface(base.rgb, mr.x, mr.y, f0, f90, shading_n, v);
                // KHR_materials_anisotropy (strength 0, isotropic, without it).
                s.anisotropy = material_anisotropy(ext, t, b, shading_n, uv0, uv1);
                // KHR_materials_iridescence (factor 0, Schlick alone, without it).
                s.iridescence = surface_iridescence(ext, uv0, uv1, s.f0, dot(shading_n, v));
                transmission = material_transmission(ext, uv0, uv1);
                diffuse_transmission = material_diffuse_transmission(ext, uv0, uv1);
                if (TRANSMISSION_BACKGROUND && transmission > 0.0) discard;
            }
        }
        // KHR_materials_transmission: that share of the diffuse passes through instead
        // (the raster's refraction below; brdf.glsl's layering).
        const vec3 opaque_diffuse = s.diffuse;
        // KHR_materials_diffuse_transmission: of what remains, that share scatters to
        // the other side (diffuse_transmission.glsl).
        s.diffuse *= (1.0 - transmission) * (1.0 - diffuse_transmission.a);
        // KHR_materials_clearcoat: factor 0 (nothing to add) without the extension.
        const Clearcoat cc = material_clearcoat(ext, t, b, n, uv0, uv1);
        // KHR_materials_sheen: black (nothing to add) without the extension.
        const Sheen sh = material_sheen(ext, uv0, uv1);
        vec3 coat = vec3(0.0), sheen = vec3(0.0);
        // The sun (and its shadow lookup) only where some pixel of the SIMD group
        // faces it: a uniform branch, so a CPU rasterizer skips the work.
        vec3 sun_l = -normalize(frame.sun_direction.xyz);
        c = vec3(0.0);
        const float view_depth = -(frame.view * vec4(in_world_pos, 1.0)).z; // for the shadow maps
        if (subgroupAny(dot(s.n, sun_l) > 0.0 || (cc.factor > 0.0 && dot(cc.n, sun_l) > 0.0))) {
            vec3 sun = frame.sun_radiance.rgb * sun_shadow(in_world_pos, shadow_normal, view_depth);
            c = brdf_times_cos(s, sun_l) * sun;
            coat += clearcoat_times_cos(cc, v, sun_l) * sun;
            sheen += sheen_times_cos(sh, s.n, v, sun_l) * sun;
        }
        if (diffuse_transmission.a > 0.0) {
            // The back is lit where the front is not: the sun's map is looked up from the
            // back side.
            float shadow = sun_shadow(in_world_pos, -shadow_normal, view_depth);
            vec3 albedo = opaque_diffuse * diffuse_transmission.rgb * diffuse_transmission.a *
                          (1.0 - transmission) *
                          beer_lambert(material_attenuation(ext), material_thickness(ext, uv0, uv1));
            c += diffuse_transmission_light(s, albedo, in_world_pos, shadow);
        }
        for (uint i = 0u; i < frame.params.y; ++i)
            c += punctual_light(s, cc, sh, frame.lights[i], in_world_pos, coat, sheen);
        float ao = x.workflow == WORKFLOW_SPECULAR_GLOSSINESS ? occlusion(m, x, uv0, uv1)
                                                              : occlusion(m, x, uv0, uv1, mr_texel);
        // The environment replaces the sky/ground ambient term where one is loaded.
        c += (has_environment() ? environment_light(s) : ambient_light(s, frame.ambient.rgb)) * ao;
        c += emission(m, x, uv0, uv1);
        if (transmission > 0.0) {
            vec3 light = refracted_light(in_world_pos, s.n, v, s.roughness, material_ior(ext),
                                         material_thickness(ext, uv0, uv1), in_model_scale,
                                         material_attenuation(ext), material_dispersion(ext), opaque_diffuse);
            c += transmission * (1.0 - transmission_fresnel(s)) * light;
        }
        if (max3(sh.color) > 0.0)
            sheen += (has_environment() ? sheen_environment(sh, s.n, v)
                                        : sh.color * sheen_albedo(sh.roughness, dot(s.n, v)) *
                                              hemisphere(s.n, frame.ambient.rgb)) * ao;
        if (cc.factor > 0.0)
            coat += (has_environment() ? clearcoat_environment(cc, v) : clearcoat_ambient(cc, v, frame.ambient.rgb)) * ao;
        c = layers_over(cc, sh, s.n, v, c, sheen, coat);
        break;
    }
    }
    }
    // Colour views (lit, base colour, emissive) are linear radiance; the rest are data.
    if (view != VIEW_LIT && view != VIEW_BASE_COLOR && view != VIEW_EMISSIVE && view != VIEW_SPECULAR_COLOR &&
        view != VIEW_SHEEN_COLOR)
        c = display_to_linear(c);
    // The lit view is radiance: exposure and the tone curve map it to the display (per
    // fragment, before blending, as three.js does).
    if (view == VIEW_LIT && !TRANSMISSION_BACKGROUND) c = tone_map(c, uint(frame.display.y), frame.display.x);
    out_color = vec4(c, view == VIEW_LIT && m.alpha_mode == SHERPA_ALPHA_BLEND && !TRANSMISSION_BACKGROUND ? base.a : 1.0);
}
