#pragma once
// The fast BC7 block decoder behind decode_image: bit-exact with the reference
// decode_bc7_block, but specialised per mode and writing straight into the image.
#include <cstddef>
#include <cstdint>

namespace sherpa::tex::bc7 {

// Decodes one 16-byte block into four rows of four RGBA8 texels, `stride` bytes
// apart (the image's row pitch, or 16 for a packed 4x4 block).
void decode_block_fast(const std::uint8_t* block, std::uint8_t* dst, std::size_t stride);

} // namespace sherpa::tex::bc7
