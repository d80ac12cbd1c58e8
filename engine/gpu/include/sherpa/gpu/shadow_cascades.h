#pragma once
// Cascaded shadow maps for the main directional light: split the camera's depth
// range (up to the farthest point of the scene) and fit each slice's bounding
// sphere with a texel-snapped orthographic projection, so shadows do not shimmer
// as the camera moves. Depth range covers the whole scene so off-screen casters
// still cast. Shadow depth is standard Z (0 near the light), compared LESS_OR_EQUAL.
#include <cstdint>

#include <glm/glm.hpp>

#include <sherpa/core/aabb.h>
#include <sherpa/gpu/camera.h>
#include <sherpa/gpu/gpu_structs.h>

namespace sherpa::gpu {

struct CascadeSetup {
    glm::mat4 view_proj[kMaxCascades]{};
    glm::vec4 splits{0.0f}; // view depth where cascade i ends
    glm::vec4 texel{0.0f};  // world size of one shadow-map texel in cascade i
    std::uint32_t count = 0;
};

// `light_dir`: the direction light travels (unit). Returns count 0 when the scene
// bounds are empty.
CascadeSetup fit_cascades(const CameraView& camera, const Aabb& scene_bounds, glm::vec3 light_dir,
                          std::uint32_t cascades, std::uint32_t resolution);

} // namespace sherpa::gpu
