#include <sherpa/core/aabb.h>

#include <cmath>

namespace sherpa::core {

void Aabb::expand(glm::vec3 p) {
    if (!valid_) {
        min = max = p;
        valid_ = true;
        return;
    }
    min = glm::min(min, p);
    max = glm::max(max, p);
}

void Aabb::expand(const Aabb& other) {
    if (!other.valid_) return;
    expand(other.min);
    expand(other.max);
}

Aabb Aabb::transformed(const glm::mat4& m) const {
    Aabb out;
    if (!valid_) return out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{(corner & 1) ? max.x : min.x, (corner & 2) ? max.y : min.y,
                          (corner & 4) ? max.z : min.z};
        out.expand(glm::vec3(m * glm::vec4(p, 1.0f)));
    }
    return out;
}

bool is_finite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool is_finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

} // namespace sherpa::core
