#pragma once
// BC7 format facts shared by the decoder and the encoders: the mode table,
// interpolation weights, partitions, anchors, endpoint expansion and the
// little-endian bit stream a block is made of.
#include <array>
#include <cstdint>

namespace sherpa::tex::bc7 {

// One row of the specification's Table.M.
struct ModeInfo {
    std::uint8_t subsets;        // NS
    std::uint8_t partition_bits; // PB
    std::uint8_t rotation_bits;  // RB
    std::uint8_t selector_bits;  // ISB
    std::uint8_t color_bits;     // CB
    std::uint8_t alpha_bits;     // AB (0: alpha decodes to 255)
    std::uint8_t endpoint_pbits; // EPB: one p-bit per endpoint
    std::uint8_t shared_pbits;   // SPB: one p-bit per subset
    std::uint8_t index_bits;     // IB
    std::uint8_t index2_bits;    // IB2 (0: no secondary index set)
};

inline constexpr ModeInfo kModes[8] = {
    {3, 4, 0, 0, 4, 0, 1, 0, 3, 0}, {2, 6, 0, 0, 6, 0, 0, 1, 3, 0}, {3, 6, 0, 0, 5, 0, 0, 0, 2, 0},
    {2, 6, 0, 0, 7, 0, 1, 0, 2, 0}, {1, 0, 2, 1, 5, 6, 0, 0, 2, 3}, {1, 0, 2, 0, 7, 8, 0, 0, 2, 2},
    {1, 0, 0, 0, 7, 7, 1, 0, 4, 0}, {2, 6, 0, 0, 5, 5, 1, 0, 2, 0},
};

// 6-bit interpolation factors for 2, 3 and 4 bit indices.
inline constexpr std::uint8_t kWeights2[4] = {0, 21, 43, 64};
inline constexpr std::uint8_t kWeights3[8] = {0, 9, 18, 27, 37, 46, 55, 64};
inline constexpr std::uint8_t kWeights4[16] = {0,  4,  9,  13, 17, 21, 26, 30,
                                               34, 38, 43, 47, 51, 55, 60, 64};
inline const std::uint8_t* weights_for_bits(int bits) {
    return bits == 2 ? kWeights2 : bits == 3 ? kWeights3 : kWeights4;
}

inline int interpolate(int e0, int e1, int weight) {
    return ((64 - weight) * e0 + weight * e1 + 32) >> 6;
}

using PartitionTable = std::array<std::array<std::uint8_t, 16>, 64>;
extern const PartitionTable kTwoSubsetPartitions;
extern const PartitionTable kThreeSubsetPartitions;
// Bit i of masks[p][s] is set when texel i belongs to subset s of partition p.
using SubsetMasks = std::array<std::array<std::uint16_t, 3>, 64>;
extern const SubsetMasks kTwoSubsetMasks;
extern const SubsetMasks kThreeSubsetMasks;
extern const std::uint8_t kAnchorTwoSubsetSecond[64];
extern const std::uint8_t kAnchorThreeSubsetSecond[64];
extern const std::uint8_t kAnchorThreeSubsetThird[64];

// Subset id of every texel for a mode's subset count and partition number.
inline const std::array<std::uint8_t, 16>& partition_of(int subsets, int partition) {
    static constexpr std::array<std::uint8_t, 16> kSingle{};
    if (subsets == 1) return kSingle;
    return subsets == 2 ? kTwoSubsetPartitions[partition] : kThreeSubsetPartitions[partition];
}

// Texel whose index omits its top bit, for subset `subset` (0 is always texel 0).
inline int anchor_of(int subsets, int partition, int subset) {
    if (subset == 0) return 0;
    if (subsets == 2) return kAnchorTwoSubsetSecond[partition];
    return subset == 1 ? kAnchorThreeSubsetSecond[partition] : kAnchorThreeSubsetThird[partition];
}

// Expands a `bits`-wide value (p-bit already appended) to 8 bits by replicating
// its top bits, as the specification's unquantisation does.
inline int expand_to_8(int value, int bits) {
    value <<= (8 - bits);
    return value | (value >> bits);
}

// 128-bit block as two little-endian words; bit 0 is the block's first bit.
class BitWriter {
public:
    // Appends the low `count` bits of `value` (count <= 32; higher bits must be 0).
    void put(std::uint32_t value, int count) {
        if (count == 0) return;
        const int word = pos_ >> 6, shift = pos_ & 63;
        words_[word] |= std::uint64_t{value} << shift;
        if (shift + count > 64) words_[word + 1] |= std::uint64_t{value} >> (64 - shift);
        pos_ += count;
    }
    int position() const { return pos_; }
    void store(std::uint8_t out[16]) const {
        for (int i = 0; i < 16; ++i)
            out[i] = static_cast<std::uint8_t>(words_[i >> 3] >> ((i & 7) * 8));
    }

private:
    std::uint64_t words_[3] = {0, 0, 0}; // a spare word keeps edge reads in bounds
    int pos_ = 0;
};

class BitReader {
public:
    explicit BitReader(const std::uint8_t in[16]) {
        for (int i = 0; i < 16; ++i) words_[i >> 3] |= std::uint64_t{in[i]} << ((i & 7) * 8);
    }
    // Reads the next `count` bits (count <= 32), least significant first.
    std::uint32_t get(int count) {
        if (count == 0) return 0;
        const int word = pos_ >> 6, shift = pos_ & 63;
        std::uint64_t v = words_[word] >> shift;
        if (shift + count > 64) v |= words_[word + 1] << (64 - shift);
        pos_ += count;
        return static_cast<std::uint32_t>(v & ((std::uint64_t{1} << count) - 1));
    }

private:
    std::uint64_t words_[3] = {0, 0, 0}; // a spare word keeps edge reads in bounds
    int pos_ = 0;
};

} // namespace sherpa::tex::bc7
