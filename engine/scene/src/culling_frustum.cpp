// Frustum extraction and the single-box reference tests.
#include <sherpa/scene/culling.h>

#include <cmath>
#include <limits>

namespace sherpa {

std::string_view to_string(CullMethod m) {
    switch (m) {
    case CullMethod::Sphere:
        return "sphere";
    case CullMethod::PVertex:
        return "pvertex";
    case CullMethod::Exact:
        return "exact";
    }
    return "?";
}

bool parse_cull_method(std::string_view s, CullMethod& out) {
    for (CullMethod m : {CullMethod::Sphere, CullMethod::PVertex, CullMethod::Exact})
        if (s == to_string(m)) {
            out = m;
            return true;
        }
    return false;
}

Frustum frustum_from_view_projection(const glm::mat4& m) {
    Frustum f;
    // Rows of the matrix (glm is column-major: m[col][row]).
    auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    const glm::dvec4 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    // Clip-space inequalities -w <= x <= w, -w <= y <= w, 0 <= z <= w.
    const glm::dvec4 raw[6] = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2};
    for (const glm::dvec4& p : raw) {
        const double len = glm::length(glm::dvec3(p));
        if (!std::isfinite(len) || !std::isfinite(p.w)) {
            f.empty = true;
            continue;
        }
        if (len < 1e-12 * std::max(1.0, std::abs(p.w))) {
            // Plane at infinity (infinite far): always satisfied if w >= 0.
            if (p.w < 0.0) f.empty = true;
            continue;
        }
        f.planes[f.plane_count++] =
            Plane{glm::vec3(glm::dvec3(p) / len), static_cast<float>(p.w / len)};
    }
    const glm::dmat4 inv = glm::inverse(glm::dmat4(m));
    for (int c = 0; c < 8; ++c) {
        const glm::dvec4 ndc((c & 1) ? 1.0 : -1.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : 0.0, 1.0);
        glm::dvec4 p = inv * ndc;
        if (std::abs(p.w) < 1e-12 * glm::length(glm::dvec3(p)))
            p.w = 0.0; // at infinity
        else
            p /= p.w;
        f.corners[static_cast<std::size_t>(c)] = glm::vec4(p);
    }
    return f;
}

bool box_is_invalid(glm::vec3 lo, glm::vec3 hi) {
    return !(is_finite(lo) && is_finite(hi) && lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z);
}

bool sphere_visible(const Frustum& f, const Aabb& box) {
    if (f.empty) return false;
    const glm::vec3 c = box.center();
    const float r = 0.5f * glm::length(box.extent());
    for (std::uint32_t i = 0; i < f.plane_count; ++i)
        if (f.planes[i].distance(c) < -r) return false;
    return true;
}

bool pvertex_visible(const Frustum& f, const Aabb& box) {
    if (f.empty) return false;
    for (std::uint32_t i = 0; i < f.plane_count; ++i) {
        const Plane& p = f.planes[i];
        const glm::vec3 v{p.normal.x >= 0 ? box.max.x : box.min.x,
                          p.normal.y >= 0 ? box.max.y : box.min.y,
                          p.normal.z >= 0 ? box.max.z : box.min.z};
        if (p.distance(v) < 0.0f) return false;
    }
    return true;
}

namespace {

// Projection interval of the frustum on `axis`; corners at infinity extend it.
void frustum_interval(const Frustum& f, glm::dvec3 axis, double& lo, double& hi) {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (const glm::vec4& c : f.corners) {
        const double d = glm::dot(glm::dvec3(c), axis);
        if (c.w == 0.0f) {
            if (d > 1e-12) hi = std::numeric_limits<double>::infinity();
            if (d < -1e-12) lo = -std::numeric_limits<double>::infinity();
        } else {
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    }
}

void box_interval(const Aabb& b, glm::dvec3 axis, double& lo, double& hi) {
    const glm::dvec3 c = glm::dvec3(b.center()), e = 0.5 * glm::dvec3(b.extent());
    const double r = std::abs(axis.x) * e.x + std::abs(axis.y) * e.y + std::abs(axis.z) * e.z;
    const double m = glm::dot(c, axis);
    lo = m - r;
    hi = m + r;
}

bool separated_on(const Frustum& f, const Aabb& b, glm::dvec3 axis) {
    const double len = glm::length(axis);
    if (len < 1e-9) return false; // parallel edges: no axis
    axis /= len;
    double flo, fhi, blo, bhi;
    frustum_interval(f, axis, flo, fhi);
    box_interval(b, axis, blo, bhi);
    return bhi < flo || blo > fhi;
}

} // namespace

bool exact_visible(const Frustum& f, const Aabb& box) {
    if (!pvertex_visible(f, box)) return false; // frustum face normals: the cheap axes
    // Box face normals.
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 axis(0.0);
        axis[a] = 1.0;
        if (separated_on(f, box, axis)) return false;
    }
    // Edge x edge axes. Frustum edge directions: the 4 lateral edges (near corner to
    // far corner, or the direction at infinity) and the near rectangle's 2 sides
    // (the far rectangle's sides are parallel to them).
    glm::dvec3 edges[6];
    for (int c = 0; c < 4; ++c) {
        const glm::vec4 a = f.corners[static_cast<std::size_t>(c)],
                        b = f.corners[static_cast<std::size_t>(c + 4)];
        const glm::dvec3 pa = glm::dvec3(a), pb = glm::dvec3(b);
        edges[c] = b.w == 0.0f ? pb : (a.w == 0.0f ? -pa : pb - pa);
    }
    const glm::vec4 c0 = f.corners[0], c1 = f.corners[1], c2 = f.corners[2];
    const bool near_finite = c0.w != 0.0f && c1.w != 0.0f && c2.w != 0.0f;
    const glm::vec4 d0 = f.corners[4], d1 = f.corners[5], d2 = f.corners[6];
    if (near_finite) {
        edges[4] = glm::dvec3(c1) - glm::dvec3(c0);
        edges[5] = glm::dvec3(c2) - glm::dvec3(c0);
    } else { // reverse-Z infinite: corners 0..3 are the far ones; use 4..6
        edges[4] = glm::dvec3(d1) - glm::dvec3(d0);
        edges[5] = glm::dvec3(d2) - glm::dvec3(d0);
    }
    for (const glm::dvec3& e : edges)
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 axis_dir(0.0);
            axis_dir[a] = 1.0;
            if (separated_on(f, box, glm::cross(axis_dir, e))) return false;
        }
    return true;
}

} // namespace sherpa
