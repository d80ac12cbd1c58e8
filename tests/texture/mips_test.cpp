// Mip chains: sRGB-correct filtering against a reference computed in linear
// space, renormalised normals, preserved alpha coverage, odd sizes down to 1x1.
#include <gtest/gtest.h>

#include <cmath>

#include <sherpa/texture/mips.h>

#include "test_images.h"

using namespace sherpa;
using namespace sherpa::tex;

namespace {
// Reference sRGB decode/encode in double precision, independent of the code under test.
double ref_to_linear(int v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
int ref_to_srgb(double l) {
    const double c = l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}
} // namespace

TEST(Mips, BlackWhiteCheckerAveragesInLinearLight) {
    const RgbaImage checker{
        2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255}};
    const auto chain = build_mip_chain(checker, {MipFilter::Color, {}});
    ASSERT_EQ(chain.size(), 2u);
    // Linear 0.5 encodes to sRGB 188, not the 128 a gamma-naive average gives.
    EXPECT_EQ(chain[1].pixels[0], 188);
    const auto naive = build_mip_chain(checker, {MipFilter::Linear, {}});
    EXPECT_EQ(naive[1].pixels[0], 128);
}

TEST(Mips, ColourLevelOneMatchesLinearSpaceReference) {
    const RgbaImage img = test::synthetic_image(64, 48, false, 7);
    const auto chain = build_mip_chain(img, {MipFilter::Color, {}});
    const RgbaImage& l1 = chain[1];
    ASSERT_EQ(l1.width, 32u);
    ASSERT_EQ(l1.height, 24u);
    int worst = 0;
    for (std::uint32_t y = 0; y < l1.height; ++y)
        for (std::uint32_t x = 0; x < l1.width; ++x)
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx)
                        sum += ref_to_linear(
                            img.pixels[((2 * y + dy) * img.width + 2 * x + dx) * 4 + c]);
                const int expected = ref_to_srgb(sum / 4);
                worst = std::max(worst,
                                 std::abs(expected - int(l1.pixels[(y * l1.width + x) * 4 + c])));
            }
    EXPECT_LE(worst, 1);
}

TEST(Mips, OddSizesReachOneByOneWithFullChain) {
    for (auto [w, h] : {std::pair{1u, 1u}, {5u, 3u}, {7u, 1u}, {129u, 66u}}) {
        const auto chain =
            build_mip_chain(test::synthetic_image(w, h, true, 3), {MipFilter::Color, {}});
        ASSERT_EQ(chain.size(), full_mip_count(w, h));
        EXPECT_EQ(chain.back().width, 1u);
        EXPECT_EQ(chain.back().height, 1u);
        for (std::size_t l = 1; l < chain.size(); ++l) {
            EXPECT_EQ(chain[l].width, std::max(1u, chain[l - 1].width / 2));
            EXPECT_EQ(chain[l].pixels.size(), std::size_t{chain[l].width} * chain[l].height * 4);
        }
    }
    // A constant image stays exactly constant on every level, odd footprints included.
    const auto flat =
        build_mip_chain(test::constant_image(13, 7, 200, 100, 50, 77), {MipFilter::Color, {}});
    for (const auto& level : flat)
        for (std::size_t i = 0; i < level.pixels.size(); i += 4) {
            ASSERT_EQ(level.pixels[i], 200);
            ASSERT_EQ(level.pixels[i + 1], 100);
            ASSERT_EQ(level.pixels[i + 2], 50);
            ASSERT_EQ(level.pixels[i + 3], 77);
        }
}

TEST(Mips, TransparentTexelsDoNotBleedColour) {
    // Opaque red next to fully transparent green: the average must stay red.
    const RgbaImage img{2, 1, {255, 0, 0, 255, 0, 255, 0, 0}};
    const auto chain = build_mip_chain(img, {MipFilter::Color, {}});
    EXPECT_EQ(chain[1].pixels[0], 255);
    EXPECT_EQ(chain[1].pixels[1], 0);
    EXPECT_EQ(chain[1].pixels[3], 128);
}

TEST(Mips, NormalsAreRenormalised) {
    const RgbaImage normals = test::load_crop(
        test::assets_dir() / "gltf/DamagedHelmet/glTF/Default_normal.jpg", 512, 512, 64, 64);
    const auto chain = build_mip_chain(normals, {MipFilter::Normal, {}});
    for (std::size_t l = 1; l < chain.size(); ++l)
        for (std::size_t i = 0; i < chain[l].pixels.size(); i += 4) {
            double len2 = 0;
            for (int c = 0; c < 3; ++c) {
                const double v = chain[l].pixels[i + c] / 127.5 - 1.0;
                len2 += v * v;
            }
            // 8-bit quantisation of a unit vector keeps its length within ~1%.
            ASSERT_NEAR(std::sqrt(len2), 1.0, 0.015) << "level " << l;
        }
}

TEST(Mips, AlphaCoverageIsPreservedForMaskedTextures) {
    const RgbaImage leaves = test::load_crop(
        test::assets_dir() / "textures/sponza/16275776544635328252.png", 256, 256, 256, 256);
    const float cutoff = 0.5f;
    const double base = alpha_coverage(leaves, cutoff);
    ASSERT_GT(base, 0.05);
    ASSERT_LT(base, 0.95);
    const auto kept = build_mip_chain(leaves, {MipFilter::Color, cutoff});
    const auto plain = build_mip_chain(leaves, {MipFilter::Color, {}});
    double plain_drift = 0, kept_drift = 0;
    for (std::size_t l = 1; l + 3 < kept.size(); ++l) { // tiny levels have too few texels to match
        kept_drift = std::max(kept_drift, std::abs(alpha_coverage(kept[l], cutoff) - base));
        plain_drift = std::max(plain_drift, std::abs(alpha_coverage(plain[l], cutoff) - base));
    }
    EXPECT_LT(kept_drift, 0.02);
    EXPECT_GT(plain_drift, kept_drift);
}
