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
    // Tightly packed elements (the usual layout) in blocks of kLanes elements: lane k
    // keeps the bounds of component k % N, element-wise operations the compiler turns
    // into SIMD minimum/maximum without reordering a float comparison.
    constexpr std::uint32_t kLanes = 16 * N;
    if (stride == N * sizeof(C) && count >= 16) {
        C bl[kLanes], bh[kLanes];
        unsigned bn[kLanes];
        for (std::uint32_t k = 0; k < kLanes; ++k) bl[k] = l[k % N], bh[k] = h[k % N], bn[k] = 0;
        const std::uint64_t blocks = count / 16;
        for (std::uint64_t b = 0; b < blocks; ++b, p += sizeof(C) * kLanes) {
            C x[kLanes];
            std::memcpy(x, p, sizeof x);
            for (std::uint32_t k = 0; k < kLanes; ++k) {
                bl[k] = x[k] < bl[k] ? x[k] : bl[k];
                bh[k] = x[k] > bh[k] ? x[k] : bh[k];
                if constexpr (std::is_floating_point_v<C>) bn[k] |= x[k] != x[k];
            }
        }
        for (std::uint32_t k = 0; k < kLanes; ++k) {
            l[k % N] = bl[k] < l[k % N] ? bl[k] : l[k % N];
            h[k % N] = bh[k] > h[k % N] ? bh[k] : h[k % N];
            nan |= bn[k];
        }
        count -= blocks * 16;
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
    if (triangles)
        for (; i + 3 <= count; i += 3) {
            const I a = at(i), b = at(i + 1), c = at(i + 2);
            s.degenerate += (a == b) | (b == c) | (c == a);
            const I ab = a > b ? a : b;
            const I abc = ab > c ? ab : c;
            high = abc > high ? abc : high;
        }
    for (; i < count; ++i) high = at(i) > high ? at(i) : high;
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
    unsigned doubtful = 0;
    const std::uint8_t* q = p;
    for (std::uint64_t i = 0; i < count; ++i, q += stride) {
        float v[4] = {0, 0, 0, 1};
        std::memcpy(v, q, (sign ? 4 : 3) * sizeof(float));
        const float len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        doubtful |= !(len2 >= inner_lo && len2 <= inner_hi) | (v[3] != 1 && v[3] != -1);
    }
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
