// BC5 (two BC4 channels) block encoder. Compiled once per instruction set (see
// encode_kernels.h); the fixed 16-texel loops are written for the vectoriser.
#include "encode_kernels.h"

#include <algorithm>
#include <utility>

#include "kernel_entry.h"

namespace sherpa::tex::SHERPA_KERNEL_NS {
namespace {

// The eight values a BC4 block can decode to for endpoints (e0, e1): six
// interpolants when e0 > e1, else four interpolants plus 0 and 255.
void bc4_palette(int e0, int e1, float pal[8]) {
    pal[0] = static_cast<float>(e0);
    pal[1] = static_cast<float>(e1);
    if (e0 > e1) {
        for (int k = 1; k <= 6; ++k)
            pal[k + 1] = static_cast<float>(((7 - k) * e0 + k * e1 + 3) / 7);
    } else {
        for (int k = 1; k <= 4; ++k)
            pal[k + 1] = static_cast<float>(((5 - k) * e0 + k * e1 + 2) / 5);
        pal[6] = 0.0f;
        pal[7] = 255.0f;
    }
}

// Squared error of the best index per texel; indices go to idx[]. The channel
// sits in row 0 of `t`, so the SIMD index search of the BC7 encoder serves here.
float bc4_select(const Texels& t, int e0, int e1, std::uint8_t idx[16]) {
    float values[8];
    bc4_palette(e0, e1, values);
    Palette pal;
    pal.count = 8;
    for (int k = 0; k < 8; ++k) pal.ch[0][k] = values[k];
    return select_indices(t, 0xFFFFu, pal, 1, idx);
}

// Weight of e1 for each index of the eight-value (e0 > e1) mode.
constexpr float kWeightOfE1[8] = {0.0f,     1.0f,     1.0f / 7, 2.0f / 7,
                                  3.0f / 7, 4.0f / 7, 5.0f / 7, 6.0f / 7};

struct Bc4Fit {
    int e0 = 0, e1 = 0;
    std::uint8_t idx[16] = {};
    float error = 3.0e38f;
};

void try_endpoints(const Texels& t, int e0, int e1, Bc4Fit& best) {
    std::uint8_t idx[16];
    const float err = bc4_select(t, e0, e1, idx);
    if (err < best.error) {
        best.e0 = e0, best.e1 = e1, best.error = err;
        std::copy(idx, idx + 16, best.idx);
    }
}

Bc4Fit fit_bc4(const Texels& t, int level) {
    const float* v = t.ch[0];
    float lo = v[0], hi = v[0];
    for (int i = 1; i < 16; ++i) lo = std::min(lo, v[i]), hi = std::max(hi, v[i]);
    Bc4Fit best;
    if (lo == hi) { // constant: six-value mode with both endpoints equal is exact
        try_endpoints(t, static_cast<int>(lo), static_cast<int>(lo), best);
        return best;
    }
    try_endpoints(t, static_cast<int>(hi), static_cast<int>(lo), best);
    // Alternate index choice and 1-D least squares on the eight-value mode.
    const int passes = level == 0 ? 1 : 3;
    for (int pass = 0; pass < passes && best.e0 > best.e1; ++pass) {
        float aa = 0, ab = 0, bb = 0, av = 0, bv = 0;
        for (int i = 0; i < 16; ++i) {
            const float w = kWeightOfE1[best.idx[i]], a = 1.0f - w;
            aa += a * a, ab += a * w, bb += w * w, av += a * v[i], bv += w * v[i];
        }
        const float det = aa * bb - ab * ab;
        if (det < 1e-6f) break;
        const int e0 = std::clamp(static_cast<int>((bb * av - ab * bv) / det + 0.5f), 0, 255);
        const int e1 = std::clamp(static_cast<int>((aa * bv - ab * av) / det + 0.5f), 0, 255);
        if (e0 <= e1 || (e0 == best.e0 && e1 == best.e1)) break;
        try_endpoints(t, e0, e1, best);
    }
    // Blocks already within about one step per texel gain nothing from searching.
    if (level >= 1 && best.error > 12.0f) {
        // Local search: nudge each endpoint of the best eight-value pair by one.
        const int c0 = best.e0, c1 = best.e1;
        for (const auto& [d0, d1] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
            const int e0 = c0 + d0, e1 = c1 + d1;
            if (e0 <= 255 && e1 >= 0 && e0 > e1) try_endpoints(t, e0, e1, best);
        }
        // Six-value mode pays off when a block holds exact 0 or 255 texels.
        if (lo == 0.0f || hi == 255.0f) {
            float ilo = 255.0f, ihi = 0.0f;
            for (int i = 0; i < 16; ++i)
                if (v[i] > 0.0f && v[i] < 255.0f)
                    ilo = std::min(ilo, v[i]), ihi = std::max(ihi, v[i]);
            if (ilo <= ihi) try_endpoints(t, static_cast<int>(ilo), static_cast<int>(ihi), best);
        }
    }
    return best;
}

void pack_bc4(const Bc4Fit& fit, std::uint8_t out[8]) {
    out[0] = static_cast<std::uint8_t>(fit.e0);
    out[1] = static_cast<std::uint8_t>(fit.e1);
    std::uint64_t bits = 0;
    for (int i = 0; i < 16; ++i) bits |= std::uint64_t{fit.idx[i]} << (3 * i);
    for (int b = 0; b < 6; ++b) out[2 + b] = static_cast<std::uint8_t>(bits >> (8 * b));
}

} // namespace

void encode_bc5_block_kernel(const std::uint8_t rgba[64], int level, std::uint8_t out[16]) {
    for (int channel = 0; channel < 2; ++channel) {
        Texels t{};
        for (int i = 0; i < 16; ++i) t.ch[0][i] = static_cast<float>(rgba[i * 4 + channel]);
        pack_bc4(fit_bc4(t, level), out + 8 * channel);
    }
}

} // namespace sherpa::tex::SHERPA_KERNEL_NS
