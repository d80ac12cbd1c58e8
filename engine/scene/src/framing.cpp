#include <sherpa/scene/framing.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sherpa::scene {

namespace {

// A box made usable: invalid -> the unit cube, so callers always get a camera.
core::Aabb usable(const core::Aabb& box) {
    if (box.valid() && core::is_finite(box.min) && core::is_finite(box.max)) return box;
    return core::Aabb::from_min_max(glm::vec3(-1.0f), glm::vec3(1.0f));
}

glm::vec3 corner(const core::Aabb& b, int i) {
    return {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
}

// The view's axes looking from `to_eye` (towards the eye; +Z when zero).
struct ViewAxes {
    glm::vec3 back, world_up, right, up;
};
ViewAxes view_axes(glm::vec3 to_eye) {
    ViewAxes a;
    a.back =
        glm::dot(to_eye, to_eye) > 1e-20f ? glm::normalize(to_eye) : glm::vec3(0.0f, 0.0f, 1.0f);
    // lookAt needs an up that is not parallel to the view.
    a.world_up =
        std::abs(a.back.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    a.right = glm::normalize(glm::cross(a.world_up, a.back));
    a.up = glm::cross(a.back, a.right);
    return a;
}

} // namespace

glm::vec3 auto_view_direction(const core::Aabb& box_in, glm::vec3 front_hint) {
    const core::Aabb box = usable(box_in);
    glm::vec3 front{0.0f, 0.0f, 1.0f}, side{1.0f, 0.0f, 0.0f};
    const glm::vec2 hint{front_hint.x, front_hint.z};
    if (glm::dot(hint, hint) > 1e-12f) {
        const glm::vec2 h = glm::normalize(hint);
        front = {h.x, 0.0f, h.y};
        side = {h.y, 0.0f, -h.x}; // front turned 90 degrees clockwise seen from above
    } else if (const glm::vec3 e = box.extent(); e.x < 0.8f * e.z) {
        // Thinner along X: the model faces +X. Turn towards +Z, the glTF front.
        front = {1.0f, 0.0f, 0.0f};
        side = {0.0f, 0.0f, 1.0f};
    }
    const float az = glm::radians(kFramingAzimuthDegrees);
    const float el = glm::radians(kFramingElevationDegrees);
    const glm::vec3 horizontal = std::cos(az) * front + std::sin(az) * side;
    return glm::normalize(std::cos(el) * horizontal + glm::vec3(0.0f, std::sin(el), 0.0f));
}

CameraSpec frame_box_along(const core::Aabb& box_in, glm::vec3 to_eye, const FramingOptions& o) {
    const core::Aabb box = usable(box_in);
    const glm::vec3 c = box.center(), half = 0.5f * box.extent();
    const float radius = std::max(glm::length(half), 1e-4f);
    const float m = std::max(o.margin, 0.0f) * radius;
    const auto [back, world_up, right, up] = view_axes(to_eye);
    const float border = 1.0f - std::clamp(o.margin, 0.0f, 0.5f);
    const float tan_y = std::tan(0.5f * glm::radians(o.fov_y_degrees)) * border;
    const float tan_x = tan_y * (o.aspect > 0.0f ? o.aspect : 1.0f);

    // d is the eye's distance from the centre along `back`. A corner at `rel` from the
    // centre lies (d - dot(rel, back)) in front of the eye and must satisfy
    // |x| <= depth * tan_x, |y| <= depth * tan_y and depth >= m.
    float d = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 rel = corner(box, i) - c;
        const float z = glm::dot(rel, back);
        d = std::max({d, z + std::abs(glm::dot(rel, right)) / tan_x,
                      z + std::abs(glm::dot(rel, up)) / tan_y, z + m});
    }
    // Outside the box grown by m: beyond its slab on at least one axis.
    float outside = INFINITY;
    for (int a = 0; a < 3; ++a)
        if (std::abs(back[a]) > 1e-6f)
            outside = std::min(outside, (half[a] + m) / std::abs(back[a]));
    d = std::max(d, outside);
    // Looking down (up) noticeably: the eye above the top (below the bottom), else a
    // cube seen from an eye level with its sides reads as a flat trapezoid.
    if (std::abs(back.y) > 0.2f) d = std::max(d, (half.y + m) / std::abs(back.y));

    float nearest = INFINITY;
    for (int i = 0; i < 8; ++i) nearest = std::min(nearest, d - glm::dot(corner(box, i) - c, back));
    CameraSpec s;
    s.eye = c + back * d;
    s.target = c;
    s.up = world_up;
    s.fov_y_degrees = o.fov_y_degrees;
    s.aspect = o.aspect > 0.0f ? o.aspect : 1.0f;
    // Half the nearest corner's depth, at most 1% of the distance: room to orbit at
    // that distance; reverse-Z keeps depth precision with a small near plane.
    s.near_plane = std::max(std::min(0.5f * nearest, 0.01f * d), 1e-5f);
    s.far_plane = 0.0f;
    return s;
}

CameraSpec frame_points_along(std::span<const glm::vec3> points, glm::vec3 to_eye,
                              const FramingOptions& o) {
    core::Aabb box;
    for (const glm::vec3& p : points)
        if (core::is_finite(p)) box.expand(p);
    if (!box.valid()) return frame_box_along(box, to_eye, o);
    const glm::vec3 c = box.center();
    const float radius = std::max(glm::length(0.5f * box.extent()), 1e-4f);
    const float m = std::max(o.margin, 0.0f) * radius;
    const auto [back, world_up, right, up] = view_axes(to_eye);
    const float fill = std::clamp(o.fill, 0.05f, 1.0f);
    const float tan_y = std::tan(0.5f * glm::radians(o.fov_y_degrees)) * fill;
    const float tan_x = tan_y * (o.aspect > 0.0f ? o.aspect : 1.0f);

    // Per axis, a point at (x, z) (across, towards the eye; from c) seen from an eye at
    // (s, d) is inside when |x - s| <= t (d - z): s >= x + t z - t d and
    // s <= x - t z + t d. Some s fits every point iff d >= (hi - lo) / 2t with
    // hi = max(x + t z), lo = min(x - t z): the tighter axis decides d.
    std::vector<glm::vec3> local; // (x, y, z) of each finite point
    local.reserve(points.size());
    float hi_x = -INFINITY, lo_x = INFINITY, hi_y = -INFINITY, lo_y = INFINITY, z_max = -INFINITY;
    for (const glm::vec3& p : points) {
        if (!core::is_finite(p)) continue;
        const glm::vec3 rel = p - c;
        const glm::vec3 q{glm::dot(rel, right), glm::dot(rel, up), glm::dot(rel, back)};
        local.push_back(q);
        hi_x = std::max(hi_x, q.x + tan_x * q.z), lo_x = std::min(lo_x, q.x - tan_x * q.z);
        hi_y = std::max(hi_y, q.y + tan_y * q.z), lo_y = std::min(lo_y, q.y - tan_y * q.z);
        z_max = std::max(z_max, q.z);
    }
    const float d = std::max(
        {(hi_x - lo_x) / (2.0f * tan_x), (hi_y - lo_y) / (2.0f * tan_y), z_max + m, 1e-4f});
    // Then, per axis, the offset s that centres the points on screen: the largest and
    // the smallest (x - s) / (d - z) equal and opposite. Their sum falls as s grows
    // and changes sign between the points' least and greatest x: bisection. (On the
    // tighter axis this is (hi + lo) / 2; on the other the perspective makes it differ.)
    const auto centre = [&](int axis) {
        float lo = INFINITY, hi = -INFINITY;
        for (const glm::vec3& q : local) lo = std::min(lo, q[axis]), hi = std::max(hi, q[axis]);
        for (int i = 0; i < 60 && lo < hi; ++i) {
            const float mid = 0.5f * (lo + hi);
            if (mid <= lo || mid >= hi) break; // no float between them
            float most = -INFINITY, least = INFINITY;
            for (const glm::vec3& q : local) {
                const float v = (q[axis] - mid) / (d - q.z);
                most = std::max(most, v), least = std::min(least, v);
            }
            (most + least > 0.0f ? lo : hi) = mid;
        }
        return 0.5f * (lo + hi);
    };
    const glm::vec3 target = c + right * centre(0) + up * centre(1);
    CameraSpec s;
    s.eye = target + back * d;
    s.target = target;
    s.up = world_up;
    s.fov_y_degrees = o.fov_y_degrees;
    s.aspect = o.aspect > 0.0f ? o.aspect : 1.0f;
    // As frame_box_along: half the nearest point's depth, at most 1% of the distance.
    s.near_plane = std::max(std::min(0.5f * (d - z_max), 0.01f * d), 1e-5f);
    s.far_plane = 0.0f;
    return s;
}

CameraSpec frame_box(const core::Aabb& box, const FramingOptions& options, glm::vec3 front_hint) {
    return frame_box_along(box, auto_view_direction(box, front_hint), options);
}

} // namespace sherpa::scene
