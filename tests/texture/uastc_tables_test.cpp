// Cross-checks of the transcribed UASTC specification tables against each other
// and against the spec's own derived tables.
#include <gtest/gtest.h>

#include "uastc.h"
#include "uastc_tables.h"

namespace {

using namespace sherpa::tex::uastc;

// Each subset's anchor is its first texel in raster order (spec: "the first
// weight index written for each subset ... must have an MSB of 0").
template <std::size_t N, std::size_t S>
void expect_anchors_are_first_texels(const Pattern (&patterns)[N],
                                     const std::uint8_t (&anchors)[N][S]) {
    for (std::size_t p = 0; p < N; ++p)
        for (std::size_t s = 0; s < S; ++s) {
            int first = -1;
            for (int i = 0; i < 16 && first < 0; ++i)
                if (patterns[p][i] == s) first = i;
            EXPECT_EQ(first, anchors[p][s]) << "pattern " << p << " subset " << s;
        }
}

TEST(UastcTables, AnchorsAreTheFirstTexelOfEachSubset) {
    expect_anchors_are_first_texels(kPatterns2, kAnchors2);
    expect_anchors_are_first_texels(kPatterns3, kAnchors3);
    expect_anchors_are_first_texels(kPatterns2Of3, kAnchors2Of3);
}

TEST(UastcTables, ModeLookupMatchesTheSpecsAccelerationTable) {
    // g_uastc_huff_modes from the spec, indexed by the low 7 bits of byte 0.
    static constexpr std::uint8_t kSpec[128] = {
        11, 0,  10, 3,  11, 15, 12, 7,  11, 18, 10, 5,  11, 14, 12, 9,  11, 0,  10, 4,  11, 16,
        12, 8,  11, 18, 10, 6,  11, 2,  12, 13, 11, 0,  10, 3,  11, 17, 12, 7,  11, 18, 10, 5,
        11, 14, 12, 9,  11, 0,  10, 4,  11, 1,  12, 8,  11, 18, 10, 6,  11, 2,  12, 13, 11, 0,
        10, 3,  11, 19, 12, 7,  11, 18, 10, 5,  11, 14, 12, 9,  11, 0,  10, 4,  11, 16, 12, 8,
        11, 18, 10, 6,  11, 2,  12, 13, 11, 0,  10, 3,  11, 17, 12, 7,  11, 18, 10, 5,  11, 14,
        12, 9,  11, 0,  10, 4,  11, 1,  12, 8,  11, 18, 10, 6,  11, 2,  12, 13};
    for (int v = 0; v < 128; ++v) {
        const std::uint8_t block[16] = {static_cast<std::uint8_t>(v)};
        EXPECT_EQ(block_mode(block), kSpec[v]) << "byte " << v;
    }
}

TEST(UastcTables, ModeFieldsFillAtMost128Bits) {
    // Mode + hints + PAT/COMPSEL + endpoints + weights, from the mode tables; the
    // spec's per-mode layouts total at most 128 bits.
    static constexpr int kRangeBits[21][3] = {
        {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, 1}, {1, 1, 0}, {3, 0, 0}, {1, 0, 1},
        {2, 1, 0}, {4, 0, 0}, {2, 0, 1}, {3, 1, 0}, {5, 0, 0}, {3, 0, 1}, {4, 1, 0},
        {6, 0, 0}, {4, 0, 1}, {5, 1, 0}, {7, 0, 0}, {5, 0, 1}, {6, 1, 0}, {8, 0, 0}};
    static constexpr int kSpecTotal[19] = {128, 100, 119, 118, 119, 115, 128, 119, 58, 127,
                                           128, 128, 128, 124, 123, 125, 128, 123, 128};
    for (int m = 0; m < kModeCount; ++m) {
        if (m == kSolidColorMode) continue;
        const ModeInfo& i = kModes[m];
        int bits = kModeCodes[m].length + i.bc1_hint0 + i.bc1_hint1 + 8 + (i.etc1_bias ? 5 : 0) +
                   (i.etc2_hints ? 8 : 0);
        bits += m == 3 ? 4 : i.subsets == 2 ? 5 : 0;
        bits += (m == 6 || m == 11 || m == 13) ? 2 : 0;
        const int values = i.components * 2 * i.subsets;
        const auto& r = kRangeBits[i.endpoint_range];
        bits += values * r[0];
        static constexpr int kTritTail[5] = {0, 2, 4, 5, 7}, kQuintTail[3] = {0, 3, 5};
        if (r[1]) bits += (values / 5) * 8 + kTritTail[values % 5];
        if (r[2]) bits += (values / 3) * 7 + kQuintTail[values % 3];
        bits += 16 * i.planes * i.weight_bits - i.subsets * i.planes;
        EXPECT_EQ(bits, kSpecTotal[m]) << "mode " << m;
    }
}

} // namespace
