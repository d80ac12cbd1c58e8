// Instruction-set dispatch, BC5 decoding and whole-image encode/decode over blocks.
#include <sherpa/texture/block_codecs.h>

#include <algorithm>
#include <omp.h>
#include <stdexcept>
#include <string>

#include "bc7_decode_fast.h"
#include "kernel_entry.h"

namespace sherpa::tex {

namespace {
using KernelFn = void (*)(const std::uint8_t*, int, std::uint8_t*);

// A requested level the CPU lacks falls back to the best one it has, so a caller
// can never run an illegal instruction.
KernelFn pick_kernel(BlockFormat format, core::SimdLevel requested) {
    const core::SimdLevel level = std::min(requested, core::best_simd_level());
    const bool bc7 = format == BlockFormat::Bc7;
    switch (level) {
    case core::SimdLevel::Avx512:
        return bc7 ? avx512::encode_bc7_block_kernel : avx512::encode_bc5_block_kernel;
    case core::SimdLevel::Avx2:
        return bc7 ? avx2::encode_bc7_block_kernel : avx2::encode_bc5_block_kernel;
    case core::SimdLevel::Scalar:
        break;
    }
    return bc7 ? scalar::encode_bc7_block_kernel : scalar::encode_bc5_block_kernel;
}

void decode_bc4(const std::uint8_t in[8], std::uint8_t* rgba, int channel) {
    const int e0 = in[0], e1 = in[1];
    int pal[8] = {e0, e1};
    if (e0 > e1) {
        for (int k = 1; k <= 6; ++k) pal[k + 1] = ((7 - k) * e0 + k * e1 + 3) / 7;
    } else {
        for (int k = 1; k <= 4; ++k) pal[k + 1] = ((5 - k) * e0 + k * e1 + 2) / 5;
        pal[6] = 0, pal[7] = 255;
    }
    std::uint64_t bits = 0;
    for (int b = 0; b < 6; ++b) bits |= std::uint64_t{in[2 + b]} << (8 * b);
    for (int i = 0; i < 16; ++i)
        rgba[i * 4 + channel] = static_cast<std::uint8_t>(pal[(bits >> (3 * i)) & 7]);
}
} // namespace

void encode_bc7_block(std::span<const std::uint8_t, kBlockTexelBytes> rgba,
                      const EncodeSettings& settings, std::span<std::uint8_t, kBlockBytes> out) {
    pick_kernel(BlockFormat::Bc7, settings.simd)(rgba.data(), settings.level, out.data());
}

void encode_bc5_block(std::span<const std::uint8_t, kBlockTexelBytes> rgba,
                      const EncodeSettings& settings, std::span<std::uint8_t, kBlockBytes> out) {
    pick_kernel(BlockFormat::Bc5, settings.simd)(rgba.data(), settings.level, out.data());
}

void decode_bc5_block(std::span<const std::uint8_t, kBlockBytes> block,
                      std::span<std::uint8_t, kBlockTexelBytes> rgba) {
    decode_bc4(block.data(), rgba.data(), 0);
    decode_bc4(block.data() + 8, rgba.data(), 1);
    for (int i = 0; i < 16; ++i) rgba[i * 4 + 2] = 0, rgba[i * 4 + 3] = 255;
}

void gather_block(std::span<const std::uint8_t> rgba, std::uint32_t width, std::uint32_t height,
                  std::uint32_t bx, std::uint32_t by,
                  std::span<std::uint8_t, kBlockTexelBytes> block) {
    if (bx * 4 + 4 <= width && by * 4 + 4 <= height) { // interior: four 16-byte rows
        for (std::uint32_t y = 0; y < 4; ++y)
            std::copy_n(rgba.data() + ((std::size_t{by} * 4 + y) * width + bx * 4) * 4, 16,
                        block.data() + y * 16);
        return;
    }
    for (std::uint32_t y = 0; y < 4; ++y) {
        const std::uint32_t sy = std::min(by * 4 + y, height - 1);
        for (std::uint32_t x = 0; x < 4; ++x) {
            const std::uint32_t sx = std::min(bx * 4 + x, width - 1);
            const std::uint8_t* src = rgba.data() + (std::size_t{sy} * width + sx) * 4;
            std::copy(src, src + 4, block.data() + (y * 4 + x) * 4);
        }
    }
}

namespace {
void check_image(std::span<const std::uint8_t> rgba, std::uint32_t width, std::uint32_t height) {
    if (width == 0 || height == 0 || rgba.size() != std::size_t{width} * height * 4)
        throw std::invalid_argument("block image: " + std::to_string(width) + "x" +
                                    std::to_string(height) + " RGBA8 needs " +
                                    std::to_string(std::size_t{width} * height * 4) +
                                    " bytes, got " + std::to_string(rgba.size()));
}
} // namespace

std::vector<std::uint8_t> encode_image(BlockFormat format, std::span<const std::uint8_t> rgba,
                                       std::uint32_t width, std::uint32_t height,
                                       const EncodeSettings& settings, int threads) {
    check_image(rgba, width, height);
    const KernelFn kernel = pick_kernel(format, settings.simd);
    const std::uint32_t bw = blocks_along(width), bh = blocks_along(height);
    std::vector<std::uint8_t> out(compressed_size(width, height));
    const long long total = static_cast<long long>(bw) * bh;
    // num_threads must be positive: 0 means "OpenMP's default", spelled out here.
    const int team = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 64) num_threads(team) if (team != 1)
    for (long long b = 0; b < total; ++b) {
        std::uint8_t texels[kBlockTexelBytes];
        const auto bx = static_cast<std::uint32_t>(b % bw), by = static_cast<std::uint32_t>(b / bw);
        gather_block(rgba, width, height, bx, by,
                     std::span<std::uint8_t, kBlockTexelBytes>(texels));
        kernel(texels, settings.level, out.data() + b * kBlockBytes);
    }
    return out;
}

namespace {
void check_blocks(std::span<const std::uint8_t> blocks, std::uint32_t width, std::uint32_t height) {
    if (width == 0 || height == 0 || blocks.size() != compressed_size(width, height))
        throw std::invalid_argument("decode_image: " + std::to_string(blocks.size()) +
                                    " bytes do not hold " + std::to_string(width) + "x" +
                                    std::to_string(height) + " in 4x4 blocks");
}
} // namespace

std::vector<std::uint8_t> decode_image_per_block(BlockFormat format,
                                                 std::span<const std::uint8_t> blocks,
                                                 std::uint32_t width, std::uint32_t height) {
    check_blocks(blocks, width, height);
    const std::uint32_t bw = blocks_along(width), bh = blocks_along(height);
    std::vector<std::uint8_t> rgba(std::size_t{width} * height * 4);
    for (std::uint32_t by = 0; by < bh; ++by)
        for (std::uint32_t bx = 0; bx < bw; ++bx) {
            std::uint8_t texels[kBlockTexelBytes];
            const auto block =
                blocks.subspan((std::size_t{by} * bw + bx) * kBlockBytes).first<kBlockBytes>();
            const std::span<std::uint8_t, kBlockTexelBytes> dst(texels);
            if (format == BlockFormat::Bc7)
                decode_bc7_block(block, dst);
            else
                decode_bc5_block(block, dst);
            for (std::uint32_t y = 0; y < 4 && by * 4 + y < height; ++y)
                for (std::uint32_t x = 0; x < 4 && bx * 4 + x < width; ++x)
                    std::copy_n(texels + (y * 4 + x) * 4, 4,
                                rgba.data() + ((std::size_t{by} * 4 + y) * width + bx * 4 + x) * 4);
        }
    return rgba;
}

std::vector<std::uint8_t> decode_image(BlockFormat format, std::span<const std::uint8_t> blocks,
                                       std::uint32_t width, std::uint32_t height, int threads) {
    check_blocks(blocks, width, height);
    const std::uint32_t bw = blocks_along(width), bh = blocks_along(height);
    std::vector<std::uint8_t> rgba(std::size_t{width} * height * 4);
    const std::size_t pitch = std::size_t{width} * 4;
    const bool bc7 = format == BlockFormat::Bc7;
    const int team = threads > 0 ? threads : omp_get_max_threads();
    // Below ~64K texels a thread team costs more than it saves.
    const bool parallel = team != 1 && std::size_t{width} * height >= (1u << 16);
#pragma omp parallel for schedule(dynamic, 4) num_threads(team) if (parallel)
    for (long long row = 0; row < static_cast<long long>(bh); ++row) {
        const auto by = static_cast<std::uint32_t>(row);
        const std::uint8_t* in = blocks.data() + std::size_t{by} * bw * kBlockBytes;
        std::uint8_t* out_row = rgba.data() + std::size_t{by} * 4 * pitch;
        const std::uint32_t rows = std::min<std::uint32_t>(4, height - by * 4);
        for (std::uint32_t bx = 0; bx < bw; ++bx, in += kBlockBytes) {
            const std::uint32_t cols = std::min<std::uint32_t>(4, width - bx * 4);
            std::uint8_t* out = out_row + std::size_t{bx} * 16;
            if (bc7 && rows == 4 && cols == 4) { // interior: straight into the image
                bc7::decode_block_fast(in, out, pitch);
                continue;
            }
            std::uint8_t texels[kBlockTexelBytes];
            if (bc7)
                bc7::decode_block_fast(in, texels, 16);
            else
                decode_bc5_block(std::span<const std::uint8_t, kBlockBytes>(in, kBlockBytes),
                                 std::span<std::uint8_t, kBlockTexelBytes>(texels));
            for (std::uint32_t y = 0; y < rows; ++y)
                std::copy_n(texels + y * 16, cols * 4, out + y * pitch);
        }
    }
    return rgba;
}

} // namespace sherpa::tex
