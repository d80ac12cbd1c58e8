#pragma once
// CPU frustum culling of world AABBs: frustum extraction, three methods of
// increasing precision (sphere, p-vertex, exact), scalar and SIMD batch paths.
//
// Contracts: planes are normalised and point inward (inside: dot(n, p) + d >= 0).
// The sphere and p-vertex tests are conservative: they never reject a box that
// intersects the frustum. The exact test rejects every box that does not.
// Boxes that are invalid (non-finite or inverted) are never culled: they are
// reported (CullCounts::invalid) and treated as visible.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/core/aabb.h>
#include <sherpa/core/cpu_features.h>

namespace sherpa::scene {

struct Plane {
    glm::vec3 normal{0.0f};
    float d = 0.0f;
    float distance(glm::vec3 p) const { return glm::dot(normal, p) + d; }
};

struct Frustum {
    std::array<Plane, 6> planes{};
    std::uint32_t plane_count = 0; // 5 when the far plane is at infinity
    // World-space corners of the NDC cube unprojected, homogeneous: w == 0 marks a
    // corner at infinity (infinite far plane), xyz is then its direction.
    std::array<glm::vec4, 8> corners{};
    bool empty = false; // the matrix admits no point (degenerate or NaN)
    // Separating axes beyond the planes (3 box axes, box-edge x frustum-edge
    // crosses) with the frustum's projection interval on each, computed once here
    // so the exact test costs a few dot products per box.
    std::array<glm::dvec3, 21> sat_axes{};
    std::array<double, 21> sat_lo{}, sat_hi{};
    std::uint32_t sat_count = 0;
};

// Gribb-Hartmann plane extraction for Vulkan clip space (0 <= z <= w). Works for
// perspective, orthographic, reverse-Z and infinite far planes (a plane whose
// normal vanishes is dropped).
Frustum frustum_from_view_projection(const glm::mat4& view_projection);

enum class CullMethod : std::uint8_t { Sphere, PVertex, Exact };
std::string_view to_string(CullMethod m);
bool parse_cull_method(std::string_view s, CullMethod& out);

// Single-box tests (valid boxes only).
bool sphere_visible(const Frustum& f, const core::Aabb& box);
bool pvertex_visible(const Frustum& f, const core::Aabb& box);
// Separating-axis test between the box and the frustum polyhedron (handles an
// infinite far plane through the corners at infinity).
bool exact_visible(const Frustum& f, const core::Aabb& box);
// Not valid: non-finite components or min > max on some axis.
bool box_is_invalid(glm::vec3 min, glm::vec3 max);

// Structure-of-arrays boxes for the batch paths.
struct BoxesSoA {
    static constexpr std::size_t kBlock = 16; // boxes per block (one AVX-512 vector)
    std::vector<float> min_x, min_y, min_z, max_x, max_y, max_z;
    std::vector<std::uint32_t> invalid; // indices of invalid boxes (stored as empty boxes)
    // Bounds of each run of kBlock consecutive boxes (the last run may be shorter),
    // the same six arrays: the AVX-512 kernel tests 16 blocks at a time and decides a
    // whole block when its bounds are wholly outside a plane or wholly inside every
    // plane. Filled by assign(); arrays changed afterwards need assign() again.
    std::vector<float> block_min_x, block_min_y, block_min_z, block_max_x, block_max_y, block_max_z;
    void assign(std::span<const core::Aabb> boxes);
    std::size_t size() const { return min_x.size(); }
    core::Aabb box(std::size_t i) const {
        return core::Aabb::from_min_max({min_x[i], min_y[i], min_z[i]},
                                        {max_x[i], max_y[i], max_z[i]});
    }
};

// SimdLevel, best_simd_level(): sherpa/core/cpu_features.h (runtime CPU dispatch).

struct CullCounts {
    std::uint64_t tested = 0, visible = 0, culled = 0, invalid = 0;
};

// Culls every box; writes visible[i] = 1 or 0. `visible.size()` must equal
// `boxes.size()`. `level` above what the CPU supports falls back to the best one.
// `threads` > 1 splits the range across OpenMP threads.
CullCounts cull_boxes(const Frustum& f, const BoxesSoA& boxes, CullMethod method,
                      core::SimdLevel level, std::span<std::uint8_t> visible, int threads = 1);

namespace detail {
// p-vertex batch kernels over [begin, end); return the number visible. Exposed
// for the benchmark.
std::size_t pvertex_scalar(const Frustum& f, const BoxesSoA& b, std::size_t begin, std::size_t end,
                           std::uint8_t* out);
std::size_t pvertex_avx2(const Frustum& f, const BoxesSoA& b, std::size_t begin, std::size_t end,
                         std::uint8_t* out);
std::size_t pvertex_avx512(const Frustum& f, const BoxesSoA& b, std::size_t begin, std::size_t end,
                           std::uint8_t* out);
} // namespace detail

} // namespace sherpa::scene
