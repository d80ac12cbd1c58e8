#pragma once
// One instance's record for the shaders (common.glsl's InstanceData), from its world
// transform: shared by the loaded scene (gpu_scene.cpp) and the per-frame pose
// (pose_pass.cpp), so both shade normals alike. joint_base is left 0 for the caller.
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include <sherpa/render/gpu_structs.h>

namespace sherpa::render {

inline GPUInstanceData make_instance_data(const glm::mat4& world, std::uint32_t material,
                                          std::uint32_t mesh) {
    GPUInstanceData g{};
    g.model = world;
    const glm::mat3 upper(world);
    // Degenerate (zero-scale) transforms have no inverse; their normals do not matter.
    const glm::mat3 nm =
        std::abs(glm::determinant(upper)) > 1e-30f ? glm::transpose(glm::inverse(upper)) : upper;
    for (int c = 0; c < 3; ++c) g.normal_matrix[c] = glm::vec4(nm[c], 0.0f);
    g.material = material;
    g.mesh = mesh;
    return g;
}

} // namespace sherpa::render
