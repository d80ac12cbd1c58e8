#pragma once
// Mip chains for the three texture roles, filtered the way each role needs:
//  - colour: sRGB texels are linearised, filtered with alpha weighting (so fully
//    transparent texels do not bleed their colour), and re-encoded to sRGB;
//    alpha itself is linear;
//  - linear data: all four channels filtered as they are;
//  - normals: texels decoded to unit vectors, averaged and renormalised.
// Each level is a box filter of the one above it over the exact footprint (odd
// sizes give fractional weights), computed in float from float, so rounding
// does not accumulate down the chain.
#include <cstdint>
#include <optional>
#include <vector>

#include <sherpa/texture/image.h>

namespace sherpa::tex {

enum class MipFilter : std::uint8_t { Color, Linear, Normal };

struct MipSettings {
    MipFilter filter = MipFilter::Color;
    // Alpha-masked materials: scale each level's alpha so the fraction of texels
    // with alpha >= cutoff matches level 0 (otherwise foliage thins out with distance).
    std::optional<float> alpha_coverage_cutoff;
};

// Number of levels of a full chain down to 1x1.
std::uint32_t full_mip_count(std::uint32_t width, std::uint32_t height);

// The full chain; [0] is a copy of `base`. `base` must not be empty
// (std::invalid_argument otherwise).
std::vector<RgbaImage> build_mip_chain(const RgbaImage& base, const MipSettings& settings);

// Fraction of texels whose alpha / 255 >= cutoff.
double alpha_coverage(const RgbaImage& image, float cutoff);

// sRGB transfer functions on [0, 1] (IEC 61966-2-1).
float srgb_to_linear(float encoded);
float linear_to_srgb(float linear);

} // namespace sherpa::tex
