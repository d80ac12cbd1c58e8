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
    C finite = 0; // x - x is 0 for every finite x, NaN otherwise: the sum says if all were
    for (std::uint64_t i = 0; i < count; ++i, p += stride) {
        C x[N];
        std::memcpy(x, p, sizeof x);
        for (std::uint32_t c = 0; c < N; ++c) {
            l[c] = x[c] < l[c] ? x[c] : l[c];
            h[c] = x[c] > h[c] ? x[c] : h[c];
            if constexpr (std::is_floating_point_v<C>) finite += x[c] - x[c];
        }
    }
    for (std::uint32_t c = 0; c < N; ++c) lo[c] = l[c], hi[c] = h[c];
    return finite == 0;
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
    I a = 0, b = 0;
    for (std::uint64_t i = 0; i < count; ++i, p += stride) {
        I x;
        std::memcpy(&x, p, sizeof x);
        if (x >= vertices && s.first_over == UINT64_MAX) s.first_over = i;
        if (x == restart && s.first_restart == UINT64_MAX) s.first_restart = i;
        if (triangles && i % 3 == 2) s.degenerate += (a == b) | (b == x) | (x == a);
        a = b;
        b = x;
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
