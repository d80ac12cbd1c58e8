#pragma once
// Shared pieces of the tangent generators (engine/scene/src/tangent_*.cpp). Not installed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/scene/tangents.h>

namespace sherpa::scene::tangent_detail {

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

// Whether triangle (p0, p1, p2) has zero area up to the rounding of its coordinates:
// twice its area is at most what moving a corner by a few float ulps of the largest
// coordinate could produce. Collinear corners written from floats (a midpoint, say) are
// rarely exactly collinear, so an exact test would miss them.
inline bool zero_area(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
    constexpr double kUlps = 4.0 * std::numeric_limits<float>::epsilon();
    const glm::vec3 m = glm::max(glm::max(glm::abs(p0), glm::abs(p1)), glm::abs(p2));
    const float scale = std::max(m.x, std::max(m.y, m.z));
    // Fast path in float: its own rounding is far below the margin of 8x.
    {
        const glm::vec3 d1 = p1 - p0, d2 = p2 - p0, c = glm::cross(d1, d2);
        const float edge2 = std::max(dot3(d1, d1), dot3(d2, d2));
        const float limit = float(kUlps) * scale;
        if (dot3(c, c) > 64.0f * limit * limit * edge2 && std::isfinite(dot3(c, c))) return false;
    }
    const glm::dvec3 a(p0), d1 = glm::dvec3(p1) - a, d2 = glm::dvec3(p2) - a;
    const double edge2 = std::max(glm::dot(d1, d1), glm::dot(d2, d2));
    const glm::dvec3 c = glm::cross(d1, d2);
    const double limit = kUlps * double(scale);
    return !(glm::dot(c, c) > limit * limit * edge2);
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
inline bool usable_normal(const glm::vec3& n) {
    return finite(n) && not_zero(n);
}

// Allocator for the scratch buffers. Blocks of 2 MiB and more are aligned to 2 MiB and
// advised as transparent huge pages where the system offers them (Linux madvise), so a
// call on a large mesh takes one page fault per 2 MiB of fresh scratch instead of one
// per 4 KiB: those faults were a third of a cold call's time. Smaller blocks come from
// operator new.
void* allocate_scratch(std::size_t bytes);
void free_scratch(void* p, std::size_t bytes) noexcept;
template <class T> struct ScratchAllocator {
    using value_type = T;
    ScratchAllocator() = default;
    template <class U> ScratchAllocator(const ScratchAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(allocate_scratch(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { free_scratch(p, n * sizeof(T)); }
    template <class U> bool operator==(const ScratchAllocator<U>&) const noexcept { return true; }
};
template <class T> using ScratchVector = std::vector<T, ScratchAllocator<T>>;

// Vertex welding as MikkTSpace defines it: corners are one vertex exactly when position,
// normal and uv compare equal as floats (so -0 == +0, and a NaN never equals anything).
struct WeldedCorners {
    ScratchVector<std::uint32_t> corner_class;       // per corner: dense class id
    ScratchVector<glm::vec3> class_normal;           // per class: projection_normal() of its normal
    ScratchVector<std::uint8_t> class_normal_usable; // per class: normal finite and not zero
    std::uint64_t rescaled_normals = 0;              // classes whose normal was rescaled
    // Scratch.
    ScratchVector<std::uint32_t> vertex_class, class_vertex;
    ScratchVector<std::uint64_t> vertex_hash, table;
};

// The kept (non-degenerate) triangles, structure of arrays, 3 entries per triangle where
// noted. Corner i's edge is (i, i+1).
struct TriangleSet {
    ScratchVector<std::uint32_t> original; // triangle index in the input
    ScratchVector<std::uint32_t> dropped;  // input triangles with a repeated welded vertex
    ScratchVector<std::uint32_t> cls;      // 3: welded classes
    ScratchVector<glm::vec3> os, ot;       // unit dP/du, dP/dv (zero when undefined)
    ScratchVector<std::uint8_t> flags;     // kOrientPreserving | kGroupWithAny
    ScratchVector<std::int32_t> neighbour; // 3: triangle across the corner's edge, or -1
    ScratchVector<std::uint32_t> group_of; // 3: the corner's group
    ScratchVector<float> angle;            // 3: the corner's weight
};

struct Group {
    std::uint32_t cls;         // the welded vertex the group is around
    std::uint32_t first, size; // range in GroupScratch::members
    bool orient_preserving;
};

struct GroupScratch {
    ScratchVector<Group> groups;
    ScratchVector<std::uint32_t> members; // triangle << 2 | corner, grouped
    ScratchVector<std::int32_t> stack;
    ScratchVector<glm::vec3> proj_os, proj_ot, sorted_os, subgroup_tangent;
    ScratchVector<std::uint32_t> sorted, subgroup_members, subgroup_first, first_kept;
};

struct NeighbourScratch {
    ScratchVector<std::uint32_t> bucket_start, fill;
    ScratchVector<std::uint64_t> sorted;
};

struct MethodScratch {
    ScratchVector<std::uint8_t> assigned, flags;
    ScratchVector<std::uint32_t> last_corner;
    ScratchVector<glm::vec3> sdir_sum, tdir_sum;
};

// generate_mesh_tangents(): the mesh's streams as spans, and the per-corner result.
struct MeshScratch {
    ScratchVector<glm::vec3> positions, normals;
    ScratchVector<glm::vec2> uvs;
    ScratchVector<glm::vec4> corners;
};

} // namespace sherpa::scene::tangent_detail

namespace sherpa::scene {
// Everything a call allocates, kept between calls that share a workspace.
struct TangentWorkspace::Buffers {
    tangent_detail::WeldedCorners weld;
    tangent_detail::TriangleSet tris;
    tangent_detail::NeighbourScratch neighbours;
    tangent_detail::GroupScratch groups;
    tangent_detail::MethodScratch method;
    tangent_detail::MeshScratch mesh;
};
} // namespace sherpa::scene

namespace sherpa::scene::tangent_detail {

// Fills `weld` (all fields) for the input.
void weld_corners(const TangentInput& input, WeldedCorners& weld);

// Face adjacency over triangles given as welded corner classes (3 per triangle, no
// class repeated within a triangle). neighbour[3t+i] receives the triangle across edge
// (corner i, corner i+1), or -1. An edge is shared only by two triangles that traverse it
// in opposite directions; where more than two qualify, triangles pair in index order,
// first come first served, exactly as the reference does.
void build_neighbours(std::span<const std::uint32_t> triangle_classes, std::uint32_t class_count,
                      std::span<std::int32_t> neighbour, NeighbourScratch& scratch);

// Raw per-corner results of one method before the guard. `assigned[c]` is 0 where the
// method left corner c at a default instead of computing it, or computed a zero or
// non-finite tangent, or the corner's normal is zero or non-finite: exactly the corners
// the guard must replace.
void mikktspace_corners(const TangentInput& input, std::span<glm::vec4> out,
                        std::span<std::uint8_t> assigned, std::uint64_t& rescaled_normals,
                        TangentWorkspace::Buffers& buffers);
void lengyel_corners(const TangentInput& input, std::span<glm::vec4> out,
                     std::span<std::uint8_t> assigned, std::uint64_t& rescaled_normals,
                     std::uint64_t& nonfinite_unguarded, MethodScratch& scratch);

} // namespace sherpa::scene::tangent_detail
