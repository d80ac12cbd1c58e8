// BC7 block encoder. Compiled once per instruction set (see encode_kernels.h).
//
// Strategy: every candidate mode is fitted by principal-axis endpoints, then
// alternating index selection and least-squares endpoint solves, with p-bits
// chosen per endpoint (or exhaustively at high levels). Partitioned modes only
// fit the partitions that a cheap moment-based estimate ranks best. The block
// keeps whichever candidate has the lowest squared RGBA error.
#include "encode_kernels.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "bc7_tables.h"
#include "kernel_entry.h"
#include <sherpa/texture/quality_levels.h>

namespace sherpa::tex::SHERPA_KERNEL_NS {
namespace {
using namespace bc7;

// What one quality level tries. Counts are partitions fitted per partitioned mode.
struct LevelConfig {
    int refine_passes;           // least-squares passes after the principal-axis start (mode 6)
    int partition_refine_passes; // the same for the other modes
    bool exhaustive_pbits;       // try every p-bit combination instead of the nearest
    int two_subset_parts;        // modes 1 and 3 (opaque) / mode 7 (alpha)
    int three_subset_parts;      // modes 0 and 2 (opaque only)
    int rotations;               // modes 4 and 5: 0 skips them, 1 tries rotation 0, 4 all
    bool separate_alpha_opaque;  // try modes 4/5 on opaque blocks too
    float good_enough;           // stop trying modes once the block error is below this
};

constexpr LevelConfig kLevels[kBc7MaxLevel + 1] = {
    {0, 0, false, 0, 0, 0, false, 0.0f},  // mode 6 only
    {1, 0, false, 1, 0, 1, false, 64.0f}, // + best 2-subset partition (modes 1, 3)
    {2, 1, false, 3, 1, 1, false, 32.0f}, // + 3-subset modes, more refinement
    {2, 1, false, 8, 4, 4, true, 16.0f},  // + all rotations of modes 4/5
    {3, 2, true, 16, 8, 4, true, 4.0f},   // wide partition search, every p-bit pair
};

// ForcedOne: per-endpoint p-bits fixed to 1, used for mode 6 on opaque blocks so
// that alpha (stored 127 with p-bit 1) decodes to exactly 255.
enum class Pbits : std::uint8_t { None, PerEndpoint, Shared, ForcedOne };

// How one subset's endpoints are stored.
struct Precision {
    int color_bits;
    int alpha_bits; // 0: alpha is not stored (modes 0-3: decodes to 255)
    Pbits pbits;
    int channels; // channels the fit and the error cover (1, 3 or 4)
};

// Quantised endpoints of one subset.
struct SubsetFit {
    int q[2][4] = {};
    int p[2] = {0, 0};
    float error = 3.0e38f;
};

// Nearest stored value for channel value v, with the p-bit fixed (or none).
// Returns the stored value; `decoded` receives its 8-bit expansion.
int quantize_channel(float v, int bits, int pbit, int& decoded) {
    const int has_p = pbit >= 0 ? 1 : 0;
    const int total = bits + has_p;
    const int max_q = (1 << bits) - 1;
    const float level = v * (static_cast<float>((1 << total) - 1) * (1.0f / 255.0f));
    // Decoded values grow with q, so the nearest is the floor or the one above.
    const float qf = has_p ? (level - static_cast<float>(pbit)) * 0.5f : level;
    const int lo = std::clamp(static_cast<int>(qf), 0, max_q), hi = std::min(lo + 1, max_q);
    const int dec_lo = expand_to_8(has_p ? (lo << 1) | pbit : lo, total);
    const int dec_hi = expand_to_8(has_p ? (hi << 1) | pbit : hi, total);
    const bool take_hi =
        std::abs(static_cast<float>(dec_hi) - v) < std::abs(static_cast<float>(dec_lo) - v);
    decoded = take_hi ? dec_hi : dec_lo;
    return take_hi ? hi : lo;
}

// Quantises one endpoint with p-bit `pbit` (-1: none); returns its squared error.
float quantize_endpoint(const float e[4], const Precision& prec, int pbit, int q[4], int dec[4]) {
    float err = 0.0f;
    for (int c = 0; c < prec.channels; ++c) {
        const int bits = (c == 3 && prec.alpha_bits) ? prec.alpha_bits : prec.color_bits;
        q[c] = quantize_channel(e[c], bits, pbit, dec[c]);
        const float d = static_cast<float>(dec[c]) - e[c];
        err += d * d;
    }
    return err;
}

// Fits one subset (texels in `mask`) with `index_bits` indices: principal-axis
// endpoints, then `passes` rounds of least squares. Indices go to idx[] for masked texels.
// Float endpoints a fit starts from.
struct Endpoints {
    float e[2][4] = {};
};

// `channels` is a template parameter (equal to prec.channels) so that the
// per-channel loops unroll and the 16-texel loops vectorise.
template <int channels>
SubsetFit fit_subset_n(const Texels& t, std::uint32_t mask, const Precision& prec, int index_bits,
                       int passes, bool exhaustive_pbits, const Endpoints* start,
                       std::uint8_t idx[16]) {
    float e[2][4] = {};
    if (start)
        std::copy(&start->e[0][0], &start->e[0][0] + 8, &e[0][0]);
    else
        principal_endpoints<channels>(t, mask, e[0], e[1]);
    const std::uint8_t* weights = weights_for_bits(index_bits);
    const int entries = 1 << index_bits;
    // Weights padded to 16 entries (the tail repeats the table; only the first
    // `entries` are ever selected because the palette's count says so).
    std::uint8_t weights16[16];
    for (int j = 0; j < 16; ++j) weights16[j] = weights[j & (entries - 1)];
    SubsetFit best;
    std::uint8_t trial_idx[16] = {};
    for (int pass = 0; pass <= passes; ++pass) {
        // p-bit candidates: (-1,-1) for none; else per endpoint pairs.
        int combos[4][2];
        int combo_count = 0;
        if (prec.pbits == Pbits::None) {
            combos[combo_count][0] = combos[combo_count][1] = -1, ++combo_count;
        } else if (prec.pbits == Pbits::ForcedOne) {
            combos[combo_count][0] = combos[combo_count][1] = 1, ++combo_count;
        } else if (prec.pbits == Pbits::Shared) {
            for (int p = 0; p < 2; ++p)
                combos[combo_count][0] = combos[combo_count][1] = p, ++combo_count;
        } else if (exhaustive_pbits) {
            for (int p = 0; p < 4; ++p)
                combos[combo_count][0] = p & 1, combos[combo_count][1] = p >> 1, ++combo_count;
        } else {
            // Each endpoint takes the p-bit that quantises it more closely.
            int q[4], dec[4];
            for (int k = 0; k < 2; ++k)
                combos[0][k] = quantize_endpoint(e[k], prec, 0, q, dec) <=
                                       quantize_endpoint(e[k], prec, 1, q, dec)
                                   ? 0
                                   : 1;
            combo_count = 1;
        }
        bool improved = false;
        for (int ci = 0; ci < combo_count; ++ci) {
            SubsetFit fit;
            int dec[2][4] = {{0, 0, 0, 255}, {0, 0, 0, 255}};
            for (int k = 0; k < 2; ++k) {
                quantize_endpoint(e[k], prec, combos[ci][k], fit.q[k], dec[k]);
                fit.p[k] = std::max(combos[ci][k], 0);
            }
            Palette pal;
            pal.count = entries;
            for (int c = 0; c < channels; ++c)
                for (int j = 0; j < 16; ++j) // fixed trip count: vectorises
                    pal.ch[c][j] =
                        static_cast<float>(interpolate(dec[0][c], dec[1][c], weights16[j]));
            fit.error = select_indices(t, mask, pal, channels, trial_idx);
            if (fit.error < best.error) {
                best = fit;
                improved = true;
                for (int i = 0; i < 16; ++i)
                    if (mask >> i & 1u) idx[i] = trial_idx[i];
            }
        }
        if (pass == passes || best.error == 0.0f || (!improved && pass > 0)) break;
        if (!solve_endpoints<channels>(t, mask, idx, weights, e[0], e[1])) break;
    }
    return best;
}

SubsetFit fit_subset(const Texels& t, std::uint32_t mask, const Precision& prec, int index_bits,
                     int passes, bool exhaustive_pbits, std::uint8_t idx[16],
                     const Endpoints* start = nullptr) {
    switch (prec.channels) {
    case 1:
        return fit_subset_n<1>(t, mask, prec, index_bits, passes, exhaustive_pbits, start, idx);
    case 3:
        return fit_subset_n<3>(t, mask, prec, index_bits, passes, exhaustive_pbits, start, idx);
    default:
        return fit_subset_n<4>(t, mask, prec, index_bits, passes, exhaustive_pbits, start, idx);
    }
}

// A complete encoding of one block in one mode, ready to pack.
struct Candidate {
    int mode = -1, partition = 0, rotation = 0, selector = 0;
    int q[6][4] = {};
    int p[6] = {};
    std::uint8_t color_idx[16] = {}, alpha_idx[16] = {}; // alpha_idx: modes 4/5 only
    float error = 3.0e38f;
};

void pack(Candidate c, std::uint8_t out[16]) {
    const ModeInfo& m = kModes[c.mode];
    // Colour and alpha index widths; for modes 4/5 the selector decides which is 3-bit.
    const int color_bits = (c.mode == 4 && c.selector == 1) ? 3 : m.index_bits;
    const int alpha_bits = c.mode == 4 ? (c.selector == 1 ? 2 : 3) : m.index2_bits;
    const auto& subset_of = partition_of(m.subsets, c.partition);
    // Anchor fix-up: the anchor texel's index must have its top bit clear, so swap
    // the subset's endpoints (and mirror its indices) where it is set.
    for (int s = 0; s < m.subsets; ++s) {
        const int anchor = anchor_of(m.subsets, c.partition, s);
        const int top = 1 << (color_bits - 1);
        if (c.color_idx[anchor] & top) {
            const int last_channel = m.index2_bits ? 3 : 4;
            for (int ch = 0; ch < last_channel; ++ch) std::swap(c.q[2 * s][ch], c.q[2 * s + 1][ch]);
            std::swap(c.p[2 * s], c.p[2 * s + 1]);
            for (int i = 0; i < 16; ++i)
                if (subset_of[i] == s)
                    c.color_idx[i] = static_cast<std::uint8_t>((2 * top - 1) - c.color_idx[i]);
        }
    }
    if (m.index2_bits && (c.alpha_idx[0] & (1 << (alpha_bits - 1)))) {
        std::swap(c.q[0][3], c.q[1][3]);
        for (int i = 0; i < 16; ++i)
            c.alpha_idx[i] = static_cast<std::uint8_t>(((1 << alpha_bits) - 1) - c.alpha_idx[i]);
    }
    BitWriter w;
    w.put(1u << c.mode, c.mode + 1);
    w.put(static_cast<std::uint32_t>(c.partition), m.partition_bits);
    w.put(static_cast<std::uint32_t>(c.rotation), m.rotation_bits);
    w.put(static_cast<std::uint32_t>(c.selector), m.selector_bits);
    const int endpoints = 2 * m.subsets;
    for (int ch = 0; ch < 3; ++ch)
        for (int e = 0; e < endpoints; ++e)
            w.put(static_cast<std::uint32_t>(c.q[e][ch]), m.color_bits);
    for (int e = 0; e < endpoints && m.alpha_bits; ++e)
        w.put(static_cast<std::uint32_t>(c.q[e][3]), m.alpha_bits);
    for (int e = 0; e < endpoints && m.endpoint_pbits; ++e)
        w.put(static_cast<std::uint32_t>(c.p[e]), 1);
    for (int s = 0; s < m.subsets && m.shared_pbits; ++s)
        w.put(static_cast<std::uint32_t>(c.p[2 * s]), 1);
    const bool alpha_first = c.mode == 4 && c.selector == 1; // primary set holds alpha then
    const std::uint8_t* primary = alpha_first ? c.alpha_idx : c.color_idx;
    const std::uint8_t* secondary = alpha_first ? c.color_idx : c.alpha_idx;
    const int primary_bits = alpha_first ? alpha_bits : color_bits;
    const int secondary_bits = alpha_first ? color_bits : alpha_bits;
    for (int i = 0; i < 16; ++i) {
        const bool anchor = i == anchor_of(m.subsets, c.partition, subset_of[i]);
        w.put(primary[i], anchor ? primary_bits - 1 : primary_bits);
    }
    for (int i = 0; i < 16 && m.index2_bits; ++i)
        w.put(secondary[i], i == 0 ? secondary_bits - 1 : secondary_bits);
    w.store(out);
}

// Modes with one index set per subset (0, 1, 2, 3, 6, 7).
// `opaque`: every texel has alpha 255. Mode 6 then fits RGB only with p-bits
// forced to 1, which keeps alpha exactly 255 (opaque stays opaque).
// `starts`: principal-axis endpoints per subset when the caller already has them
// (modes 1 and 3, or 0 and 2, share partitions, so the axes are computed once).
Candidate fit_mode(const Texels& t, int mode, int partition, const LevelConfig& cfg, bool opaque,
                   const Endpoints* starts = nullptr) {
    const ModeInfo& m = kModes[mode];
    const bool opaque_mode6 = mode == 6 && opaque;
    const Precision prec{m.color_bits, m.alpha_bits,
                         opaque_mode6       ? Pbits::ForcedOne
                         : m.endpoint_pbits ? Pbits::PerEndpoint
                         : m.shared_pbits   ? Pbits::Shared
                                            : Pbits::None,
                         (m.alpha_bits && !opaque_mode6) ? 4 : 3};
    Candidate c;
    c.mode = mode, c.partition = partition, c.error = 0.0f;
    for (int s = 0; s < m.subsets; ++s) {
        const std::uint32_t mask = m.subsets == 1   ? 0xFFFFu
                                   : m.subsets == 2 ? kTwoSubsetMasks[partition][s]
                                                    : kThreeSubsetMasks[partition][s];
        const int passes = mode == 6 ? cfg.refine_passes : cfg.partition_refine_passes;
        const SubsetFit fit = fit_subset(t, mask, prec, m.index_bits, passes, cfg.exhaustive_pbits,
                                         c.color_idx, starts ? &starts[s] : nullptr);
        for (int k = 0; k < 2; ++k) {
            for (int ch = 0; ch < 4; ++ch) c.q[2 * s + k][ch] = fit.q[k][ch];
            if (opaque_mode6) c.q[2 * s + k][3] = 127; // with p-bit 1: 255
            c.p[2 * s + k] = fit.p[k];
        }
        c.error += fit.error;
    }
    return c;
}

// Modes 4 and 5: colour and one rotated-in channel fitted with separate indices.
Candidate fit_separate_alpha(const Texels& t, int mode, int rotation, int selector,
                             const LevelConfig& cfg) {
    const ModeInfo& m = kModes[mode];
    Texels rotated = t;
    if (rotation) std::swap(rotated.ch[3], rotated.ch[rotation - 1]);
    Texels scalar;
    std::copy(std::begin(rotated.ch[3]), std::end(rotated.ch[3]), scalar.ch[0]);
    const int color_index_bits = (mode == 4 && selector == 1) ? 3 : 2;
    const int alpha_index_bits = mode == 4 ? (selector == 1 ? 2 : 3) : 2;
    Candidate c;
    c.mode = mode, c.rotation = rotation, c.selector = selector;
    const SubsetFit color =
        fit_subset(rotated, 0xFFFFu, Precision{m.color_bits, 0, Pbits::None, 3}, color_index_bits,
                   cfg.partition_refine_passes, false, c.color_idx);
    const SubsetFit alpha =
        fit_subset(scalar, 0xFFFFu, Precision{m.alpha_bits, 0, Pbits::None, 1}, alpha_index_bits,
                   cfg.partition_refine_passes, false, c.alpha_idx);
    for (int k = 0; k < 2; ++k) {
        for (int ch = 0; ch < 3; ++ch) c.q[k][ch] = color.q[k][ch];
        c.q[k][3] = alpha.q[k][0];
    }
    c.error = color.error + alpha.error;
    return c;
}

#include "encode_bc7_partitions.inc" // the partition ranking, in this namespace

// Principal-axis start endpoints (RGB) of every subset of a partition, into buf.
const Endpoints* subset_starts(const Texels& t, int subsets, int partition, Endpoints buf[3]) {
    const SubsetMasks& masks = subsets == 2 ? kTwoSubsetMasks : kThreeSubsetMasks;
    for (int s = 0; s < subsets; ++s)
        principal_endpoints<3>(t, masks[partition][s], buf[s].e[0], buf[s].e[1]);
    return buf;
}

} // namespace

void encode_bc7_block_kernel(const std::uint8_t rgba[64], int level, std::uint8_t out[16]) {
    const LevelConfig& cfg = kLevels[std::clamp(level, kBc7MinLevel, kBc7MaxLevel)];
    const Texels t = load_texels(rgba);
    bool opaque = true;
    for (int i = 0; i < 16; ++i) opaque &= rgba[i * 4 + 3] == 255;

    Candidate best = fit_mode(t, 6, 0, cfg, opaque);
    auto consider = [&](const Candidate& c) {
        if (c.error < best.error) best = c;
    };
    auto done = [&] { return best.error <= cfg.good_enough; };
    int parts[64];
    Endpoints starts_buf[3];
    if (opaque) {
        if (cfg.two_subset_parts && !done()) {
            const int n = rank_partitions(t, 2, 64, 3, cfg.two_subset_parts, parts);
            for (int i = 0; i < n; ++i) {
                const Endpoints* starts = subset_starts(t, 2, parts[i], starts_buf);
                consider(fit_mode(t, 1, parts[i], cfg, opaque, starts));
                consider(fit_mode(t, 3, parts[i], cfg, opaque, starts));
            }
        }
        if (cfg.three_subset_parts && !done()) {
            const int n = rank_partitions(t, 3, 64, 3, cfg.three_subset_parts, parts);
            for (int i = 0; i < n; ++i) {
                const Endpoints* starts = subset_starts(t, 3, parts[i], starts_buf);
                consider(fit_mode(t, 2, parts[i], cfg, opaque, starts));
                if (parts[i] < 16) consider(fit_mode(t, 0, parts[i], cfg, opaque, starts));
            }
        }
    } else {
        if (cfg.two_subset_parts && !done()) {
            const int n = rank_partitions(t, 2, 64, 4, cfg.two_subset_parts, parts);
            for (int i = 0; i < n; ++i) consider(fit_mode(t, 7, parts[i], cfg, opaque));
        }
    }
    if (cfg.rotations && (!opaque || cfg.separate_alpha_opaque) && !done()) {
        for (int rotation = 0; rotation < cfg.rotations; ++rotation) {
            consider(fit_separate_alpha(t, 5, rotation, 0, cfg));
            consider(fit_separate_alpha(t, 4, rotation, 0, cfg));
            consider(fit_separate_alpha(t, 4, rotation, 1, cfg));
        }
    }
    pack(best, out);
}

} // namespace sherpa::tex::SHERPA_KERNEL_NS
