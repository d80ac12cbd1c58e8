// tex::decode_level_rgba8: a prepared level as the GPU samples it (thumbnails).
// BC5 normals come back with z rebuilt; checked against the unit normals the
// level was encoded from, not against our own formula.
#include <gtest/gtest.h>

#include <cmath>
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/prepared_levels.h>

namespace sherpa::tex {
namespace {

constexpr std::uint32_t kSize = 16;

// Unit normals leaning up to ~45° in x and y across the image, stored as 8-bit
// 0.5 + 0.5·n, and their z.
std::vector<std::uint8_t> normal_map(std::vector<float>& z) {
    std::vector<std::uint8_t> rgba(kSize * kSize * 4);
    z.assign(kSize * kSize, 0.0f);
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            const float nx = (x / float(kSize - 1) - 0.5f) * 1.4f;
            const float ny = (y / float(kSize - 1) - 0.5f) * 1.4f;
            const float len = std::sqrt(nx * nx + ny * ny + 1.0f);
            const std::size_t i = y * kSize + x;
            z[i] = 1.0f / len;
            rgba[4 * i + 0] = static_cast<std::uint8_t>(std::lround((nx / len + 1.0f) * 127.5f));
            rgba[4 * i + 1] = static_cast<std::uint8_t>(std::lround((ny / len + 1.0f) * 127.5f));
            rgba[4 * i + 2] = static_cast<std::uint8_t>(std::lround((z[i] + 1.0f) * 127.5f));
            rgba[4 * i + 3] = 255;
        }
    return rgba;
}

PreparedTexture prepared(VkFormat format, std::vector<std::uint8_t> level0) {
    PreparedTexture p;
    p.format = format;
    p.width = p.height = kSize;
    p.levels.push_back(std::move(level0));
    return p;
}

TEST(PreparedLevels, Bc5LevelDecodesWithTheNormalsZRebuilt) {
    std::vector<float> z;
    const std::vector<std::uint8_t> source = normal_map(z);
    const PreparedTexture p =
        prepared(VkFormat::Bc5UnormBlock, encode_image(BlockFormat::Bc5, source, kSize, kSize, {}));
    const std::vector<std::uint8_t> rgba = decode_level_rgba8(p, 0);
    ASSERT_EQ(rgba.size(), source.size());
    for (std::size_t i = 0; i < z.size(); ++i) {
        // BC5 keeps x and y to a few 8-bit steps; z follows from them.
        const float decoded = rgba[4 * i + 2] / 127.5f - 1.0f;
        EXPECT_NEAR(decoded, z[i], 0.05f) << "texel " << i;
    }
}

TEST(PreparedLevels, Bc7LevelIsItsBlockDecodeAndRgba8IsAsStored) {
    std::vector<float> z;
    const std::vector<std::uint8_t> source = normal_map(z);
    const std::vector<std::uint8_t> blocks =
        encode_image(BlockFormat::Bc7, source, kSize, kSize, {});
    EXPECT_EQ(decode_level_rgba8(prepared(VkFormat::Bc7SrgbBlock, blocks), 0),
              decode_image(BlockFormat::Bc7, blocks, kSize, kSize));
    EXPECT_EQ(decode_level_rgba8(prepared(VkFormat::R8G8B8A8Unorm, source), 0), source);
}

TEST(PreparedLevels, MissingFailedOrWrongSizedLevelsGiveNothing) {
    std::vector<float> z;
    std::vector<std::uint8_t> blocks =
        encode_image(BlockFormat::Bc5, normal_map(z), kSize, kSize, {});
    EXPECT_TRUE(decode_level_rgba8(prepared(VkFormat::Bc5UnormBlock, blocks), 1).empty());
    PreparedTexture failed = prepared(VkFormat::Bc5UnormBlock, blocks);
    failed.failed = true;
    EXPECT_TRUE(decode_level_rgba8(failed, 0).empty());
    blocks.resize(blocks.size() / 2);
    EXPECT_TRUE(decode_level_rgba8(prepared(VkFormat::Bc5UnormBlock, blocks), 0).empty());
}

} // namespace
} // namespace sherpa::tex
