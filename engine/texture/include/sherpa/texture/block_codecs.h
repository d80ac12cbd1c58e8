#pragma once
// Block compression for BC7 (RGBA, 8 bits per texel) and BC5 (two channels,
// 8 bits per texel): pure functions over one 4x4 block or a whole image.
//
// Texel order inside a block is row-major (x fastest), 4 bytes per texel (RGBA8).
// Blocks of an image are stored row-major, 16 bytes each. Images whose sides are
// not multiples of 4 are encoded with their edge texels replicated into the
// padding, so every decoded in-image texel comes from real data.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include <sherpa/core/cpu_features.h>
#include <sherpa/texture/quality_levels.h>

namespace sherpa::tex {

// Instruction sets the encoders have kernels for: the engine's one SimdLevel
// (core layer, shared with the scene layer's culling). `best_simd_level()` asks the CPU; callers
// pass the level explicitly so tests can compare kernels.
using ::sherpa::core::best_simd_level;
using ::sherpa::core::SimdLevel;
using ::sherpa::core::to_string;

struct EncodeSettings {
    int level = kBc7DefaultLevel; // clamped to the format's range
    SimdLevel simd = SimdLevel::Scalar;
};

inline constexpr std::size_t kBlockBytes = 16;
inline constexpr std::size_t kBlockTexelBytes = 64; // 16 texels x RGBA8

void encode_bc7_block(std::span<const std::uint8_t, kBlockTexelBytes> rgba,
                      const EncodeSettings& settings, std::span<std::uint8_t, kBlockBytes> out);
// Reserved mode bytes (no mode bit set) decode to transparent black, as the spec says.
void decode_bc7_block(std::span<const std::uint8_t, kBlockBytes> block,
                      std::span<std::uint8_t, kBlockTexelBytes> rgba);

// BC5 stores the red and green channels; blue and alpha of the input are ignored.
void encode_bc5_block(std::span<const std::uint8_t, kBlockTexelBytes> rgba,
                      const EncodeSettings& settings, std::span<std::uint8_t, kBlockBytes> out);
// Writes R and G; blue decodes to 0 and alpha to 255.
void decode_bc5_block(std::span<const std::uint8_t, kBlockBytes> block,
                      std::span<std::uint8_t, kBlockTexelBytes> rgba);

enum class BlockFormat : std::uint8_t { Bc7, Bc5 };

inline std::uint32_t blocks_along(std::uint32_t texels) {
    return (texels + 3) / 4;
}
inline std::size_t compressed_size(std::uint32_t width, std::uint32_t height) {
    return std::size_t{blocks_along(width)} * blocks_along(height) * kBlockBytes;
}

// Copies the 4x4 block at block coordinates (bx, by) out of a tightly packed
// RGBA8 image, replicating edge texels where the block overhangs the image.
void gather_block(std::span<const std::uint8_t> rgba, std::uint32_t width, std::uint32_t height,
                  std::uint32_t bx, std::uint32_t by,
                  std::span<std::uint8_t, kBlockTexelBytes> block);

// Compresses a tightly packed RGBA8 image (width * height * 4 bytes, both sides
// >= 1). Blocks are encoded in parallel with OpenMP over `threads` threads
// (0: OpenMP's default). Throws std::invalid_argument on a size mismatch.
std::vector<std::uint8_t> encode_image(BlockFormat format, std::span<const std::uint8_t> rgba,
                                       std::uint32_t width, std::uint32_t height,
                                       const EncodeSettings& settings, int threads = 0);

// Decodes compressed blocks back to a tightly packed RGBA8 image of the given size,
// bit-exact with decode_bc7_block / decode_bc5_block. Block rows are decoded in
// parallel with OpenMP over `threads` threads (0: OpenMP's default; small images
// stay on the calling thread). Throws std::invalid_argument when `blocks` has the
// wrong size.
std::vector<std::uint8_t> decode_image(BlockFormat format, std::span<const std::uint8_t> blocks,
                                       std::uint32_t width, std::uint32_t height, int threads = 0);

// The reference decode_image: decode_bc7_block / decode_bc5_block per block on one
// thread, each block copied texel by texel. Slow; for tests and benchmarks of the
// fast path. Same arguments, result and exceptions as decode_image.
std::vector<std::uint8_t> decode_image_per_block(BlockFormat format,
                                                 std::span<const std::uint8_t> blocks,
                                                 std::uint32_t width, std::uint32_t height);

} // namespace sherpa::tex
