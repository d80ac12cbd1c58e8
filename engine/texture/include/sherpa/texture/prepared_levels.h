#pragma once
// A prepared texture's mip level as RGBA8 on the CPU, as the GPU samples it:
// thumbnails and previews of the texture cache's BC7/BC5 blocks.
#include <cstdint>
#include <vector>

#include <sherpa/texture/texture_pipeline.h>

namespace sherpa::tex {

// Level `level` of `texture` as tightly packed RGBA8 rows: BC7 blocks decoded, BC5
// decoded with z rebuilt, RGBA8 as is. Empty when the texture failed, the level does
// not exist or its bytes do not match its size.
std::vector<std::uint8_t> decode_level_rgba8(const PreparedTexture& texture, std::uint32_t level);

} // namespace sherpa::tex
