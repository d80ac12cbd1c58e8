#pragma once
// Internal: the data pass's hot loops as pure functions over strided bytes (one typed
// pass, no per-value dispatch, no branch taken per value on good data). Each reports
// only whether, and where first, data breaks a rule; the messages are the caller's.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace sherpa::detail::kernels {

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

struct IndexScan {
    std::uint64_t first_over = UINT64_MAX;    // first index > max_index (or any when none)
    std::uint64_t first_restart = UINT64_MAX; // first primitive-restart value
    std::uint64_t degenerate = 0;             // triangles with a repeated index
};

// Index values of type I: against the highest vertex index (`vertices` - 1; every value
// is over when `vertices` is 0), the restart value (all bits set), and, for triangle
// lists, triangles that repeat an index.
template <typename I>
IndexScan indices(const std::uint8_t* p, std::uint64_t count, std::uint64_t stride,
                  std::uint64_t vertices, bool triangles) {
    IndexScan s;
    const I restart = std::numeric_limits<I>::max();
    auto at = [&](std::uint64_t i) {
        I x;
        std::memcpy(&x, p + i * stride, sizeof x);
        return x;
    };
    // One pass for the largest value and the degenerate triangles; the restart value is
    // the type's largest, so the maximum also says whether any index is a restart.
    I high = 0;
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
        V vhigh{};
        while (i + 3 * kLanes + 2 <= count) {
            M counts{};
            for (int b = 0; b < 64 && i + 3 * kLanes + 2 <= count; ++b, i += 3 * kLanes) {
#pragma GCC unroll 3
                for (std::uint32_t k = 0; k < 3; ++k) {
                    const std::uint8_t* q = p + (i + k * kLanes) * sizeof(I);
                    const V a = load16<I>(q), b1 = load16<I>(q + sizeof(I)),
                            c = load16<I>(q + 2 * sizeof(I));
                    counts += ((a == b1) | (b1 == c) | (c == a)) & first[k];
                    vhigh = a > vhigh ? a : vhigh;
                }
            }
            for (std::uint32_t j = 0; j < kLanes; ++j)
                s.degenerate += static_cast<std::uint64_t>(-counts[j]);
        }
        for (std::uint32_t j = 0; j < kLanes; ++j) high = vhigh[j] > high ? vhigh[j] : high;
    }
    if (triangles)
        for (; i + 3 <= count; i += 3) {
            const I a = at(i), b = at(i + 1), c = at(i + 2);
            s.degenerate += (a == b) | (b == c) | (c == a);
            const I ab = a > b ? a : b;
            const I abc = ab > c ? ab : c;
            high = abc > high ? abc : high;
        }
    if (i < count) {
        I lo_rest, hi_rest;
        bounds<I, 1>(p + i * stride, count - i, stride, &lo_rest, &hi_rest);
        high = hi_rest > high ? hi_rest : high;
    }
    if (count == 0 || (high < vertices && high != restart)) return s;
    for (i = 0; i < count; ++i) { // where first, only for data that breaks a rule
        const I x = at(i);
        if (x >= vertices && s.first_over == UINT64_MAX) s.first_over = i;
        if (x == restart && s.first_restart == UINT64_MAX) s.first_restart = i;
    }
    return s;
}

// The first of `count` float vectors (3 components, `stride` apart) whose length is
// finite and differs from 1 by more than `tolerance`, and, with `sign`, the first whose
// fourth component is not +-1; UINT64_MAX where there is none.
// Nonzero when any of `count` vectors (3 floats, and with Sign a fourth, `stride` bytes
// apart) has a squared length outside [lo, hi] (NaN included) or a sign not +-1. The
// copy's size is a constant (a size chosen per vector was a call to memcpy each).
template <bool Sign>
unsigned doubtful_vectors(const std::uint8_t* q, std::uint64_t count, std::uint64_t stride,
                          float lo, float hi) {
    unsigned doubtful = 0;
    if (!Sign && stride == 3 * sizeof(float)) {
        // Tightly packed 3-vectors (normals), four per 3 SIMD vectors:
        // a = x0 y0 z0 x1, b = y1 z1 x2 y2, c = z2 x3 y3 z3, squared and gathered into
        // x, y and z of all four, whose sums are the four squared lengths.
        using V = Vec16<float>;
        decltype(V{} < V{}) inside = V{} == V{};
        for (; count >= 4; count -= 4, q += 12 * sizeof(float)) {
            const V a = load16<float>(q), b = load16<float>(q + 16), c = load16<float>(q + 32);
            const V a2 = a * a, b2 = b * b, c2 = c * c;
            const V x = __builtin_shufflevector(__builtin_shufflevector(a2, b2, 0, 3, 6, 0), c2, 0,
                                                1, 2, 5);
            const V y = __builtin_shufflevector(__builtin_shufflevector(a2, b2, 1, 4, 7, 0), c2, 0,
                                                1, 2, 6);
            const V z = __builtin_shufflevector(__builtin_shufflevector(a2, b2, 2, 5, 0, 0), c2, 0,
                                                1, 4, 7);
            const V len2 = x + y + z;
            inside &= (len2 >= lo) & (len2 <= hi);
        }
        for (std::uint32_t j = 0; j < 4; ++j) doubtful |= inside[j] == 0;
    }
    for (std::uint64_t i = 0; i < count; ++i, q += stride) {
        float v[4] = {0, 0, 0, 1};
        std::memcpy(v, q, (Sign ? 4 : 3) * sizeof(float));
        const float len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        doubtful |= !(len2 >= lo && len2 <= hi) | (v[3] != 1 && v[3] != -1);
    }
    return doubtful;
}

struct UnitScan {
    std::uint64_t first_non_unit = UINT64_MAX, first_bad_sign = UINT64_MAX;
};
inline UnitScan unit_vectors(const std::uint8_t* p, std::uint64_t count, std::uint64_t stride,
                             double tolerance, bool sign) {
    UnitScan s;
    // A first pass without square roots or branches: squared lengths well inside
    // (1 +- tolerance)^2 (a margin far above float rounding) and signs of +-1 pass; any
    // other vector, NaN included, sends the whole accessor to the exact pass below.
    const float inner_lo = static_cast<float>((1 - tolerance) * (1 - tolerance) + 1e-4);
    const float inner_hi = static_cast<float>((1 + tolerance) * (1 + tolerance) - 1e-4);
    const unsigned doubtful = sign ? doubtful_vectors<true>(p, count, stride, inner_lo, inner_hi)
                                   : doubtful_vectors<false>(p, count, stride, inner_lo, inner_hi);
    if (!doubtful) return s;
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

} // namespace sherpa::detail::kernels
