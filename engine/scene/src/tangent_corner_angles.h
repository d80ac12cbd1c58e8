#pragma once
// The weight MikkTSpace gives a triangle at each corner: the angle between the corner's
// two edges projected onto the tangent plane of its normal. Scalar (exactly the
// reference's sequence of operations) and four SIMD lanes (the same operations, so the
// same results), for tangent_mikktspace.cpp. Not installed.
#include <algorithm>
#include <cstdint>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "tangent_internal.h"

namespace sherpa::scene::tangent_detail {

// acos on [-1, 1] from Abramowitz & Stegun 4.4.46 (|error| <= 2e-8 rad): the angle
// weights only need float accuracy, and this is several times cheaper than acosf.
// acos(x) = sqrt(1 - |x|) * acos_polynomial(|x|) for x >= 0, pi minus that for x < 0.
// A template so that scalars and SIMD lanes share one sequence of operations.
template <class T> T acos_polynomial(T a) {
    T p = T{} - 0.0012624911f;
    p = p * a + 0.0066700901f;
    p = p * a - 0.0170881256f;
    p = p * a + 0.0308918810f;
    p = p * a - 0.0501743046f;
    p = p * a + 0.0889789874f;
    p = p * a - 0.2145988016f;
    p = p * a + 1.5707963050f;
    return p;
}

inline float fast_acos(float x) {
    const float a = std::fabs(x);
    const float r = std::sqrt(1.0f - a) * acos_polynomial(a);
    return x < 0.0f ? 3.14159265f - r : r;
}

// Angle between edges e1 and e2 after projecting both onto the plane orthogonal to n,
// computed exactly as the reference does (normalise both, clamp the dot product, acos):
// thin slivers make acos ill-conditioned, and a shortcut such as one square root of the
// product of squared lengths rounds some of their weights to zero where the reference's
// do not.
inline float corner_angle(const glm::vec3& e1, const glm::vec3& e2, const glm::vec3& n) {
    const glm::vec3 v1 = project_normalized(e1, n), v2 = project_normalized(e2, n);
    return fast_acos(std::clamp(dot3(v1, v2), -1.0f, 1.0f));
}

// Four floats, one per corner of a triangle (the fourth lane repeats the first): GCC's
// vector extension, so the same source compiles to SSE on x86-64 and to scalars elsewhere.
using Lanes = float __attribute__((vector_size(16)));
using LaneMask = std::int32_t __attribute__((vector_size(16)));

inline Lanes lane_sqrt(Lanes x) {
#if defined(__SSE2__)
    return reinterpret_cast<Lanes>(_mm_sqrt_ps(reinterpret_cast<__m128>(x)));
#else
    for (int i = 0; i < 4; ++i) x[i] = std::sqrt(x[i]);
    return x;
#endif
}

inline Lanes lane_abs(Lanes x) {
    return reinterpret_cast<Lanes>(reinterpret_cast<LaneMask>(x) & 0x7fffffff);
}

struct LaneVec {
    Lanes x, y, z;
};
inline Lanes lane_dot(const LaneVec& a, const LaneVec& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// project_normalized() per lane, with the same operations in the same order. `in_range`
// turns false where the scalar code would take robust_length's rescaling path.
inline LaneVec lane_project_normalized(const LaneVec& v, const LaneVec& n, LaneMask& in_range) {
    const Lanes d = lane_dot(n, v);
    const LaneVec p{v.x - n.x * d, v.y - n.y * d, v.z - n.z * d};
    const float kMin = std::numeric_limits<float>::min();
    const LaneMask nonzero =
        (lane_abs(p.x) > kMin) | (lane_abs(p.y) > kMin) | (lane_abs(p.z) > kMin);
    const Lanes squared = lane_dot(p, p);
    in_range &= ~nonzero | ((squared > 1e-30f) & (squared < 1e30f));
    const Lanes inverse = 1.0f / lane_sqrt(squared);
    return {nonzero ? p.x * inverse : p.x, nonzero ? p.y * inverse : p.y,
            nonzero ? p.z * inverse : p.z};
}

// The three corner angles of triangle p (normals n), as corner_angle() computes them, in
// one pass of four lanes. Returns false (writing nothing) where some edge needs the
// rescaled length; the caller then uses corner_angle().
inline bool triangle_corner_angles(const glm::vec3 p[3], const glm::vec3 n[3], float* out) {
    auto lanes = [](float a, float b, float c) { return Lanes{a, b, c, a}; };
    const glm::vec3 e1[3] = {p[2] - p[0], p[0] - p[1], p[1] - p[2]};
    const glm::vec3 e2[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};
    const LaneVec a{lanes(e1[0].x, e1[1].x, e1[2].x), lanes(e1[0].y, e1[1].y, e1[2].y),
                    lanes(e1[0].z, e1[1].z, e1[2].z)};
    const LaneVec b{lanes(e2[0].x, e2[1].x, e2[2].x), lanes(e2[0].y, e2[1].y, e2[2].y),
                    lanes(e2[0].z, e2[1].z, e2[2].z)};
    const LaneVec normal{lanes(n[0].x, n[1].x, n[2].x), lanes(n[0].y, n[1].y, n[2].y),
                         lanes(n[0].z, n[1].z, n[2].z)};
    LaneMask in_range = LaneMask{} == 0;
    const LaneVec v1 = lane_project_normalized(a, normal, in_range);
    const LaneVec v2 = lane_project_normalized(b, normal, in_range);
    if (!(in_range[0] & in_range[1] & in_range[2])) return false;
    Lanes x = lane_dot(v1, v2);
    x = x < -1.0f ? Lanes{} - 1.0f : (1.0f < x ? Lanes{} + 1.0f : x); // std::clamp, NaN kept
    // fast_acos, per lane.
    const Lanes abs_x = lane_abs(x);
    const Lanes r = lane_sqrt(1.0f - abs_x) * acos_polynomial(abs_x);
    const Lanes angle = x < 0.0f ? 3.14159265f - r : r;
    out[0] = angle[0];
    out[1] = angle[1];
    out[2] = angle[2];
    return true;
}

} // namespace sherpa::scene::tangent_detail
