// UASTC block decoding. Field order of every mode (spec, "List of UASTC Modes"):
// MODE, hint bits, PAT or COMPSEL, the trit/quint groups of all endpoint values,
// each value's low bits, then the weights as plain LSB-first bits, where each
// subset's anchor texel (its first texel) drops its always-zero top bit.
#include "uastc.h"

#include <array>

#include "uastc_tables.h"

namespace sherpa::tex::uastc {

namespace {

// 128-bit block read LSB first. Reads stay inside the block: every mode's
// fields total at most 128 bits (spec), and past the end only zeros come back.
class BlockReader {
public:
    explicit BlockReader(const std::uint8_t* b) {
        for (int i = 0; i < 8; ++i) lo_ |= std::uint64_t{b[i]} << (8 * i);
        for (int i = 0; i < 8; ++i) hi_ |= std::uint64_t{b[8 + i]} << (8 * i);
    }
    void skip(unsigned n) { pos_ += n; }
    // n <= 8
    std::uint32_t read(unsigned n) {
        std::uint64_t v = 0;
        if (pos_ >= 128)
            v = 0;
        else if (pos_ >= 64)
            v = hi_ >> (pos_ - 64);
        else if (pos_ == 0)
            v = lo_;
        else
            v = (lo_ >> pos_) | (hi_ << (64 - pos_));
        pos_ += n;
        return static_cast<std::uint32_t>(v) & ((1u << n) - 1);
    }

private:
    std::uint64_t lo_ = 0, hi_ = 0;
    unsigned pos_ = 0;
};

constexpr std::array<std::uint8_t, 128> make_mode_lookup() {
    std::array<std::uint8_t, 128> t{};
    for (unsigned v = 0; v < 128; ++v)
        for (std::uint8_t m = 0; m < 20; ++m)
            if ((v & ((1u << kModeCodes[m].length) - 1)) == kModeCodes[m].code) t[v] = m;
    return t;
}
constexpr std::array<std::uint8_t, 128> kModeLookup = make_mode_lookup();

// ASTC BISE ranges (index 0..20): low bits, trits, quints.
struct Range {
    std::uint8_t bits, trits, quints;
};
constexpr Range kRanges[21] = {{1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {0, 0, 1}, {1, 1, 0}, {3, 0, 0},
                               {1, 0, 1}, {2, 1, 0}, {4, 0, 0}, {2, 0, 1}, {3, 1, 0}, {5, 0, 0},
                               {3, 0, 1}, {4, 1, 0}, {6, 0, 0}, {4, 0, 1}, {5, 1, 0}, {7, 0, 0},
                               {5, 0, 1}, {6, 1, 0}, {8, 0, 0}};

// ASTC endpoint unquantisation (Khronos Data Format spec, "Endpoint
// Unquantization"): bit replication for pure-bit ranges; for trit/quint ranges
// the value's top digit D and low bits feed T = D*C + B, T ^= A, (A&0x80)|(T>>2).
constexpr std::uint8_t unquantize_endpoint(unsigned value, const Range& r) {
    if (!r.trits && !r.quints) {
        unsigned v = value << (8 - r.bits), out = v;
        for (unsigned shift = r.bits; shift < 8; shift += r.bits) out |= v >> shift;
        return static_cast<std::uint8_t>(out);
    }
    const unsigned low = value & ((1u << r.bits) - 1), digit = value >> r.bits;
    const unsigned a = (low & 1) ? 0x1FF : 0, m = low >> 1; // m: bits b, c, d, ...
    unsigned b = 0, c = 0;
    if (r.trits) {
        switch (r.bits) {
        case 1:
            c = 204;
            break;
        case 2:
            b = (m << 8) | (m << 4) | (m << 2) | (m << 1), c = 93;
            break;
        case 3:
            b = (m << 7) | (m << 2) | m, c = 44;
            break;
        case 4:
            b = (m << 6) | m, c = 22;
            break;
        case 5:
            b = (m << 5) | (m >> 2), c = 11;
            break;
        case 6:
            b = (m << 4) | (m >> 4), c = 5;
            break;
        }
    } else {
        switch (r.bits) {
        case 1:
            c = 113;
            break;
        case 2:
            b = (m << 8) | (m << 3) | (m << 2), c = 54;
            break;
        case 3:
            b = (m << 7) | (m << 1) | (m >> 1), c = 26;
            break;
        case 4:
            b = (m << 6) | (m >> 1), c = 13;
            break;
        case 5:
            b = (m << 5) | (m >> 3), c = 6;
            break;
        }
    }
    unsigned t = (digit * c + b) ^ a;
    return static_cast<std::uint8_t>((a & 0x80) | (t >> 2));
}

using EndpointTable = std::array<std::array<std::uint8_t, 256>, 21>;
constexpr EndpointTable make_endpoint_table() {
    EndpointTable t{};
    for (unsigned r = 0; r < 21; ++r) {
        const unsigned levels = (1u << kRanges[r].bits) * (kRanges[r].trits    ? 3
                                                           : kRanges[r].quints ? 5
                                                                               : 1);
        for (unsigned v = 0; v < levels && v < 256; ++v)
            t[r][v] = unquantize_endpoint(v, kRanges[r]);
    }
    return t;
}
constexpr EndpointTable kEndpoints = make_endpoint_table();

// ASTC weight unquantisation for plain-bit ranges: replicate to 6 bits, then
// values above 32 move up by one so that the range ends at 64.
constexpr std::uint8_t unquantize_weight(unsigned value, unsigned bits) {
    if (bits == 1) return value ? 64 : 0;
    unsigned v = value << (6 - bits), out = v;
    for (unsigned shift = bits; shift < 6; shift += bits) out |= v >> shift;
    return static_cast<std::uint8_t>(out > 32 ? out + 1 : out);
}
using WeightTable = std::array<std::array<std::uint8_t, 32>, 6>;
constexpr WeightTable make_weight_table() {
    WeightTable t{};
    for (unsigned bits = 1; bits <= 5; ++bits)
        for (unsigned v = 0; v < (1u << bits); ++v) t[bits][v] = unquantize_weight(v, bits);
    return t;
}
constexpr WeightTable kWeights = make_weight_table();

// ASTC's interpolation of two 8-bit endpoints expanded to 16 bits.
inline std::uint8_t interpolate(unsigned l, unsigned h, unsigned w, bool srgb) {
    if (srgb)
        l = (l << 8) | 0x80, h = (h << 8) | 0x80;
    else
        l |= l << 8, h |= h << 8;
    return static_cast<std::uint8_t>(((l * (64 - w) + h * w + 32) >> 6) >> 8);
}

// Reads the mode's endpoint values: trit/quint groups first (base 3 or 5,
// first value in the lowest digit, the last group as few bits as it needs),
// then each value's low bits.
void read_endpoints(BlockReader& in, const Range& r, unsigned count, std::uint8_t* values) {
    const unsigned group = r.trits ? 5 : r.quints ? 3 : 0;
    std::uint32_t groups[8] = {};
    const unsigned group_count = group ? (count + group - 1) / group : 0;
    for (unsigned g = 0; g < group_count; ++g) {
        unsigned bits = r.trits ? 8 : 7;
        const unsigned left = count - g * group;
        if (left < group) {
            static constexpr std::uint8_t kTritBits[5] = {0, 2, 4, 5, 7};
            static constexpr std::uint8_t kQuintBits[3] = {0, 3, 5};
            bits = r.trits ? kTritBits[left] : kQuintBits[left];
        }
        groups[g] = in.read(bits);
    }
    // Each group's digits, lowest first (one division per digit, not per value).
    std::uint8_t digits[20] = {};
    const unsigned base = r.trits ? 3 : 5;
    for (unsigned g = 0; g < group_count; ++g)
        for (unsigned k = 0; k < group; ++k, groups[g] /= base)
            digits[g * group + k] = static_cast<std::uint8_t>(groups[g] % base);
    for (unsigned i = 0; i < count; ++i)
        values[i] = static_cast<std::uint8_t>(in.read(r.bits) | (unsigned(digits[i]) << r.bits));
}

} // namespace

int block_mode(const std::uint8_t* block) {
    return kModeLookup[block[0] & 127];
}

BlockStatus decode_block(const std::uint8_t* block, std::uint8_t* rgba, bool srgb) {
    const int mode = block_mode(block);
    if (mode >= kModeCount) return BlockStatus::ReservedMode;
    BlockReader in(block);
    in.skip(kModeCodes[mode].length);
    if (mode == kSolidColorMode) {
        std::uint8_t c[4];
        for (auto& v : c) v = static_cast<std::uint8_t>(in.read(8));
        for (int i = 0; i < 16; ++i)
            for (int k = 0; k < 4; ++k) rgba[4 * i + k] = c[k];
        return BlockStatus::Ok; // the ETC1 hints that follow only serve transcoders
    }
    const ModeInfo& info = kModes[mode];
    // BC1H0, BC1H1, ETC1F, ETC1D, ETC1I0, ETC1I1, ETC1BIAS, ETC2TM: hints only.
    in.skip(unsigned(info.bc1_hint0) + unsigned(info.bc1_hint1) + 8 + (info.etc1_bias ? 5 : 0) +
            (info.etc2_hints ? 8 : 0));

    const std::uint8_t* pattern = nullptr;
    const std::uint8_t* anchors = nullptr;
    if (mode == 3) {
        const unsigned p = in.read(4);
        if (p >= 11) return BlockStatus::BadPatternIndex;
        pattern = kPatterns3[p], anchors = kAnchors3[p];
    } else if (mode == 7) {
        const unsigned p = in.read(5);
        if (p >= 19) return BlockStatus::BadPatternIndex;
        pattern = kPatterns2Of3[p], anchors = kAnchors2Of3[p];
    } else if (info.subsets == 2) {
        const unsigned p = in.read(5);
        if (p >= 30) return BlockStatus::BadPatternIndex;
        pattern = kPatterns2[p], anchors = kAnchors2[p];
    }
    // Component interpolated with the second plane's weights (ASTC's CCS);
    // the LA dual-plane mode 17 always uses alpha.
    unsigned ccs = 3;
    if (mode == 6 || mode == 11 || mode == 13) ccs = in.read(2);

    const unsigned comps = info.components, subsets = info.subsets;
    std::uint8_t values[18];
    const unsigned count = comps * 2 * subsets;
    const Range& range = kRanges[info.endpoint_range];
    read_endpoints(in, range, count, values);
    std::uint8_t ep[18];
    for (unsigned i = 0; i < count; ++i) ep[i] = kEndpoints[info.endpoint_range][values[i]];

    bool is_anchor[16] = {};
    is_anchor[0] = true;
    for (unsigned s = 0; s < subsets && anchors; ++s) is_anchor[anchors[s]] = true;
    const unsigned planes = info.planes, wbits = info.weight_bits;
    std::uint8_t weights[32];
    for (unsigned i = 0; i < 16; ++i)
        for (unsigned p = 0; p < planes; ++p)
            weights[i * planes + p] = kWeights[wbits][in.read(wbits - (is_anchor[i] ? 1 : 0))];

    for (unsigned i = 0; i < 16; ++i) {
        const std::uint8_t* e = ep + (pattern ? pattern[i] : 0) * comps * 2;
        const unsigned w0 = weights[i * planes], w1 = weights[i * planes + planes - 1];
        std::uint8_t* out = rgba + 4 * i;
        if (comps == 2) {
            const std::uint8_t l = interpolate(e[0], e[1], w0, srgb);
            out[0] = out[1] = out[2] = l;
            out[3] = interpolate(e[2], e[3], planes == 2 ? w1 : w0, srgb);
            continue;
        }
        for (unsigned c = 0; c < 4; ++c) {
            const unsigned w = (planes == 2 && c == ccs) ? w1 : w0;
            out[c] = c < comps ? interpolate(e[2 * c], e[2 * c + 1], w, srgb) : 255;
        }
    }
    return BlockStatus::Ok;
}

} // namespace sherpa::tex::uastc
