// The path tracer's ray payload (pt.rgen, pt.rchit, pt.rahit, pt.rmiss): the hit
// surface's BRDF inputs, made by the closest-hit shader with the raster's material
// functions (material_sampling.glsl, brdf.glsl's *_surface()).
#ifndef SHERPA_PATH_PAYLOAD_GLSL
#define SHERPA_PATH_PAYLOAD_GLSL
const uint PATH_RAY_CAMERA = 0u;  // the camera ray and bounces (closest hit)
const uint PATH_RAY_SHADOW = 1u;  // visibility toward a light (any hit ends it)
const uint PATH_HIT_UNLIT = 1u;   // KHR_materials_unlit (or no surface): emission only
// The material has extension blocks: the fields from transmission_tint on are written.
// Without it they are not (the closest hit and pt.rgen skip them: on lavapipe every
// payload field is a store and a load per lane), and mean no transmission, coat, sheen,
// anisotropy or iridescence.
const uint PATH_HIT_EXTENDED = 2u;

struct PathPayload {
    vec3 position;  // world hit point
    uint hit;       // 1 hit, 0 miss
    vec3 geometric; // unit face normal on the ray's side
    uint flags;     // PATH_HIT_*
    vec3 normal;    // shading normal (normal-mapped, of the side seen)
    float roughness;
    vec3 diffuse;
    uint kind;      // PATH_RAY_*, set by the tracer
    vec3 f0;
    uint seed;      // set by the tracer: any-hit draws stochastic transparency from it
    vec3 emission;
    float f90; // Surface::f90 (brdf.glsl): 1 but for KHR_materials_specular's dielectrics
    float light_luminance; // emitted luminance if the hit triangle is in the light list, else 0
    // Written only with PATH_HIT_EXTENDED (below).
    // The transmission family (transmission_sampling.glsl): the transmission lobe's
    // tint (transmission x base colour x (1 - metallic); 0: opaque), the ior, the
    // volume's attenuation (rgb colour, a distance; a < 0: thin-walled, no volume),
    // the dispersion, and whether the ray arrived on the front face.
    vec3 transmission_tint;
    float ior;
    vec3 diffuse_transmission_tint; // KHR_materials_diffuse_transmission's lobe (0: none)
    float pad0;
    vec4 attenuation;
    float dispersion;
    uint front;
    vec3 clearcoat_normal;    // KHR_materials_clearcoat (clearcoat.glsl's Clearcoat)
    float clearcoat;          // 0: no coat
    float clearcoat_roughness;
    vec3 sheen_color; // KHR_materials_sheen (sheen.glsl's Sheen); black: no sheen
    float sheen_roughness;
    vec4 anisotropy; // KHR_materials_anisotropy: Surface::anisotropy (w 0: isotropic)
    vec4 iridescence; // KHR_materials_iridescence: Surface::iridescence (a 0: none)
};
#endif
