// Fast BC7 block decoder: one template instance per mode, so every field width
// and position is a compile-time constant; the block is read as one 128-bit
// value; index streams get a zero bit inserted at each anchor so every texel's
// index sits at a fixed offset; texels are looked up in per-subset palettes
// that are interpolated once per block and stored straight into the image.
#include "bc7_decode_fast.h"

#include <array>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <utility>

#include "bc7_tables.h"

namespace sherpa::tex::bc7 {

namespace {

using u32 = std::uint32_t;
using u64 = std::uint64_t;
__extension__ using u128 = unsigned __int128;

// Sequential reader over the block's 128 bits; positions fold to constants.
struct Bits128 {
    u128 v;
    int pos;
    u32 get(int count) {
        const auto r = static_cast<u32>(static_cast<u64>(v >> pos) & ((u64{1} << count) - 1));
        pos += count;
        return r;
    }
};

// Inserts a zero bit at `bit`, shifting the higher bits up by one.
inline u64 insert_zero(u64 v, int bit) {
    const u64 low = v & ((u64{1} << bit) - 1);
    return low | ((v >> bit) << (bit + 1));
}

// The index stream of `count` bits with the anchors' implicit top bits restored
// as zeros: texel i's index is then bits [i * ib, i * ib + ib).
template <int Ib, int Subsets> u64 expand_indices(u64 raw, int partition) {
    u64 x = insert_zero(raw, Ib - 1);
    if constexpr (Subsets == 2) {
        x = insert_zero(x, kAnchorTwoSubsetSecond[partition] * Ib + Ib - 1);
    } else if constexpr (Subsets == 3) {
        int a = kAnchorThreeSubsetSecond[partition], b = kAnchorThreeSubsetThird[partition];
        if (a > b) std::swap(a, b);
        x = insert_zero(x, a * Ib + Ib - 1);
        x = insert_zero(x, b * Ib + Ib - 1);
    }
    return x;
}

template <int Ib> constexpr const std::uint8_t* weights() {
    if constexpr (Ib == 2)
        return kWeights2;
    else if constexpr (Ib == 3)
        return kWeights3;
    else
        return kWeights4;
}

inline u32 pack(int r, int g, int b, int a) {
    return u32(r) | u32(g) << 8 | u32(b) << 16 | u32(a) << 24;
}

inline void store(std::uint8_t* dst, std::size_t stride, int i, u32 texel) {
    std::memcpy(dst + (i >> 2) * stride + (i & 3) * 4, &texel, 4);
}

#if defined(__SSE2__)
// Every weight of an index width repeated over the four channels, as 16-bit lanes.
template <int Ib> struct LaneWeights {
    alignas(16) std::array<std::int16_t, 4 << Ib> w{};
    constexpr LaneWeights() {
        for (int k = 0; k < (1 << Ib); ++k)
            for (int c = 0; c < 4; ++c) w[4 * k + c] = weights<Ib>()[k];
    }
};
template <int Ib> inline constexpr LaneWeights<Ib> kLaneWeights{};
#endif

// The 2^Ib interpolated RGBA8 colours between two expanded endpoints.
template <int Ib> void subset_palette(const int* e0, const int* e1, u32* out) {
#if defined(__SSE2__)
    // Two colours per register in 16-bit lanes; (64 - w) * e0 + w * e1 + 32 <= 16352.
    const __m128i a = _mm_setr_epi16(std::int16_t(e0[0]), std::int16_t(e0[1]), std::int16_t(e0[2]),
                                     std::int16_t(e0[3]), std::int16_t(e0[0]), std::int16_t(e0[1]),
                                     std::int16_t(e0[2]), std::int16_t(e0[3]));
    const __m128i b = _mm_setr_epi16(std::int16_t(e1[0]), std::int16_t(e1[1]), std::int16_t(e1[2]),
                                     std::int16_t(e1[3]), std::int16_t(e1[0]), std::int16_t(e1[1]),
                                     std::int16_t(e1[2]), std::int16_t(e1[3]));
    const __m128i c64 = _mm_set1_epi16(64), c32 = _mm_set1_epi16(32);
    const auto* lanes = reinterpret_cast<const __m128i*>(kLaneWeights<Ib>.w.data());
    auto two = [&](int pair) {
        const __m128i w = _mm_load_si128(lanes + pair);
        const __m128i sum = _mm_add_epi16(
            _mm_add_epi16(_mm_mullo_epi16(_mm_sub_epi16(c64, w), a), _mm_mullo_epi16(w, b)), c32);
        return _mm_srli_epi16(sum, 6);
    };
    for (int k = 0; k < (1 << Ib); k += 4)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + k),
                         _mm_packus_epi16(two(k / 2), two(k / 2 + 1)));
#else
    constexpr const std::uint8_t* w = weights<Ib>();
    for (int k = 0; k < (1 << Ib); ++k)
        out[k] = pack(interpolate(e0[0], e1[0], w[k]), interpolate(e0[1], e1[1], w[k]),
                      interpolate(e0[2], e1[2], w[k]), interpolate(e0[3], e1[3], w[k]));
#endif
}

template <int M> void decode_mode(u128 v, std::uint8_t* dst, std::size_t stride) {
    constexpr ModeInfo m = kModes[M];
    constexpr int ns = m.subsets, ne = 2 * ns;
    constexpr bool has_p = m.endpoint_pbits || m.shared_pbits;
    constexpr int cbits = m.color_bits + (has_p ? 1 : 0);
    constexpr int abits = m.alpha_bits + (has_p ? 1 : 0);
    Bits128 bits{v, M + 1};
    const int partition = m.partition_bits ? int(bits.get(m.partition_bits)) : 0;
    const int rotation = m.rotation_bits ? int(bits.get(m.rotation_bits)) : 0;
    const int selector = m.selector_bits ? int(bits.get(m.selector_bits)) : 0;

    int ep[ne][4];
    for (int c = 0; c < 3; ++c)
        for (int e = 0; e < ne; ++e) ep[e][c] = int(bits.get(m.color_bits));
    for (int e = 0; e < ne; ++e) ep[e][3] = m.alpha_bits ? int(bits.get(m.alpha_bits)) : 255;
    int pbit[ne] = {};
    if constexpr (m.endpoint_pbits)
        for (int e = 0; e < ne; ++e) pbit[e] = int(bits.get(1));
    if constexpr (m.shared_pbits)
        for (int s = 0; s < ns; ++s) pbit[2 * s] = pbit[2 * s + 1] = int(bits.get(1));
    for (int e = 0; e < ne; ++e) {
        for (int c = 0; c < 3; ++c)
            ep[e][c] = expand_to_8(has_p ? (ep[e][c] << 1) | pbit[e] : ep[e][c], cbits);
        if constexpr (m.alpha_bits != 0)
            ep[e][3] = expand_to_8(has_p ? (ep[e][3] << 1) | pbit[e] : ep[e][3], abits);
    }

    constexpr int ib = m.index_bits;
    constexpr int n = 1 << ib;
    constexpr u64 mask = n - 1;
    const u64 raw = static_cast<u64>(v >> bits.pos);
    if constexpr (m.index2_bits == 0) {
        // One index set: a palette of n colours per subset.
        const u64 idx = expand_indices<ib, ns>(raw & ((u64{1} << (16 * ib - ns)) - 1), partition);
        alignas(16) u32 pal[ns * n];
        for (int s = 0; s < ns; ++s) subset_palette<ib>(ep[2 * s], ep[2 * s + 1], pal + s * n);
        if constexpr (ns == 1) {
            for (int i = 0; i < 16; ++i) store(dst, stride, i, pal[(idx >> (i * ib)) & mask]);
        } else {
            const std::uint8_t* subset =
                (ns == 2 ? kTwoSubsetPartitions : kThreeSubsetPartitions)[partition].data();
            for (int i = 0; i < 16; ++i)
                store(dst, stride, i, pal[subset[i] * n + ((idx >> (i * ib)) & mask)]);
        }
    } else {
        // Modes 4 and 5: separate colour and alpha index sets, then the rotation.
        constexpr int ib2 = m.index2_bits;
        const u64 idx1 = expand_indices<ib, 1>(raw & ((u64{1} << (16 * ib - 1)) - 1), 0);
        const u64 raw2 = static_cast<u64>(v >> (bits.pos + 16 * ib - 1));
        const u64 idx2 = expand_indices<ib2, 1>(raw2 & ((u64{1} << (16 * ib2 - 1)) - 1), 0);
        // Where the interpolated colour channels and alpha end up after the rotation.
        int cshift[3] = {0, 8, 16};
        int ashift = 24;
        if (rotation) cshift[rotation - 1] = 24, ashift = (rotation - 1) * 8;
        // Selector 1 (mode 4 only) takes colour from the secondary set, alpha from the primary.
        const bool swap = selector == 1;
        const u64 cidx = swap ? idx2 : idx1, aidx = swap ? idx1 : idx2;
        const int cib = swap ? ib2 : ib, aib = swap ? ib : ib2;
        const std::uint8_t* cw = weights_for_bits(cib);
        const std::uint8_t* aw = weights_for_bits(aib);
        u32 cpal[8], apal[8];
        for (int k = 0; k < (1 << cib); ++k) {
            u32 t = 0;
            for (int c = 0; c < 3; ++c)
                t |= u32(interpolate(ep[0][c], ep[1][c], cw[k])) << cshift[c];
            cpal[k] = t;
        }
        for (int k = 0; k < (1 << aib); ++k)
            apal[k] = u32(interpolate(ep[0][3], ep[1][3], aw[k])) << ashift;
        const u64 cmask = (u64{1} << cib) - 1, amask = (u64{1} << aib) - 1;
        for (int i = 0; i < 16; ++i)
            store(dst, stride, i,
                  cpal[(cidx >> (i * cib)) & cmask] | apal[(aidx >> (i * aib)) & amask]);
    }
}

} // namespace

void decode_block_fast(const std::uint8_t* block, std::uint8_t* dst, std::size_t stride) {
    u64 lo, hi;
    std::memcpy(&lo, block, 8);
    std::memcpy(&hi, block + 8, 8);
    const u128 v = u128{hi} << 64 | lo;
    switch (__builtin_ctz(u32{block[0]} | 0x100u)) {
    case 0:
        return decode_mode<0>(v, dst, stride);
    case 1:
        return decode_mode<1>(v, dst, stride);
    case 2:
        return decode_mode<2>(v, dst, stride);
    case 3:
        return decode_mode<3>(v, dst, stride);
    case 4:
        return decode_mode<4>(v, dst, stride);
    case 5:
        return decode_mode<5>(v, dst, stride);
    case 6:
        return decode_mode<6>(v, dst, stride);
    case 7:
        return decode_mode<7>(v, dst, stride);
    default: // reserved mode byte: transparent black
        for (int y = 0; y < 4; ++y) std::memset(dst + y * stride, 0, 16);
    }
}

} // namespace sherpa::tex::bc7
