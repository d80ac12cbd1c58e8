#pragma once
// Internal: the data pass's hot loops as pure functions over strided bytes (one typed
// pass, no per-value dispatch, no branch taken per value on good data). Each reports
// only whether, and where first, data breaks a rule; the messages are the caller's.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace sherpa::scene::detail::kernels {

// A 16-byte vector of C (the GCC/Clang vector extension: SSE2 on x86-64, NEON on
// ARM): element-wise operators, `?:` chooses per lane.
template <typename C> struct Vector16 { typedef C type __attribute__((vector_size(16))); };
template <typename C> using Vec16 = typename Vector16<C>::type;

template <typename C> Vec16<C> load16(const std::uint8_t* p) {
    Vec16<C> x;
    std::memcpy(&x, p, sizeof x);
    return x;
}

// Per-component bounds of `count` elements of N components of type C, `stride` bytes
// apart, into lo/hi. False when a float component is not finite (NaN or infinite):
// the bounds then may include it, and the caller takes an exact path.
template <typename C, std::uint32_t N>
bool bounds(const std::uint8_t* p, std::uint64_t count, std::uint64_t stride, C* lo, C* hi) {
    C l[N], h[N];
    for (std::uint32_t c = 0; c < N; ++c) {
        l[c] = std::numeric_limits<C>::max();
        h[c] = std::numeric_limits<C>::lowest();
    }
    unsigned nan = 0;
    // Tightly packed elements (the usual layout) in blocks of K vectors (K a multiple
    // of N; at least 4, so that one or two components still have independent chains):
    // lane j of vector k holds component (k * kLanes + j) % N. The bounds stay in
    // vector registers (arrays of lanes spilled to the stack on every element); `?:` on
    // vectors is SIMD minimum/maximum with the scalar loop's order of a float comparison.
    constexpr std::uint32_t kLanes = 16 / sizeof(C);
    constexpr std::uint32_t K = N >= 3 ? N : 4;
    static_assert(K % N == 0);
    if (stride == N * sizeof(C) && count >= std::uint64_t{K} * kLanes / N) {
        using V = Vec16<C>;
        V vl[K], vh[K];
        for (std::uint32_t k = 0; k < K; ++k) {
            vl[k] = V{} + std::numeric_limits<C>::max();
            vh[k] = V{} + std::numeric_limits<C>::lowest();
        }
        decltype(V{} != V{}) vnan{};
        constexpr std::uint64_t kElements = std::uint64_t{K} * kLanes / N;
        const std::uint64_t blocks = count / kElements;
        for (std::uint64_t b = 0; b < blocks; ++b, p += sizeof(V) * K) {
#pragma GCC unroll 16
            for (std::uint32_t k = 0; k < K; ++k) {
                const V x = load16<C>(p + sizeof(V) * k);
                vl[k] = x < vl[k] ? x : vl[k];
                vh[k] = x > vh[k] ? x : vh[k];
                if constexpr (std::is_floating_point_v<C>) vnan |= x != x;
            }
        }
        for (std::uint32_t k = 0; k < K; ++k)
            for (std::uint32_t j = 0; j < kLanes; ++j) {
                const std::uint32_t c = (k * kLanes + j) % N;
                l[c] = vl[k][j] < l[c] ? vl[k][j] : l[c];
                h[c] = vh[k][j] > h[c] ? vh[k][j] : h[c];
            }
        for (std::uint32_t j = 0; j < sizeof(vnan) / sizeof(vnan[0]); ++j) nan |= vnan[j] != 0;
        count -= blocks * kElements;
    }
    // NaN never enters the bounds (both comparisons are false), so it is flagged apart,
    // with an integer OR (a float sum here was a 4-cycle dependency per component);
    // infinities do enter them and are seen there afterwards. The rest, element-wise:
    for (std::uint64_t i = 0; i < count; ++i, p += stride) {
        C x[N];
        std::memcpy(x, p, sizeof x);
        for (std::uint32_t c = 0; c < N; ++c) {
            l[c] = x[c] < l[c] ? x[c] : l[c];
            h[c] = x[c] > h[c] ? x[c] : h[c];
            if constexpr (std::is_floating_point_v<C>) nan |= x[c] != x[c];
        }
    }
    bool finite = nan == 0;
    for (std::uint32_t c = 0; c < N; ++c) {
        lo[c] = l[c], hi[c] = h[c];
        if constexpr (std::is_floating_point_v<C>)
            finite &= std::isfinite(l[c]) && std::isfinite(h[c]);
    }
    return finite;
}

// One pass over `count` index values of type I, `stride` bytes apart: their bounds and,
// for triangle lists, how many triangles repeat an index. The min/max check and the
// index checks both read these from one summary (low > high when `count` is 0).
struct IndexSummary {
    std::uint64_t low = UINT64_MAX, high = 0;
    std::uint64_t degenerate = 0; // triangles with a repeated index
};
template <typename I>
IndexSummary summarize_indices(const std::uint8_t* p, std::uint64_t count, std::uint64_t stride,
                               bool triangles) {
    IndexSummary s;
    auto at = [&](std::uint64_t i) {
        I x;
        std::memcpy(&x, p + i * stride, sizeof x);
        return x;
    };
    I low = std::numeric_limits<I>::max(), high = 0;
    std::uint64_t i = 0;
    if (triangles && stride == sizeof(I)) {
        // Tightly packed (as indices must be) in blocks of 3 vectors, kLanes triangles:
        // a, b, c are the values at i, i + 1, i + 2 for every i, so lane i's
        // (a == b) | (b == c) | (c == a) is triangle i / 3's test where i % 3 == 0
        // (`first`: lanes kLanes % 3 != 0 apart put exactly one such i in each lane of
        // the block's 3 vectors). Lanes count in their own width, summed every 64 blocks.
        using V = Vec16<I>;
        using M = decltype(V{} == V{});
        constexpr std::uint32_t kLanes = 16 / sizeof(I);
        M first[3];
        for (std::uint32_t k = 0; k < 3; ++k)
            for (std::uint32_t j = 0; j < kLanes; ++j)
                first[k][j] = (k * kLanes + j) % 3 == 0 ? -1 : 0;
        V vlow = V{} + low, vhigh{};
        while (i + 3 * kLanes + 2 <= count) {
            M counts{};
            for (int b = 0; b < 64 && i + 3 * kLanes + 2 <= count; ++b, i += 3 * kLanes) {
#pragma GCC unroll 3
                for (std::uint32_t k = 0; k < 3; ++k) {
                    const std::uint8_t* q = p + (i + k * kLanes) * sizeof(I);
                    const V a = load16<I>(q), b1 = load16<I>(q + sizeof(I)),
                            c = load16<I>(q + 2 * sizeof(I));
                    counts += ((a == b1) | (b1 == c) | (c == a)) & first[k];
                    vlow = a < vlow ? a : vlow;
                    vhigh = a > vhigh ? a : vhigh;
                }
            }
            for (std::uint32_t j = 0; j < kLanes; ++j)
                s.degenerate += static_cast<std::uint64_t>(-counts[j]);
        }
        for (std::uint32_t j = 0; j < kLanes; ++j) {
            low = vlow[j] < low ? vlow[j] : low;
            high = vhigh[j] > high ? vhigh[j] : high;
        }
    }
    if (triangles)
        for (; i + 3 <= count; i += 3) {
            const I a = at(i), b = at(i + 1), c = at(i + 2);
            s.degenerate += (a == b) | (b == c) | (c == a);
            const I ab = a > b ? a : b, abc = ab > c ? ab : c;
            const I ab_ = a < b ? a : b, abc_ = ab_ < c ? ab_ : c;
            high = abc > high ? abc : high;
            low = abc_ < low ? abc_ : low;
        }
    if (i < count) {
        I lo_rest, hi_rest;
        bounds<I, 1>(p + i * stride, count - i, stride, &lo_rest, &hi_rest);
        high = hi_rest > high ? hi_rest : high;
        low = lo_rest < low ? lo_rest : low;
    }
    if (count > 0) s.low = low, s.high = high;
    return s;
}

struct IndexScan {
    std::uint64_t first_over = UINT64_MAX;    // first index > max_index (or any when none)
    std::uint64_t first_restart = UINT64_MAX; // first primitive-restart value
    std::uint64_t degenerate = 0;             // triangles with a repeated index
};

// Index values of type I against the highest vertex index (`vertices` - 1; every value
// is over when `vertices` is 0) and the restart value (all bits set), given their
// summary: the restart value is the type's largest, so the summary's maximum says
// whether any index breaks a rule, and only then are they read again, for where first.
template <typename I>
IndexScan indices(const std::uint8_t* p, std::uint64_t count, std::uint64_t stride,
                  std::uint64_t vertices, const IndexSummary& summary) {
    IndexScan s;
    s.degenerate = summary.degenerate;
    const I restart = std::numeric_limits<I>::max();
    if (count == 0 || (summary.high < vertices && summary.high != restart)) return s;
    for (std::uint64_t i = 0; i < count; ++i) {
        I x;
        std::memcpy(&x, p + i * stride, sizeof x);
        if (x >= vertices && s.first_over == UINT64_MAX) s.first_over = i;
        if (x == restart && s.first_restart == UINT64_MAX) s.first_restart = i;
    }
    return s;
}
// The same, with triangles counted when `triangles` (one pass more).
template <typename I>
IndexScan indices(const std::uint8_t* p, std::uint64_t count, std::uint64_t stride,
                  std::uint64_t vertices, bool triangles) {
    return indices<I>(p, count, stride, vertices,
                      summarize_indices<I>(p, count, stride, triangles));
}

// The squared lengths a unit vector's first test lets pass: well inside
// (1 +- tolerance)^2 (a margin far above float rounding). Any other vector, NaN
// included, sends the whole accessor to the exact test (unit_vectors_exact).
struct UnitBand {
    float lo, hi;
};
inline UnitBand unit_band(double tolerance) {
    return {static_cast<float>((1 - tolerance) * (1 - tolerance) + 1e-4),
            static_cast<float>((1 + tolerance) * (1 + tolerance) - 1e-4)};
}

// Tightly packed 3-vectors, four per 3 SIMD vectors: a = x0 y0 z0 x1, b = y1 z1 x2 y2,
// c = z2 x3 y3 z3, squared, whose sums by lane of
//   p = a0 a3 b2 c1, q = a1 b0 b3 c2, r = a2 b1 c0 c3
// are the four squared lengths (each lane one vector's three squares; which lane holds
// which vector does not matter). Each shuffle picks two lanes of one source and two of
// another (one SHUFPS on x86-64; the x, y, z of four vectors took some thirty).
inline auto inside_band(Vec16<float> a, Vec16<float> b, Vec16<float> c, UnitBand band) {
    using V = Vec16<float>;
    const V a2 = a * a, b2 = b * b, c2 = c * c;
    const V bc = __builtin_shufflevector(b2, c2, 2, 3, 4, 5);  // b2 b3 c0 c1
    const V ab = __builtin_shufflevector(a2, b2, 1, 2, 4, 5);  // a1 a2 b0 b1
    const V bcc = __builtin_shufflevector(b2, c2, 3, 3, 6, 6); // b3 b3 c2 c2
    const V p = __builtin_shufflevector(a2, bc, 0, 3, 4, 7);
    const V q = __builtin_shufflevector(ab, bcc, 0, 2, 4, 6);
    const V r = __builtin_shufflevector(ab, c2, 1, 3, 4, 7);
    const V len2 = p + q + r;
    return (len2 >= band.lo) & (len2 <= band.hi);
}

// Nonzero when any of `count` vectors (3 floats, and with Sign a fourth, `stride` bytes
// apart) has a squared length outside `band` or a sign not +-1. The copy's size is a
// constant (a size chosen per vector was a call to memcpy each).
template <bool Sign>
unsigned doubtful_vectors(const std::uint8_t* q, std::uint64_t count, std::uint64_t stride,
                          UnitBand band) {
    unsigned doubtful = 0;
    if (!Sign && stride == 3 * sizeof(float)) {
        using V = Vec16<float>;
        decltype(V{} < V{}) inside = V{} == V{};
        for (; count >= 4; count -= 4, q += 12 * sizeof(float))
            inside &=
                inside_band(load16<float>(q), load16<float>(q + 16), load16<float>(q + 32), band);
        for (std::uint32_t j = 0; j < 4; ++j) doubtful |= inside[j] == 0;
    }
    for (std::uint64_t i = 0; i < count; ++i, q += stride) {
        float v[4] = {0, 0, 0, 1};
        std::memcpy(v, q, (Sign ? 4 : 3) * sizeof(float));
        const float len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        doubtful |= !(len2 >= band.lo && len2 <= band.hi) | (v[3] != 1 && v[3] != -1);
    }
    return doubtful;
}

// bounds<float, 3> and doubtful_vectors<false> in one pass over `count` tightly packed
// 3-vectors (a normal accessor: its min/max check and its unit-length check read the
// same bytes once). Returns what bounds returns; `doubtful` as doubtful_vectors.
inline bool unit_bounds(const std::uint8_t* p, std::uint64_t count, UnitBand band, float* lo,
                        float* hi, bool& doubtful) {
    using V = Vec16<float>;
    V vl[3], vh[3];
    for (std::uint32_t k = 0; k < 3; ++k) {
        vl[k] = V{} + std::numeric_limits<float>::max();
        vh[k] = V{} + std::numeric_limits<float>::lowest();
    }
    decltype(V{} < V{}) vnan{}, inside = V{} == V{};
    const std::uint64_t blocks = count / 4;
    for (std::uint64_t b = 0; b < blocks; ++b, p += 3 * sizeof(V)) {
        V x[3];
#pragma GCC unroll 3
        for (std::uint32_t k = 0; k < 3; ++k) {
            x[k] = load16<float>(p + sizeof(V) * k);
            vl[k] = x[k] < vl[k] ? x[k] : vl[k];
            vh[k] = x[k] > vh[k] ? x[k] : vh[k];
            vnan |= x[k] != x[k];
        }
        inside &= inside_band(x[0], x[1], x[2], band);
    }
    // The rest (fewer than 4) by the two kernels, merged.
    float l[3], h[3];
    bool finite = bounds<float, 3>(p, count - blocks * 4, 3 * sizeof(float), l, h);
    doubtful = doubtful_vectors<false>(p, count - blocks * 4, 3 * sizeof(float), band) != 0;
    for (std::uint32_t k = 0; k < 3; ++k)
        for (std::uint32_t j = 0; j < 4; ++j) {
            const std::uint32_t c = (k * 4 + j) % 3;
            l[c] = vl[k][j] < l[c] ? vl[k][j] : l[c];
            h[c] = vh[k][j] > h[c] ? vh[k][j] : h[c];
        }
    for (std::uint32_t j = 0; j < 4; ++j) {
        finite &= vnan[j] == 0;
        doubtful |= inside[j] == 0;
    }
    for (std::uint32_t c = 0; c < 3; ++c) {
        lo[c] = l[c], hi[c] = h[c];
        finite &= std::isfinite(l[c]) && std::isfinite(h[c]);
    }
    return finite;
}

// The first of `count` float vectors (3 components, `stride` apart) whose length is
// finite and differs from 1 by more than `tolerance`, and, with `sign`, the first whose
// fourth component is not +-1; UINT64_MAX where there is none.
struct UnitScan {
    std::uint64_t first_non_unit = UINT64_MAX, first_bad_sign = UINT64_MAX;
};
// Vector by vector, in double precision: for accessors the first test doubts.
inline UnitScan unit_vectors_exact(const std::uint8_t* p, std::uint64_t count, std::uint64_t stride,
                                   double tolerance, bool sign) {
    UnitScan s;
    for (std::uint64_t i = 0; i < count; ++i, p += stride) {
        float v[4] = {};
        std::memcpy(v, p, (sign ? 4 : 3) * sizeof(float));
        const double x = v[0], y = v[1], z = v[2];
        const double len = std::sqrt(x * x + y * y + z * z);
        if (std::abs(len - 1) > tolerance && std::isfinite(len) && s.first_non_unit == UINT64_MAX)
            s.first_non_unit = i;
        if (sign && v[3] != 1 && v[3] != -1 && s.first_bad_sign == UINT64_MAX) s.first_bad_sign = i;
    }
    return s;
}
// A first pass without square roots or branches, then the exact one where it doubts.
inline UnitScan unit_vectors(const std::uint8_t* p, std::uint64_t count, std::uint64_t stride,
                             double tolerance, bool sign) {
    const UnitBand band = unit_band(tolerance);
    const unsigned doubtful = sign ? doubtful_vectors<true>(p, count, stride, band)
                                   : doubtful_vectors<false>(p, count, stride, band);
    return doubtful ? unit_vectors_exact(p, count, stride, tolerance, sign) : UnitScan{};
}

} // namespace sherpa::scene::detail::kernels
