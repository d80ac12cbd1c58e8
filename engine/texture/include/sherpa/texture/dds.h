#pragma once
// Minimal DDS writer: wraps one level of BC7/BC5 blocks in a DDS file with the
// DX10 extension header. Used to hand our blocks to an independent decoder
// (OpenImageIO's DDS reader) in tests and tools; Sherpa's cache uses KTX2.
#include <cstdint>
#include <span>
#include <vector>

#include <sherpa/texture/block_codecs.h>

namespace sherpa::tex {

// Throws std::invalid_argument when `blocks` does not match width x height.
std::vector<std::uint8_t> wrap_in_dds(BlockFormat format, std::uint32_t width, std::uint32_t height,
                                      std::span<const std::uint8_t> blocks);

} // namespace sherpa::tex
