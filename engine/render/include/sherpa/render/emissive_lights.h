#pragma once
// Emissive triangles as lights for the path tracer (docs/path_tracer.md, next-event
// estimation): every triangle of a static mesh whose material emits, in world space,
// drawn in proportion to its power (emitted luminance x area) through a CDF. Pure
// functions over the Scene, tested without a device; shaders/include/emissive_lights.glsl
// reads the records.
#include <sherpa/scene/scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace sherpa::gpu {

// std430, 48 bytes: GPUEmissiveTriangle in emissive_lights.glsl.
struct EmissiveTriangle {
    glm::vec4 p0_cdf;     // xyz first corner (world), w: the CDF up to and including it
    glm::vec4 e1_density; // xyz p1 - p0, w: density per area (luminance / total power)
    glm::vec4 e2;         // xyz p2 - p0
};
static_assert(sizeof(EmissiveTriangle) == 48);

// What the light list holds at most (48 bytes each: 12 MiB). A scene with more emissive
// triangles has no light list (BSDF sampling finds them, as before) and says so.
inline constexpr std::size_t kMaxEmissiveTriangles = std::size_t(1) << 18;
// Emitted luminance (factor x strength) above this is not sampled as a light: the path
// tracer caps a sample's luminance here (renderer_path.cpp), so such a light is
// clamped anyway, and its power would drown every other light's share.
inline constexpr float kMaxEmissiveLuminance = 1e20f;

struct EmissiveLights {
    std::vector<EmissiveTriangle> triangles; // empty: no light sampling
    float inv_power = 0.0f;            // 1 / (sum of luminance x area); the shader's density scale
    double power = 0.0;                // sum of luminance x area
    std::vector<std::string> warnings; // why some or all emitters are not sampled
};

// The luminance a material emits where its emissive texture is white (the weights of
// the shaders' luminance()). 0 for materials that do not emit or are unlit.
float emitted_luminance(const MaterialInstance& m);

// The light list of `scene` as its instances are placed (the default pose). A scene
// that animates (node animation, skins, morphs) gets none: its triangles move, and a
// stale list would bias the estimate, so BSDF sampling alone finds them.
EmissiveLights emissive_lights(const Scene& scene,
                               std::size_t max_triangles = kMaxEmissiveTriangles);

} // namespace sherpa::gpu
