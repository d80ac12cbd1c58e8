#pragma once
// An image's luminance box-filtered down to a small grid: what the path tracer weighs
// emissive triangles by (render/emissive_lights.h). Made by the texture pipeline while
// it holds an emissive image's decoded pixels, and kept in the texture cache beside the
// levels, so that a ray-traced load does not decode the image a second time.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sherpa::tex {

// The grid is at most this many texels a side.
inline constexpr std::uint32_t kLuminanceGridSize = 256;

struct LuminanceGrid {
    std::uint32_t width = 0, height = 0;
    std::vector<float> texels; // rows top to bottom (uv (0, 0) is the first texel)
    double mean = 0.0;
};

// The luminance (linear, from sRGB texels; Rec. 709 weights) of a `width` x `height`
// RGBA8 image, each grid texel the mean of the source texels it covers.
LuminanceGrid luminance_grid(std::uint32_t width, std::uint32_t height,
                             std::span<const std::uint8_t> rgba8_srgb);

// The grid as bytes for a texture-cache metadata entry (sizes, mean, texels, all
// little-endian as in memory), and back; false for bytes that are not such a grid.
std::string encode_luminance_grid(const LuminanceGrid& grid);
bool decode_luminance_grid(const std::string& bytes, LuminanceGrid& grid);

} // namespace sherpa::tex
