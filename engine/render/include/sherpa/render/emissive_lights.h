#pragma once
// Emissive triangles as lights for the path tracer (docs/path_tracer.md, next-event
// estimation): every triangle of a static mesh whose material emits, in world space,
// drawn in proportion to its power (emitted luminance x area x its emissive texture's
// mean over the triangle) through a CDF. Pure functions over the Scene, tested without
// a device; shaders/include/emissive_lights.glsl reads the records.
#include <sherpa/scene/scene.h>
#include <sherpa/texture/luminance_grid.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sherpa::tex {
struct PreparedTextureSet;
} // namespace sherpa::tex

namespace sherpa::render {

// std430, 64 bytes: GPUEmissiveTriangle in emissive_lights.glsl.
struct EmissiveTriangle {
    glm::vec4 p0_cdf;     // xyz first corner (world), w: the CDF up to and including it
    glm::vec4 e1_density; // xyz p1 - p0, w: density per area of drawing a point on it
    glm::vec4 e2;         // xyz p2 - p0
    // x: the material's emitted luminance (factor x strength; the density per area the
    // multiple-importance weights use is x / the list's material power, as the closest
    // hit computes it), y: the estimated emitted luminance over the triangle (x times
    // the texture's mean there: what a light sample's choice is weighted by), zw: 0.
    glm::vec4 emission;
};
static_assert(sizeof(EmissiveTriangle) == 64);

// A triangle's share of a light sample is its material's luminance x its area x the
// mean luminance of its emissive texture over it (1 without a texture), plus this
// fraction of the texture's mean over the whole image: every triangle whose material
// emits keeps a probability above 0 (an estimate of the mean over a triangle that
// missed a bright texel near its edge would otherwise make the estimator biased).
inline constexpr float kEmissiveTextureFloor = 0.01f;

// What the light list holds at most (64 bytes each: 16 MiB). A scene with more emissive
// triangles has no light list (BSDF sampling finds them, as before) and says so.
inline constexpr std::size_t kMaxEmissiveTriangles = std::size_t(1) << 18;
// Emitted luminance (factor x strength) above this is not sampled as a light: the path
// tracer caps a sample's luminance here (renderer_path.cpp), so such a light is
// clamped anyway, and its power would drown every other light's share.
inline constexpr float kMaxEmissiveLuminance = 1e20f;

struct EmissiveLights {
    std::vector<EmissiveTriangle> triangles; // empty: no light sampling
    // 1 / (sum of material luminance x area): the density scale of the multiple-importance
    // weights (the closest hit knows the material, not the triangle's texture mean).
    float inv_power = 0.0f;
    double power = 0.0;                // sum of material luminance x area
    double sampled_power = 0.0;        // sum of the triangles' shares (texture means included)
    std::uint32_t textures_read = 0;   // emissive images decoded here for the triangles' means
    std::uint32_t textures_reused = 0; // those whose grid the texture pipeline made instead
    // Why some or all emitters are not sampled, one line each naming the file, the JSON
    // pointer where one applies, and the problem ("FILE: /materials/3/emissiveTexture: ...").
    std::vector<std::string> warnings;
};

// The luminance a material emits where its emissive texture is white (the weights of
// the shaders' luminance()). 0 for materials that do not emit or are unlit.
float emitted_luminance(const scene::MaterialInstance& m);

// A texture's luminance (linear, from its sRGB texels), box-filtered down to at most
// kEmissiveGridSize texels a side, for the triangles' means: the texture layer's
// (luminance_grid.h), which makes it for emissive images while it decodes them.
inline constexpr std::uint32_t kEmissiveGridSize = tex::kLuminanceGridSize;
using LuminanceGrid = tex::LuminanceGrid;
using tex::luminance_grid;

// The grid's mean over the triangle with texture coordinates `uv` (after the texture
// transform): nearest texels at the centroids of 64 equal sub-triangles, wrapped as
// the sampler wraps.
double mean_over_triangle(const LuminanceGrid& grid, const glm::vec2 uv[3],
                          scene::AddressMode wrap_u = scene::AddressMode::Repeat,
                          scene::AddressMode wrap_v = scene::AddressMode::Repeat);

// The light list of `scene` as its instances are placed (the default pose). A scene
// that animates (node animation, skins, morphs) gets none: its triangles move, and a
// stale list would bias the estimate, so BSDF sampling alone finds them. `textures`:
// the scene's prepared textures, whose luminance grids (and failures) are taken
// instead of decoding the emissive images again; null: every emissive image is decoded.
EmissiveLights emissive_lights(const scene::Scene& scene,
                               std::size_t max_triangles = kMaxEmissiveTriangles,
                               const tex::PreparedTextureSet* textures = nullptr);

} // namespace sherpa::render
