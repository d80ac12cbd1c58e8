#pragma once
// Shared pieces of the tangent generators (engine/scene/src/tangent_*.cpp). Not installed.
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/scene/tangents.h>

namespace sherpa::tangent_detail {

// The reference's "non-zero" test: magnitudes at or below FLT_MIN count as zero. NaN is
// never non-zero.
inline bool not_zero(float x) {
    return std::fabs(x) > std::numeric_limits<float>::min();
}
inline bool not_zero(const glm::vec3& v) {
    return not_zero(v.x) || not_zero(v.y) || not_zero(v.z);
}

// The reference's dot product, summed left to right so results match it bit for bit.
inline float dot3(const glm::vec3& a, const glm::vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// sqrt(x²+y²+z²) like the reference where that is representable; rescaled where the
// squares overflow (coordinates beyond ~1e19) or underflow (below ~1e-19), where the
// reference would return Inf or 0 and then lose the triangle.
inline float robust_length(const glm::vec3& v) {
    const float squared = dot3(v, v);
    if (squared > 1e-30f && squared < 1e30f) return std::sqrt(squared);
    const float largest = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
    if (!(largest > 0.0f) || !std::isfinite(largest)) return std::sqrt(squared);
    const glm::vec3 scaled = v / largest;
    return largest * std::sqrt(dot3(scaled, scaled));
}

// The reference's Normalize (scale by the reciprocal length), with the robust length.
inline glm::vec3 normalized(const glm::vec3& v) {
    return v * (1.0f / robust_length(v));
}

// v minus its component along n, then normalised when not zero: the reference's
// "project onto the tangent plane" step.
inline glm::vec3 project_normalized(const glm::vec3& v, const glm::vec3& n) {
    const glm::vec3 p = v - n * dot3(n, v);
    return not_zero(p) ? normalized(p) : p;
}

// The normal the generators project with: the file's normal when it is within
// kNormalUnitTolerance of unit length (so results equal the reference's), rescaled to
// unit length otherwise. Zero and non-finite normals are returned unchanged.
inline glm::vec3 projection_normal(const glm::vec3& n, bool& rescaled) {
    const float squared = dot3(n, n);
    rescaled = false;
    if (!std::isfinite(squared) || squared == 0.0f) return n;
    if (std::fabs(squared - 1.0f) <= kNormalUnitTolerance) return n;
    rescaled = true;
    return normalized(n);
}

inline bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool finite(const glm::vec2& v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}
inline bool finite(const glm::vec4& v) {
    return finite(glm::vec3(v)) && std::isfinite(v.w);
}

// Vertex welding as MikkTSpace defines it: corners are one vertex exactly when position,
// normal and uv compare equal as floats (so -0 == +0, and a NaN never equals anything).
struct WeldedCorners {
    std::vector<std::uint32_t> corner_class; // per corner: dense class id
    std::vector<glm::vec3> class_normal;     // per class: projection_normal() of its normal
    std::uint64_t rescaled_normals = 0;      // classes whose normal was rescaled
};
WeldedCorners weld_corners(const TangentInput& input);

// Face adjacency over triangles given as welded corner classes (3 per triangle, no
// class repeated within a triangle). neighbour[3t+i] receives the triangle across edge
// (corner i, corner i+1), or -1. An edge is shared only by two triangles that traverse it
// in opposite directions; where more than two qualify, triangles pair in index order,
// first come first served, exactly as the reference does.
void build_neighbours(std::span<const std::uint32_t> triangle_classes, std::uint32_t class_count,
                      std::span<std::int32_t> neighbour);

// Raw per-corner results of one method before the guard. `assigned[c]` is 0 where the
// method left corner c at a default instead of computing it.
void mikktspace_corners(const TangentInput& input, std::span<glm::vec4> out,
                        std::span<std::uint8_t> assigned, std::uint64_t& rescaled_normals);
void lengyel_corners(const TangentInput& input, std::span<glm::vec4> out,
                     std::span<std::uint8_t> assigned, std::uint64_t& rescaled_normals,
                     std::uint64_t& nonfinite_unguarded);

} // namespace sherpa::tangent_detail
