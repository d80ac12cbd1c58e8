// Frustum extraction and the single-box reference tests.
#include <sherpa/scene/culling.h>

#include <cmath>
#include <limits>

namespace sherpa::scene {

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

// The axes that can separate a world AABB from the frustum besides the frustum's
// own planes: the 3 box face normals and the crosses of the box edge directions
// with the frustum edge directions (4 lateral edges, 2 near-rectangle sides; the
// far rectangle's sides are parallel to the near one's).
void build_separating_axes(Frustum& f) {
    glm::dvec3 edges[6];
    for (int c = 0; c < 4; ++c) {
        const glm::vec4 a = f.corners[static_cast<std::size_t>(c)],
                        b = f.corners[static_cast<std::size_t>(c + 4)];
        edges[c] = b.w == 0.0f ? glm::dvec3(b)
                               : (a.w == 0.0f ? glm::dvec3(a) : glm::dvec3(b) - glm::dvec3(a));
    }
    const bool first_finite =
        f.corners[0].w != 0.0f && f.corners[1].w != 0.0f && f.corners[2].w != 0.0f;
    const std::size_t base =
        first_finite ? 0 : 4; // reverse-Z infinite: corners 0..3 are at infinity
    edges[4] = glm::dvec3(f.corners[base + 1]) - glm::dvec3(f.corners[base]);
    edges[5] = glm::dvec3(f.corners[base + 2]) - glm::dvec3(f.corners[base]);
    auto add = [&](glm::dvec3 axis) {
        const double len = glm::length(axis);
        if (!(len > 1e-9)) return; // parallel edges give no axis
        axis /= len;
        const std::uint32_t k = f.sat_count++;
        f.sat_axes[k] = axis;
        frustum_interval(f, axis, f.sat_lo[k], f.sat_hi[k]);
    };
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 axis(0.0);
        axis[a] = 1.0;
        add(axis);
    }
    for (const glm::dvec3& e : edges)
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 axis(0.0);
            axis[a] = 1.0;
            add(glm::cross(axis, e));
        }
}

} // namespace

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
    if (!f.empty) build_separating_axes(f);
    return f;
}

bool box_is_invalid(glm::vec3 lo, glm::vec3 hi) {
    return !(core::is_finite(lo) && core::is_finite(hi) && lo.x <= hi.x && lo.y <= hi.y &&
             lo.z <= hi.z);
}

bool sphere_visible(const Frustum& f, const core::Aabb& box) {
    if (f.empty) return false;
    const glm::vec3 c = box.center();
    const float r = 0.5f * glm::length(box.extent());
    for (std::uint32_t i = 0; i < f.plane_count; ++i)
        if (f.planes[i].distance(c) < -r) return false;
    return true;
}

namespace {

// The box corner farthest along the plane normal (p-vertex), or against it (n-vertex).
glm::vec3 p_vertex(const Plane& p, const core::Aabb& b) {
    return {p.normal.x >= 0 ? b.max.x : b.min.x, p.normal.y >= 0 ? b.max.y : b.min.y,
            p.normal.z >= 0 ? b.max.z : b.min.z};
}
glm::vec3 n_vertex(const Plane& p, const core::Aabb& b) {
    return {p.normal.x >= 0 ? b.min.x : b.max.x, p.normal.y >= 0 ? b.min.y : b.max.y,
            p.normal.z >= 0 ? b.min.z : b.max.z};
}

} // namespace

bool pvertex_visible(const Frustum& f, const core::Aabb& box) {
    if (f.empty) return false;
    for (std::uint32_t i = 0; i < f.plane_count; ++i)
        if (f.planes[i].distance(p_vertex(f.planes[i], box)) < 0.0f) return false;
    return true;
}

bool exact_visible(const Frustum& f, const core::Aabb& box) {
    if (f.empty) return false;
    // Frustum planes: reject on any (the p-vertex test), and accept at once when
    // the box's n-vertex is inside every plane (the box lies wholly inside).
    bool wholly_inside = true;
    for (std::uint32_t i = 0; i < f.plane_count; ++i) {
        const Plane& p = f.planes[i];
        if (p.distance(p_vertex(p, box)) < 0.0f) return false;
        wholly_inside &= p.distance(n_vertex(p, box)) >= 0.0f;
    }
    if (wholly_inside) return true;
    const glm::dvec3 c = glm::dvec3(box.center()), e = 0.5 * glm::dvec3(box.extent());
    for (std::uint32_t k = 0; k < f.sat_count; ++k) {
        const glm::dvec3& axis = f.sat_axes[k];
        const double r = std::abs(axis.x) * e.x + std::abs(axis.y) * e.y + std::abs(axis.z) * e.z;
        const double m = glm::dot(c, axis);
        if (m + r < f.sat_lo[k] || m - r > f.sat_hi[k]) return false;
    }
    return true;
}

} // namespace sherpa::scene
