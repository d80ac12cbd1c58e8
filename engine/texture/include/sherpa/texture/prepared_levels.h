#pragma once
// A prepared texture's mip level as RGBA8 on the CPU, as the GPU samples it:
// thumbnails and previews of the texture cache's BC7/BC5 blocks.
#include <cstdint>
#include <span>
#include <vector>

#include <sherpa/texture/texture_pipeline.h>

namespace sherpa::tex {

// Rebuilds z of unit normals stored in x (R) and y (G) as the shaders do
// (z = sqrt(1 - x² - y²), clamped at 0) into B of each RGBA8 texel.
// `rgba.size()` must be a multiple of 4.
void rebuild_normal_z(std::span<std::uint8_t> rgba);

// Level `level` of `texture` as tightly packed RGBA8 rows: BC7 blocks decoded, BC5
// decoded with z rebuilt, RGBA8 as is. Empty when the texture failed, the level does
// not exist or its bytes do not match its size.
std::vector<std::uint8_t> decode_level_rgba8(const PreparedTexture& texture, std::uint32_t level);

} // namespace sherpa::tex
