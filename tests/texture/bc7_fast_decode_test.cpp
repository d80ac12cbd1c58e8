// decode_image's fast BC7 path must be bit-exact with the reference per-block
// decoder (decode_bc7_block) on random blocks of every mode, reserved mode bytes
// and real encoder output, for images with and without partial edge blocks and
// for any thread count.
#include <gtest/gtest.h>

#include <random>

#include <sherpa/texture/block_codecs.h>

#include "test_images.h"

using namespace sherpa;
using namespace sherpa::tex;

namespace {

// Random blocks whose first byte selects `mode` (8: a reserved, all-zero mode byte).
std::vector<std::uint8_t> random_blocks(int mode, std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<std::uint8_t> blocks(count * kBlockBytes);
    for (auto& b : blocks) b = static_cast<std::uint8_t>(rng());
    for (std::size_t i = 0; i < count; ++i) {
        std::uint8_t& first = blocks[i * kBlockBytes];
        first =
            mode == 8 ? 0 : static_cast<std::uint8_t>((first & ~((2u << mode) - 1)) | 1u << mode);
    }
    return blocks;
}

// Decodes `blocks` as images of several shapes (exact multiples of 4 and with
// partial edge blocks) and thread counts; every one must match the reference.
void expect_fast_matches_reference(const std::vector<std::uint8_t>& blocks) {
    const std::size_t count = blocks.size() / kBlockBytes;
    const std::uint32_t bw = 16, bh = static_cast<std::uint32_t>(count / bw);
    ASSERT_GT(bh, 0u);
    const std::vector<std::uint8_t> used(blocks.begin(),
                                         blocks.begin() + std::size_t{bw} * bh * kBlockBytes);
    for (const auto& [w, h] : {std::pair{bw * 4, bh * 4}, std::pair{bw * 4 - 1, bh * 4 - 3},
                               std::pair{bw * 4 - 2, bh * 4 - 1}}) {
        const auto expected = decode_image_per_block(BlockFormat::Bc7, used, w, h);
        for (int threads : {1, 2, 0}) {
            SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " threads " +
                         std::to_string(threads));
            EXPECT_EQ(decode_image(BlockFormat::Bc7, used, w, h, threads), expected);
        }
    }
}

} // namespace

TEST(Bc7FastDecode, MatchesReferenceOnRandomBlocksOfEveryMode) {
    for (int mode = 0; mode <= 8; ++mode) {
        SCOPED_TRACE("mode " + std::to_string(mode));
        // 16 x 272 blocks: a 64 x 1088 image, big enough to run in parallel.
        expect_fast_matches_reference(random_blocks(mode, 16 * 272, 1000u + mode));
    }
}

TEST(Bc7FastDecode, MatchesReferenceOnFullyRandomBytes) {
    std::mt19937 rng(7);
    std::vector<std::uint8_t> blocks(16 * 64 * kBlockBytes);
    for (auto& b : blocks) b = static_cast<std::uint8_t>(rng());
    expect_fast_matches_reference(blocks);
}

TEST(Bc7FastDecode, MatchesReferenceOnEncodedCorpusBlocks) {
    const RgbaImage images[] = {
        test::synthetic_image(64, 64, false, 1), test::synthetic_image(64, 64, true, 2),
        test::load_crop(test::assets_dir() / "gltf/DamagedHelmet/glTF/Default_albedo.jpg", 700, 900,
                        64, 64)};
    std::vector<std::uint8_t> all;
    int modes = 0;
    for (const auto& img : images)
        for (int level = kBc7MinLevel; level <= kBc7MaxLevel; ++level) {
            const auto blocks = encode_image(BlockFormat::Bc7, img.pixels, img.width, img.height,
                                             {level, core::best_simd_level()}, 1);
            for (std::size_t b = 0; b < blocks.size(); b += kBlockBytes)
                modes |= blocks[b] ? 1 << __builtin_ctz(blocks[b]) : 0;
            all.insert(all.end(), blocks.begin(), blocks.end());
        }
    EXPECT_EQ(modes, 0xff); // real blocks of every mode 0-7
    expect_fast_matches_reference(all);
}
