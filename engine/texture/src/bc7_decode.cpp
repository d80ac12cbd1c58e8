// BC7 block decoder, written from the ARB_texture_compression_bptc description.
#include <sherpa/texture/block_codecs.h>

#include <algorithm>

#include "bc7_tables.h"

namespace sherpa::tex {

using namespace bc7;

void decode_bc7_block(std::span<const std::uint8_t, kBlockBytes> block,
                      std::span<std::uint8_t, kBlockTexelBytes> rgba) {
    BitReader bits(block.data());
    int mode = 0;
    while (mode < 8 && bits.get(1) == 0) ++mode;
    if (mode == 8) {
        std::fill(rgba.begin(), rgba.end(), std::uint8_t{0});
        return;
    }
    const ModeInfo& m = kModes[mode];
    const int partition = static_cast<int>(bits.get(m.partition_bits));
    const int rotation = static_cast<int>(bits.get(m.rotation_bits));
    const int selector = static_cast<int>(bits.get(m.selector_bits));

    const int endpoints = m.subsets * 2;
    int ep[6][4] = {}; // [endpoint][channel], endpoint = subset * 2 + {0, 1}
    for (int c = 0; c < 3; ++c)
        for (int e = 0; e < endpoints; ++e) ep[e][c] = static_cast<int>(bits.get(m.color_bits));
    for (int e = 0; e < endpoints; ++e)
        ep[e][3] = m.alpha_bits ? static_cast<int>(bits.get(m.alpha_bits)) : 255;

    // Append p-bits, then expand every channel to 8 bits.
    int pbit[6] = {};
    const bool has_pbits = m.endpoint_pbits || m.shared_pbits;
    if (m.endpoint_pbits)
        for (int e = 0; e < endpoints; ++e) pbit[e] = static_cast<int>(bits.get(1));
    if (m.shared_pbits)
        for (int s = 0; s < m.subsets; ++s)
            pbit[2 * s] = pbit[2 * s + 1] = static_cast<int>(bits.get(1));
    for (int e = 0; e < endpoints; ++e) {
        for (int c = 0; c < 3; ++c) {
            const int v = has_pbits ? (ep[e][c] << 1) | pbit[e] : ep[e][c];
            ep[e][c] = expand_to_8(v, m.color_bits + (has_pbits ? 1 : 0));
        }
        if (m.alpha_bits) {
            const int v = has_pbits ? (ep[e][3] << 1) | pbit[e] : ep[e][3];
            ep[e][3] = expand_to_8(v, m.alpha_bits + (has_pbits ? 1 : 0));
        }
    }

    const auto& subset_of = partition_of(m.subsets, partition);
    auto read_indices = [&](int index_bits, std::uint8_t out[16]) {
        for (int i = 0; i < 16; ++i) {
            const int s = subset_of[i];
            const bool anchor = i == anchor_of(m.subsets, partition, s);
            out[i] = static_cast<std::uint8_t>(bits.get(anchor ? index_bits - 1 : index_bits));
        }
    };
    std::uint8_t primary[16], secondary[16];
    read_indices(m.index_bits, primary);
    if (m.index2_bits) read_indices(m.index2_bits, secondary);

    // Which index set drives colour and alpha (spec: secondary for colour when the
    // selector is 1, secondary for alpha when present and the selector is 0).
    const bool color_secondary = m.index2_bits && selector == 1;
    const bool alpha_secondary = m.index2_bits && selector == 0;
    const std::uint8_t* color_idx = color_secondary ? secondary : primary;
    const std::uint8_t* alpha_idx = alpha_secondary ? secondary : primary;
    const std::uint8_t* color_w = weights_for_bits(color_secondary ? m.index2_bits : m.index_bits);
    const std::uint8_t* alpha_w = weights_for_bits(alpha_secondary ? m.index2_bits : m.index_bits);

    for (int i = 0; i < 16; ++i) {
        const int s = subset_of[i];
        const int* e0 = ep[2 * s];
        const int* e1 = ep[2 * s + 1];
        int px[4];
        for (int c = 0; c < 3; ++c) px[c] = interpolate(e0[c], e1[c], color_w[color_idx[i]]);
        px[3] = interpolate(e0[3], e1[3], alpha_w[alpha_idx[i]]);
        if (rotation) std::swap(px[3], px[rotation - 1]);
        for (int c = 0; c < 4; ++c) rgba[i * 4 + c] = static_cast<std::uint8_t>(px[c]);
    }
}

} // namespace sherpa::tex
