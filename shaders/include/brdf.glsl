// glTF 2.0 metallic-roughness BRDF (spec appendix B): GGX distribution,
// height-correlated Smith visibility, Schlick Fresnel, Lambert diffuse.
//
// Functions over the material-inputs struct `Surface`, shared by the rasterizer and the
// ray tracers (their names are stable):
//   Surface metal_rough_surface(albedo, metallic, roughness, n, v)       core glTF
//   Surface metal_rough_surface(albedo, metallic, roughness, f0, f90, n, v)
//                                  with a dielectric F0 colour and F90 weight
//   Surface spec_gloss_surface(diffuse, specular, glossiness, n, v)     KHR_materials_pbrSpecularGlossiness
//   float ior_f0(ior)                          KHR_materials_ior: F0 of a dielectric against air
//   vec3 dielectric_f0(ior, specular, specular_color)   KHR_materials_specular's F0
//   vec3 fresnel_schlick(f0, f90, v_dot_h), fresnel_schlick(f0, v_dot_h) (F90 = 1)
//   float d_ggx(n_dot_h, alpha), float v_smith_ggx(n_dot_l, n_dot_v, alpha)
//   vec2 anisotropic_alpha(roughness, strength), d_ggx_anisotropic, v_smith_ggx_anisotropic
//                                  KHR_materials_anisotropy's GGX (Surface::anisotropy)
//   vec3 specular_direction(Surface)   the environment's lookup direction (bent normal)
//   vec3 brdf_times_cos(Surface, l)            one light direction, unit radiance
//   vec3 ambient_light(Surface, radiance)      the sky/ground term without an environment
#ifndef SHERPA_BRDF_GLSL
#define SHERPA_BRDF_GLSL
const float PI = 3.14159265358979;

// BRDF inputs, whichever workflow gave them: the diffuse reflectance, F0, F90 and the
// perceptual roughness.
struct Surface {
    vec3 diffuse;
    vec3 f0;
    float f90; // Fresnel at grazing angles: 1 but for KHR_materials_specular's dielectrics
    float roughness;
    vec3 n; // shading normal, unit, facing the viewer side of the surface
    vec3 v; // unit vector to the eye
    // KHR_materials_anisotropy: xyz the anisotropy direction (unit, in the tangent
    // plane), w the strength; w 0: isotropic GGX (every surface without the extension).
    vec4 anisotropy;
    // KHR_materials_iridescence: rgb the thin film's Fresnel at n . v, a its factor; a 0:
    // Schlick's Fresnel alone (every surface without the extension).
    vec4 iridescence;
};

// glTF metallic-roughness: dielectric F0 0.04, metals reflect their base colour.
Surface metal_rough_surface(vec3 albedo, float metallic, float roughness, vec3 n, vec3 v) {
    return Surface(albedo * (1.0 - metallic), mix(vec3(0.04), albedo, metallic), 1.0, roughness, n, v,
                   vec4(0.0), vec4(0.0));
}

// F0 of a dielectric of index of refraction `ior` against air (KHR_materials_ior):
// ((ior - 1) / (ior + 1))^2; 1.5 gives the core 0.04, and 0 gives 1.
float ior_f0(float ior) {
    float r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}

// KHR_materials_specular: the dielectric's F0 is its ior's, tinted by the specular
// colour (at most 1) and scaled by the specular weight; its F90 is the weight itself.
vec3 dielectric_f0(float ior, float specular, vec3 specular_color) {
    return min(vec3(ior_f0(ior)) * specular_color, vec3(1.0)) * specular;
}

// Metallic-roughness with a dielectric F0 colour and F90 weight (KHR_materials_ior,
// KHR_materials_specular): metals still reflect their base colour with F90 = 1.
Surface metal_rough_surface(vec3 albedo, float metallic, float roughness, vec3 f0, float f90, vec3 n, vec3 v) {
    return Surface(albedo * (1.0 - metallic), mix(f0, albedo, metallic), mix(f90, 1.0, metallic), roughness, n, v,
                   vec4(0.0), vec4(0.0));
}

// KHR_materials_pbrSpecularGlossiness, by its definition: F0 = specular, roughness =
// 1 - glossiness, and the diffuse reflectance diffuse * (1 - max(specular)).
Surface spec_gloss_surface(vec3 diffuse, vec3 specular, float glossiness, vec3 n, vec3 v) {
    float max_specular = max(max(specular.r, specular.g), specular.b);
    return Surface(diffuse * (1.0 - max_specular), specular, 1.0, 1.0 - glossiness, n, v, vec4(0.0), vec4(0.0));
}

// x^5 as products: a CPU rasterizer evaluates pow() as exp2(5 * log2(x)), two
// polynomial approximations per lane.
float pow5(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

vec3 fresnel_schlick(vec3 f0, float f90, float v_dot_h) {
    return f0 + (f90 - f0) * pow5(clamp(1.0 - v_dot_h, 0.0, 1.0));
}

vec3 fresnel_schlick(vec3 f0, float v_dot_h) {
    return fresnel_schlick(f0, 1.0, v_dot_h);
}

float d_ggx(float n_dot_h, float a) {
    float a2 = a * a;
    float d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

float v_smith_ggx(float n_dot_l, float n_dot_v, float a) {
    float a2 = a * a;
    float gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
    float gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
    float s = gv + gl;
    return s > 0.0 ? 0.5 / s : 0.0;
}

// KHR_materials_anisotropy's GGX: alpha along the anisotropy direction (x, the spec's
// alpha_t = mix(alpha, 1, strength^2)) and across it (y, alpha_b = alpha).
vec2 anisotropic_alpha(float roughness, float strength) {
    float a = max(roughness * roughness, 1e-3);
    return vec2(mix(a, 1.0, strength * strength), a);
}

// The anisotropic distribution; h_tbn is the half vector in the frame (direction,
// n x direction, n).
float d_ggx_anisotropic(vec3 h_tbn, vec2 a) {
    vec3 f = vec3(h_tbn.x / a.x, h_tbn.y / a.y, h_tbn.z);
    float d = dot(f, f);
    return 1.0 / (PI * a.x * a.y * d * d);
}

// Its height-correlated Smith visibility; v_tbn and l_tbn in the same frame.
float v_smith_ggx_anisotropic(vec3 v_tbn, vec3 l_tbn, vec2 a) {
    float gv = l_tbn.z * length(vec3(a.x * v_tbn.x, a.y * v_tbn.y, v_tbn.z));
    float gl = v_tbn.z * length(vec3(a.x * l_tbn.x, a.y * l_tbn.y, l_tbn.z));
    float s = gv + gl;
    return s > 0.0 ? 0.5 / s : 0.0;
}

// The anisotropy direction of `s`, made perpendicular to s.n (the path tracer bends
// s.n toward the viewer after the direction was made).
vec3 anisotropy_direction(Surface s) {
    vec3 t = s.anisotropy.xyz - s.n * dot(s.n, s.anisotropy.xyz);
    return dot(t, t) > 1e-12 ? normalize(t) : cross(s.n, abs(s.n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0));
}

// The GGX specular D x V of `s` for light l (isotropic or anisotropic).
float ggx_dv(Surface s, vec3 l, vec3 h, float n_dot_l, float n_dot_v, float n_dot_h) {
    if (s.anisotropy.w > 0.0) {
        vec3 t = anisotropy_direction(s);
        vec3 b = cross(s.n, t);
        vec2 a = anisotropic_alpha(s.roughness, s.anisotropy.w);
        return d_ggx_anisotropic(vec3(dot(t, h), dot(b, h), n_dot_h), a) *
               v_smith_ggx_anisotropic(vec3(dot(t, s.v), dot(b, s.v), n_dot_v),
                                       vec3(dot(t, l), dot(b, l), n_dot_l), a);
    }
    float a = max(s.roughness * s.roughness, 1e-3);
    return d_ggx(n_dot_h, a) * v_smith_ggx(n_dot_l, n_dot_v, a);
}

// Outgoing radiance for unit radiance arriving from direction l.
vec3 brdf_times_cos(Surface s, vec3 l) {
    float n_dot_l = clamp(dot(s.n, l), 0.0, 1.0);
    if (n_dot_l <= 0.0) return vec3(0.0);
    vec3 h = normalize(l + s.v);
    float n_dot_v = clamp(abs(dot(s.n, s.v)), 1e-4, 1.0);
    float n_dot_h = clamp(dot(s.n, h), 0.0, 1.0);
    float v_dot_h = clamp(dot(s.v, h), 0.0, 1.0);
    vec3 f = fresnel_schlick(s.f0, s.f90, v_dot_h);
    // KHR_materials_iridescence: the film's Fresnel in proportion to its factor.
    if (s.iridescence.a > 0.0) f = mix(f, s.iridescence.rgb, s.iridescence.a);
    // (1 - F) per channel, as the specular-glossiness extension defines it; for
    // KHR_materials_specular's coloured F0 its spec weights by 1 - max(F) instead
    // (docs/materials.md).
    vec3 diffuse = (1.0 - f) * s.diffuse / PI;
    vec3 specular = f * ggx_dv(s, l, h, n_dot_l, n_dot_v, n_dot_h);
    return (diffuse + specular) * n_dot_l;
}

// KHR_materials_iridescence in the split-sum: the F0 whose Schlick Fresnel at n . v is
// the film's Fresnel there (three.js's Schlick_to_F0), mixed in by the factor.
vec3 iridescent_f0(Surface s, float n_dot_v) {
    if (s.iridescence.a <= 0.0) return s.f0;
    float x5 = min(pow5(clamp(1.0 - n_dot_v, 0.0, 1.0)), 0.9999);
    vec3 f0 = clamp((s.iridescence.rgb - x5) / (1.0 - x5), 0.0, 1.0);
    return mix(s.f0, f0, s.iridescence.a);
}

// The direction the environment's specular is read along: the reflection about n, or,
// for anisotropy, about the normal bent toward the plane across the anisotropy
// direction, the less the rougher (three.js's and the Khronos Sample Viewer's form).
vec3 specular_direction(Surface s) {
    if (s.anisotropy.w <= 0.0) return reflect(-s.v, s.n);
    vec3 b = cross(s.n, anisotropy_direction(s));
    vec3 across = cross(cross(b, s.v), b); // v projected on the plane normal to b
    if (dot(across, across) < 1e-12) return reflect(-s.v, s.n);
    float k = 1.0 - s.anisotropy.w * (1.0 - s.roughness);
    k *= k;
    vec3 bent = normalize(mix(normalize(across), s.n, k * k));
    return reflect(-s.v, bent);
}

// The simple ambient term: a sky/ground hemisphere (brighter above, darker below)
// instead of an environment map. Diffuse reads it along the normal, specular along
// the reflection vector, so normal-mapped metals still show their relief.
vec3 hemisphere(vec3 dir, vec3 radiance) {
    return radiance * mix(0.35, 1.6, 0.5 + 0.5 * dir.y);
}

vec3 ambient_light(Surface s, vec3 radiance) {
    float n_dot_v = clamp(abs(dot(s.n, s.v)), 1e-4, 1.0);
    vec3 f = s.f0 + (max(vec3((1.0 - s.roughness) * s.f90), s.f0) - s.f0) * pow5(1.0 - n_dot_v);
    if (s.iridescence.a > 0.0) f = mix(f, s.iridescence.rgb, s.iridescence.a);
    vec3 diffuse = (1.0 - f) * s.diffuse * hemisphere(s.n, radiance);
    vec3 r = specular_direction(s);
    // Rough surfaces see a blurrier sky: blend the reflected towards the normal's.
    vec3 specular = f * hemisphere(normalize(mix(r, s.n, s.roughness * s.roughness)), radiance);
    return diffuse + specular;
}
#endif
