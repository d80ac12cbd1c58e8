// Encoder quality and edge cases: PSNR floors per level on crops of the corpus
// (quality only, never time), tiny and odd-sized images, constant blocks, alpha.
#include <gtest/gtest.h>

#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/quality.h>

#include "test_images.h"

using namespace sherpa;
using namespace sherpa::tex;

namespace {

struct Sample {
    RgbaImage image;
    unsigned channels;
};

// 128x128 crops: DamagedHelmet albedo and metal-roughness, a Sponza colour map,
// and a Sponza map with alpha (RGBA error).
std::vector<Sample> bc7_samples() {
    const auto helmet = test::assets_dir() / "gltf/DamagedHelmet/glTF";
    const auto sponza = test::assets_dir() / "textures/sponza";
    return {
        {test::load_crop(helmet / "Default_albedo.jpg", 640, 880, 128, 128), kChannelsRgb},
        {test::load_crop(helmet / "Default_metalRoughness.jpg", 1024, 512, 128, 128), kChannelsRgb},
        {test::load_crop(sponza / "10381718147657362067.jpg", 448, 448, 128, 128), kChannelsRgb},
        {test::load_crop(sponza / "5061699253647017043.png", 384, 384, 128, 128), kChannelsRgba}};
}

SquaredError encode_error(BlockFormat format, const RgbaImage& img, int level, unsigned channels,
                          core::SimdLevel simd = core::best_simd_level()) {
    const auto blocks = encode_image(format, img.pixels, img.width, img.height, {level, simd});
    return squared_error(img.pixels, decode_image(format, blocks, img.width, img.height), channels);
}

int max_abs_diff(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                 unsigned channels) {
    int worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (channels >> (i & 3) & 1u) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
    return worst;
}

} // namespace

// Floors sit a little under what each level measured on these crops when the
// test was written; a level must also never be worse than the one below it.
TEST(EncoderQuality, Bc7PsnrFloorsPerLevel) {
    const double floors[kBc7MaxLevel + 1] = {35.8, 40.0, 41.2, 42.7, 42.8};
    const auto samples = bc7_samples();
    double previous = 0.0;
    for (int level = kBc7MinLevel; level <= kBc7MaxLevel; ++level) {
        SquaredError pooled;
        for (const Sample& s : samples)
            pooled += encode_error(BlockFormat::Bc7, s.image, level, s.channels);
        std::printf("BC7 level %d: %.3f dB\n", level, pooled.psnr());
        EXPECT_GE(pooled.psnr(), floors[level]) << "level " << level;
        EXPECT_GE(pooled.psnr(), previous - 0.05)
            << "level " << level << " worse than the level below";
        previous = pooled.psnr();
    }
}

TEST(EncoderQuality, Bc5PsnrAndAngleFloors) {
    const auto helmet = test::assets_dir() / "gltf/DamagedHelmet/glTF/Default_normal.jpg";
    const auto sponza = test::assets_dir() / "textures/sponza/10388182081421875623.jpg";
    const std::vector<RgbaImage> normals = {test::load_crop(helmet, 700, 1200, 128, 128),
                                            test::load_crop(sponza, 256, 256, 128, 128)};
    const double psnr_floor[kBc5MaxLevel + 1] = {45.1, 45.5};
    for (int level = kBc5MinLevel; level <= kBc5MaxLevel; ++level) {
        SquaredError pooled;
        AngleError angle;
        for (const RgbaImage& n : normals) {
            const auto blocks = encode_image(BlockFormat::Bc5, n.pixels, n.width, n.height,
                                             {level, core::best_simd_level()});
            const auto decoded = decode_image(BlockFormat::Bc5, blocks, n.width, n.height);
            pooled += squared_error(n.pixels, decoded, kChannelsRg);
            const AngleError a = normal_angle_error(n.pixels, decoded);
            angle.sum_degrees += a.sum_degrees, angle.texels += a.texels;
        }
        std::printf("BC5 level %d: %.3f dB, %.3f deg\n", level, pooled.psnr(), angle.mean());
        EXPECT_GE(pooled.psnr(), psnr_floor[level]);
        EXPECT_LT(angle.mean(), 1.5);
    }
}

TEST(EncoderQuality, EveryKernelMeetsTheFloorOfLevelOne) {
    // The scalar, AVX2 and AVX-512 builds of the kernels must all be real encoders
    // (a level the CPU lacks falls back to the best it has).
    const auto samples = bc7_samples();
    for (core::SimdLevel simd :
         {core::SimdLevel::Scalar, core::SimdLevel::Avx2, core::SimdLevel::Avx512}) {
        SquaredError pooled;
        for (const Sample& s : samples)
            pooled += encode_error(BlockFormat::Bc7, s.image, 1, s.channels, simd);
        EXPECT_GE(pooled.psnr(), 40.0) << to_string(simd);
    }
}

TEST(EncoderEdgeCases, TinyAndOddSizesDecodeToTheirOwnSize) {
    for (auto [w, h] : {std::pair{1u, 1u}, {2u, 3u}, {5u, 3u}, {7u, 9u}, {4u, 13u}}) {
        RgbaImage img{w, h, {}}; // a smooth gradient with partial alpha
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x)
                img.pixels.insert(img.pixels.end(),
                                  {std::uint8_t(x * 255 / w), std::uint8_t(y * 255 / h), 128, 200});
        for (BlockFormat f : {BlockFormat::Bc7, BlockFormat::Bc5}) {
            const auto blocks = encode_image(f, img.pixels, w, h, {1, core::best_simd_level()});
            ASSERT_EQ(blocks.size(), compressed_size(w, h));
            const auto decoded = decode_image(f, blocks, w, h);
            ASSERT_EQ(decoded.size(), img.pixels.size());
            // The padding is the edge texels replicated: encoding the explicitly
            // padded image must give the same texels inside the original area.
            const std::uint32_t pw = blocks_along(w) * 4, ph = blocks_along(h) * 4;
            RgbaImage padded{pw, ph, std::vector<std::uint8_t>(std::size_t{pw} * ph * 4)};
            for (std::uint32_t y = 0; y < ph; ++y)
                for (std::uint32_t x = 0; x < pw; ++x)
                    std::copy_n(&img.pixels[(std::min(y, h - 1) * w + std::min(x, w - 1)) * 4], 4,
                                &padded.pixels[(y * pw + x) * 4]);
            const auto padded_decoded = decode_image(
                f, encode_image(f, padded.pixels, pw, ph, {1, core::best_simd_level()}), pw, ph);
            for (std::uint32_t y = 0; y < h; ++y)
                for (std::uint32_t x = 0; x < w; ++x)
                    for (int c = 0; c < 4; ++c)
                        ASSERT_EQ(decoded[(y * w + x) * 4 + c],
                                  padded_decoded[(y * pw + x) * 4 + c]);
            // Tiny 2-D gradients are hard for one block; this only catches garbage.
            const double psnr = squared_error(img.pixels, decoded,
                                              f == BlockFormat::Bc7 ? kChannelsRgba : kChannelsRg)
                                    .psnr();
            EXPECT_GT(psnr, 22.0) << w << "x" << h;
        }
    }
    const RgbaImage one = test::constant_image(1, 1, 12, 200, 99, 255);
    for (int level = kBc7MinLevel; level <= kBc7MaxLevel; ++level) {
        const auto blocks =
            encode_image(BlockFormat::Bc7, one.pixels, 1, 1, {level, core::best_simd_level()});
        EXPECT_LE(
            max_abs_diff(decode_image(BlockFormat::Bc7, blocks, 1, 1), one.pixels, kChannelsRgba),
            1);
    }
}

TEST(EncoderEdgeCases, ConstantBlocksStayWithinOneStep) {
    std::uint32_t state = 12345;
    auto next = [&] {
        return static_cast<std::uint8_t>((state = state * 1103515245u + 12345u) >> 23);
    };
    for (int trial = 0; trial < 40; ++trial) {
        const std::uint8_t a = trial % 2 ? 255 : next();
        const RgbaImage block = test::constant_image(4, 4, next(), next(), next(), a);
        for (int level = kBc7MinLevel; level <= kBc7MaxLevel; ++level) {
            const auto bc7 = encode_image(BlockFormat::Bc7, block.pixels, 4, 4,
                                          {level, core::best_simd_level()});
            EXPECT_LE(max_abs_diff(decode_image(BlockFormat::Bc7, bc7, 4, 4), block.pixels,
                                   kChannelsRgba),
                      1)
                << "level " << level << " trial " << trial;
        }
        const auto bc5 =
            encode_image(BlockFormat::Bc5, block.pixels, 4, 4, {1, core::best_simd_level()});
        EXPECT_EQ(
            max_abs_diff(decode_image(BlockFormat::Bc5, bc5, 4, 4), block.pixels, kChannelsRg), 0);
    }
}

TEST(EncoderEdgeCases, OpaqueStaysOpaqueAndAlphaIsKept) {
    const RgbaImage opaque = test::synthetic_image(32, 32, false, 9);
    const RgbaImage cutout = test::load_crop(
        test::assets_dir() / "textures/sponza/16275776544635328252.png", 500, 500, 64, 64);
    for (int level = kBc7MinLevel; level <= kBc7MaxLevel; ++level) {
        const auto o = decode_image(
            BlockFormat::Bc7,
            encode_image(BlockFormat::Bc7, opaque.pixels, 32, 32, {level, core::best_simd_level()}),
            32, 32);
        for (std::size_t i = 3; i < o.size(); i += 4) ASSERT_EQ(o[i], 255) << "level " << level;
        const SquaredError alpha = encode_error(BlockFormat::Bc7, cutout, level, 0b1000);
        EXPECT_GT(alpha.psnr(), 35.0) << "alpha channel, level " << level;
    }
}
