// The debug views of surface data, shared by the rasterizer (forward.frag) and the
// ray tracer (rt.rchit) so that both draw each view from the same formula: the
// exactness check compares the two data paths, not two copies of the views.
// Needs common.glsl or rt_hit.glsl (materials), debug_views.glsl, material_sampling.glsl.
#ifndef SHERPA_SURFACE_VIEWS_GLSL
#define SHERPA_SURFACE_VIEWS_GLSL

// The shading frame of a surface point from its interpolated (world) normal and
// tangent: t Gram-Schmidt against n, b from the tangent's sign. Double-sided back
// faces (`flip`) shade with the frame flipped (glTF spec).
void shading_frame(vec3 normal, vec4 tangent, bool flip, out vec3 n, out vec3 t, out vec3 b) {
    n = normalize(normal);
    t = tangent.xyz;
    // A tangent (almost) parallel to the normal has no direction left after
    // Gram-Schmidt: the remainder is rounding noise, which each renderer rounds
    // differently (OrientationTest's arrows). Keep the stored direction instead.
    const vec3 o = t - n * dot(n, t);
    t = dot(o, o) > 1e-6 * dot(t, t) ? normalize(o) : dot(t, t) > 1e-12 ? normalize(t) : vec3(1.0, 0.0, 0.0);
    b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    if (flip) {
        n = -n;
        t = -t;
        b = -b;
    }
}

// The colour of `view` at a surface point (data values; base colour and emissive
// are linear radiance); false for views that are not surface data (lit, checkers,
// geometric-vs-shading: they need derivatives or lights).
bool surface_view_color(uint view, GPUMaterialData m, GPUMaterialExtra x, vec4 base, vec3 n, vec3 t,
                        vec3 b, float tangent_w, vec2 uv0, vec2 uv1, uint mesh_flags, out vec3 c) {
    c = vec3(0.0);
    switch (view) {
    case VIEW_NORMAL: c = encode_vector(n); return true;
    case VIEW_TANGENT: c = encode_vector(t); return true;
    case VIEW_BITANGENT: c = encode_vector(b); return true;
    case VIEW_TANGENT_W:
        c = tangent_w > 0.0 ? vec3(0.15, 0.75, 0.2) : tangent_w < 0.0 ? vec3(0.9, 0.15, 0.1)
                                                                      : vec3(0.95, 0.8, 0.1);
        return true;
    case VIEW_UV0: c = vec3(fract(uv0), 0.0); return true;
    case VIEW_UV1: c = vec3(fract(uv1), 0.0); return true;
    case VIEW_BASE_COLOR: c = base.rgb; return true;
    // Specular-glossiness materials have no metallic value: the metallic view flags
    // them (SPEC_GLOSS_FLAG, sherpa::render::kSpecGlossFlagColor), their roughness is
    // 1 - glossiness and their F0 the specular colour (metal-rough: mix(0.04, base, metallic)).
    case VIEW_METALLIC:
        c = x.workflow == WORKFLOW_SPECULAR_GLOSSINESS
                ? SPEC_GLOSS_FLAG
                : vec3(metallic_roughness(m, metallic_roughness_texel(m, x, uv0, uv1)).x);
        return true;
    case VIEW_ROUGHNESS:
        c = vec3(x.workflow == WORKFLOW_SPECULAR_GLOSSINESS
                     ? 1.0 - specular_glossiness(x, uv0, uv1).a
                     : metallic_roughness(m, metallic_roughness_texel(m, x, uv0, uv1)).y);
        return true;
    case VIEW_SPECULAR:
        c = x.workflow == WORKFLOW_SPECULAR_GLOSSINESS
                ? specular_glossiness(x, uv0, uv1).rgb
                : mix(vec3(0.04), base.rgb, metallic_roughness(m, metallic_roughness_texel(m, x, uv0, uv1)).x);
        return true;
    case VIEW_OCCLUSION: c = vec3(occlusion(m, x, uv0, uv1)); return true;
    case VIEW_EMISSIVE: c = emission(m, x, uv0, uv1); return true;
    case VIEW_PROVENANCE: c = provenance_color((mesh_flags >> TANGENT_PROVENANCE_SHIFT) & 3u); return true;
    case VIEW_SHADING_NORMAL: c = encode_vector(mapped_normal(m, x, t, b, n, uv0, uv1)); return true;
    default: return false;
    }
}
#endif
