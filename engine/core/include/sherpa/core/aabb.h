#pragma once
// Axis-aligned bounding boxes. An empty box is explicit (`valid() == false`) so
// that inverted +-FLT_MAX sentinels never leak into later stages.
#include <glm/glm.hpp>

namespace sherpa::core {

struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    bool valid_ = false;

    static Aabb empty() { return Aabb{}; }
    static Aabb from_min_max(glm::vec3 lo, glm::vec3 hi) { return Aabb{lo, hi, true}; }

    bool valid() const { return valid_; }
    void expand(glm::vec3 p);
    void expand(const Aabb& other);
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 extent() const { return max - min; }

    // Bounds of the 8 corners of this box transformed by `m` (affine or projective
    // with w = 1 assumed). Exact for the transformed box, not a loose sphere bound.
    Aabb transformed(const glm::mat4& m) const;
};

// True when every component is finite (no NaN or Inf).
bool is_finite(glm::vec3 v);
bool is_finite(const glm::mat4& m);

} // namespace sherpa::core
