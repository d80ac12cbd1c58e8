#include "picking.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sherpa::editor {

namespace {

// Slab test; returns the entry distance or +inf when the ray misses the box.
float ray_box(glm::vec3 o, glm::vec3 inv_d, const core::Aabb& box) {
    const glm::vec3 t0 = (box.min - o) * inv_d;
    const glm::vec3 t1 = (box.max - o) * inv_d;
    const glm::vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
    const float enter = std::max({lo.x, lo.y, lo.z, 0.0f});
    const float exit = std::min({hi.x, hi.y, hi.z});
    return enter <= exit ? enter : std::numeric_limits<float>::infinity();
}

// Möller-Trumbore, both faces (the inspector picks back faces too).
float ray_triangle(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(d, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::numeric_limits<float>::infinity();
    const float inv = 1.0f / det;
    const glm::vec3 s = o - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return std::numeric_limits<float>::infinity();
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(d, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return std::numeric_limits<float>::infinity();
    const float t = glm::dot(e2, q) * inv;
    return t > 0.0f ? t : std::numeric_limits<float>::infinity();
}

// Lines and points have no area: they are hit where they pass within this cone
// around the ray (radius per unit of distance, about 0.6 degrees: a few pixels).
constexpr float kThinPickRadius = 0.01f;

// Distance along the ray to where it passes closest to segment ab, when that pass
// lies within the pick cone; +inf otherwise. A point is the segment a == b.
float ray_segment(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b) {
    const glm::vec3 u = glm::normalize(d), e = b - a, w = o - a;
    const float ee = glm::dot(e, e), ue = glm::dot(u, e);
    const float denom = ee - ue * ue; // |e|^2 sin^2: 0 when parallel or a point
    float s = 0.0f;                   // along the segment, 0..1
    if (ee > 0.0f)
        s = denom > 1e-12f * ee
                ? std::clamp((glm::dot(e, w) - ue * glm::dot(u, w)) / denom, 0.0f, 1.0f)
                : 0.0f;
    const glm::vec3 p = a + s * e;
    const float t = glm::dot(p - o, u); // along the unit ray
    if (t <= 0.0f) return std::numeric_limits<float>::infinity();
    const float miss = glm::length(o + t * u - p);
    return miss <= kThinPickRadius * t ? t / glm::length(d)
                                       : std::numeric_limits<float>::infinity();
}

} // namespace

PickHit pick(const scene::Scene& scene, glm::vec3 origin, glm::vec3 direction,
             const std::function<bool(std::size_t)>& visible) {
    PickHit best;
    best.distance = std::numeric_limits<float>::infinity();
    const glm::vec3 inv_d = 1.0f / direction;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const scene::MeshInstance& inst = scene.instances[i];
        if (!inst.world_bounds.valid() || !visible(i)) continue;
        const scene::Mesh& mesh = scene.meshes[inst.mesh_id];
        core::Aabb box = inst.world_bounds;
        if (mesh.topology() != scene::Topology::Triangles) {
            // Grown by the pick cone's radius there: a flat line's box has no thickness.
            const float r =
                kThinPickRadius * (glm::length(box.center() - origin) + glm::length(box.extent()));
            box.min -= glm::vec3(r);
            box.max += glm::vec3(r);
        }
        if (ray_box(origin, inv_d, box) >= best.distance) continue;
        // Local-space ray: t stays a world distance because the direction is not renormalised.
        const glm::mat4 to_local = glm::inverse(inst.world);
        const glm::vec3 lo = glm::vec3(to_local * glm::vec4(origin, 1.0f));
        const glm::vec3 ld = glm::vec3(to_local * glm::vec4(direction, 0.0f));
        if (mesh.topology() != scene::Topology::Triangles) {
            // Element e: segment (2e, 2e+1) or point e, reported as `triangle`.
            const std::size_t per = scene::indices_per_element(mesh.topology());
            for (std::size_t e = 0; e + per <= mesh.indices.size(); e += per) {
                const float hit = ray_segment(lo, ld, mesh.vertices[mesh.indices[e]].position,
                                              mesh.vertices[mesh.indices[e + per - 1]].position);
                if (hit < best.distance) {
                    best.distance = hit;
                    best.instance = static_cast<std::int64_t>(i);
                    best.triangle = static_cast<std::int64_t>(e / per);
                }
            }
            continue;
        }
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const float hit = ray_triangle(lo, ld, mesh.vertices[mesh.indices[t]].position,
                                           mesh.vertices[mesh.indices[t + 1]].position,
                                           mesh.vertices[mesh.indices[t + 2]].position);
            if (hit < best.distance) {
                best.distance = hit;
                best.instance = static_cast<std::int64_t>(i);
                best.triangle = static_cast<std::int64_t>(t / 3);
            }
        }
    }
    if (best.instance < 0) best.distance = 0.0f;
    return best;
}

} // namespace sherpa::editor
