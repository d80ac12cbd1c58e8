#pragma once
// Cascaded shadow maps for the main directional light, fitted once for every
// user: the renderer draws these cascades and `sherpa-cli cull` culls them.
//
// The camera's depth range (up to the farthest point of the scene) is split
// (practical scheme, mostly logarithmic); each slice's bounding sphere gets a
// texel-snapped orthographic projection (no shimmer as the camera moves) whose
// depth range covers the whole scene, so casters outside the view still cast.
// Shadow depth is standard Z (0 nearest the light).
//
// Culling volume of cascade i (`cull_view_proj`): the cascade's light-space box
// with its near side at the scene's side nearest the light (off-screen casters
// between the light and the slice are kept, however large) and its far side at
// the slice's farthest point from the light (plus a margin): nothing farther from
// the light than every receiver of the slice can shadow it.
#include <array>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include <sherpa/core/aabb.h>
#include <sherpa/scene/camera_spec.h>

namespace sherpa::scene {

struct Scene;

inline constexpr std::uint32_t kMaxShadowCascades = 4;
// What the renderer uses unless told otherwise (FrameRequest, RendererOptions);
// `sherpa-cli cull` uses the same so its cascades are the ones the renderer draws.
inline constexpr std::uint32_t kDefaultShadowCascades = 3;
inline constexpr std::uint32_t kDefaultShadowResolution = 2048;
// Direction the default sun's light travels when a scene has no lights at all.
inline constexpr glm::vec3 kDefaultSunDirection{-0.4f, -1.0f, -0.55f};

// What the fit needs of a camera (the renderer's resolved camera, or a CameraSpec).
struct CascadeCamera {
    glm::mat4 view{1.0f};
    float near_plane = 0.05f, far_plane = 0.0f; // far 0: infinite
    float fov_y = 1.0471976f, aspect = 1.0f;    // radians, width / height
    bool orthographic = false;
    float ortho_half_width = 1.0f, ortho_half_height = 1.0f;
};
CascadeCamera cascade_camera(const CameraSpec& spec);

struct ShadowCascades {
    std::array<glm::mat4, kMaxShadowCascades> view_proj{};      // rendering (standard Z)
    std::array<glm::mat4, kMaxShadowCascades> cull_view_proj{}; // culling volume, see above
    glm::vec4 splits{0.0f};                                     // view depth where cascade i ends
    glm::vec4 texel{0.0f}; // world size of one shadow-map texel in cascade i
    std::uint32_t count = 0;
};

// `light_dir`: the direction light travels. Returns count 0 when the bounds are
// empty or `cascades` is 0; at most kMaxShadowCascades.
ShadowCascades fit_shadow_cascades(const CascadeCamera& camera, const core::Aabb& scene_bounds,
                                   glm::vec3 light_dir, std::uint32_t cascades,
                                   std::uint32_t resolution);

// The shadowed main light: the first placed directional light; with no placed
// lights at all a default sun (`default_sun`); none when the scene has lights but
// no directional one.
std::optional<glm::vec3> main_light_direction(const Scene& scene,
                                              glm::vec3 default_sun = kDefaultSunDirection);

// Bounds of the instances that draw (a mesh with triangles): what the renderer
// uploads and fits its cascades to.
core::Aabb drawable_bounds(const Scene& scene);

} // namespace sherpa::scene
