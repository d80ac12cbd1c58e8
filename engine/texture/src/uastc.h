#pragma once
// UASTC LDR 4x4 block decoding (Binomial's "UASTC Texture Specification", public
// domain): one 128-bit block to 16 RGBA8 texels, as ASTC decodes it.
#include <cstdint>

namespace sherpa::tex::uastc {

inline constexpr int kModeCount = 19;
inline constexpr int kSolidColorMode = 8;

enum class BlockStatus : std::uint8_t {
    Ok,
    ReservedMode,   // the mode code is the reserved one (19)
    BadPatternIndex // a partition pattern index past its table
};

// Mode of a block (0..18), or kModeCount for the reserved code.
int block_mode(const std::uint8_t* block);

// Decodes `block` (16 bytes) into `rgba` (16 texels, raster order, 4 bytes each).
// `srgb_interpolation` selects ASTC's sRGB endpoint expansion (e << 8 | 0x80)
// instead of the linear one (e * 257); see the spec's astc_interpolate.
BlockStatus decode_block(const std::uint8_t* block, std::uint8_t* rgba, bool srgb_interpolation);

} // namespace sherpa::tex::uastc
