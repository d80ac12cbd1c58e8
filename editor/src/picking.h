#pragma once
// Click-to-pick: the nearest visible instance under a world-space ray, exact to
// the triangle (box test first, then every triangle of the candidate's mesh in
// its local space; lines and points are hit within a thin cone around the ray).
// Qt-free.
#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

#include <sherpa/scene/scene.h>

namespace sherpa::editor {

struct PickHit {
    std::int64_t instance = -1; // Scene::instances, -1: nothing hit
    std::int64_t triangle = -1; // in the instance's mesh (segment or point for those)
    float distance = 0.0f;      // along the ray, world units
    explicit operator bool() const { return instance >= 0; }
};

// `visible(i)` filters instances (hidden nodes are not pickable).
PickHit pick(const scene::Scene& scene, glm::vec3 origin, glm::vec3 direction,
             const std::function<bool(std::size_t)>& visible);

} // namespace sherpa::editor
