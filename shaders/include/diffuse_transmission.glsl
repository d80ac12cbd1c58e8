// KHR_materials_diffuse_transmission in the raster's lit view: the share of the diffuse
// lobe that scatters through the surface is lit from the other side, Lambertian about
// -n, tinted by the diffuse transmission colour and the base colour (the glTF layering
// mix(diffuse_brdf, diffuse_btdf x colour, factor) under the dielectric's Fresnel), and
// attenuated by a volume over its thickness (Beer-Lambert), as the Khronos Sample Viewer
// does. Light from the environment (irradiance about -n, its specular albedo removed
// as for the front), the sun (its shadow map looked up at the fragment) and punctual
// lights. Needs brdf.glsl, ibl.glsl, shadows.glsl, punctual.glsl, frame constants.
#ifndef SHERPA_DIFFUSE_TRANSMISSION_GLSL
#define SHERPA_DIFFUSE_TRANSMISSION_GLSL

// Radiance towards the eye through the back of surface `s` (s.n faces the eye) for a
// transmitted diffuse albedo `albedo`; `shadow` the sun's visibility at the fragment.
vec3 diffuse_transmission_light(Surface s, vec3 albedo, vec3 pos, float shadow) {
    vec3 back = -s.n;
    float n_dot_v = clamp(dot(s.n, s.v), 1e-4, 1.0);
    vec3 f = fresnel_schlick(s.f0, s.f90, n_dot_v);
    vec3 c = vec3(0.0);
    vec3 sun_l = -normalize(frame.sun_direction.xyz);
    c += max(dot(back, sun_l), 0.0) / PI * frame.sun_radiance.rgb * shadow;
    for (uint i = 0u; i < frame.params.y; ++i) {
        vec3 l;
        float dist;
        vec3 radiance = punctual_incident(frame.lights[i], pos, l, dist);
        c += max(dot(back, l), 0.0) / PI * radiance;
    }
    c += has_environment() ? ibl_irradiance(back) : hemisphere(back, frame.ambient.rgb);
    return (1.0 - f) * albedo * c;
}
#endif
