// Base colour keeps its stored (unassociated) RGB where alpha < 1: the texels the
// texture pipeline makes for AlphaBlendModeTest's label atlas, decoded from BC7,
// against the PNG decoded by libpng (not by OpenImageIO, which Sherpa reads with).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/quality.h>
#include <sherpa/texture/texture_pipeline.h>

#include "reference/reference_images.h"
#include "test_images.h"

using namespace sherpa;

namespace {

const std::filesystem::path kLabels =
    test::assets_dir() / "gltf/AlphaBlendModeTest/glTF/AlphaBlendLabels.png";

struct Prepared {
    tex::PreparedTextureSet set;
    const tex::PreparedTexture* labels = nullptr;
};

Prepared prepare_alpha_blend_mode_test(bool bc) {
    const scene::LoadResult r = scene::load_scene(
        (test::assets_dir() / "gltf/AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf").string());
    EXPECT_TRUE(r) << r.error;
    Prepared p;
    if (!r) return p;
    tex::PipelineOptions options; // no cache: the texels come from this run's decoding
    options.device_supports_bc = bc;
    p.set = tex::prepare_textures(*r.scene, options);
    for (const tex::PreparedTexture& t : p.set.textures)
        if (t.source == "AlphaBlendLabels.png" && t.role == scene::kRoleColor) p.labels = &t;
    return p;
}

// Level 0 of `t` as RGBA8.
std::vector<std::uint8_t> level0_rgba(const tex::PreparedTexture& t) {
    if (!tex::is_block_compressed(t.format)) return t.levels.at(0);
    return tex::decode_image(tex::BlockFormat::Bc7, t.levels.at(0), t.width, t.height);
}

struct RgbDifference {
    double mean = 0; // mean |difference| per channel over translucent texels
    int max = 0;     // largest |difference|
    std::size_t texels = 0;
};

// RGB difference over texels whose reference alpha is in [16, 254]: where
// premultiplied storage would darken the colour, and alpha is large enough that an
// encoder has a reason to keep the colour.
RgbDifference translucent_rgb_difference(const std::vector<std::uint8_t>& ours,
                                         const test::ReferenceImage& ref) {
    RgbDifference d;
    double sum = 0;
    for (std::size_t i = 0; i + 3 < ref.rgba.size(); i += 4) {
        const int a = ref.rgba[i + 3];
        if (a < 16 || a == 255) continue;
        ++d.texels;
        for (int c = 0; c < 3; ++c) {
            const int diff = std::abs(int(ours[i + c]) - int(ref.rgba[i + c]));
            sum += diff;
            d.max = std::max(d.max, diff);
        }
    }
    d.mean = d.texels ? sum / (3.0 * double(d.texels)) : 0.0;
    return d;
}

} // namespace

// The label atlas read by libpng, and Sherpa's level 0 of it (BC7 or RGBA8).
class UnassociatedAlpha : public ::testing::Test {
protected:
    void prepare(bool bc) {
        std::string error;
        ASSERT_TRUE(test::read_png_reference(kLabels, ref, error)) << error;
        p = prepare_alpha_blend_mode_test(bc);
        ASSERT_NE(p.labels, nullptr);
        ASSERT_EQ(p.labels->width, ref.width);
        ASSERT_EQ(p.labels->height, ref.height);
        ours = level0_rgba(*p.labels);
        d = translucent_rgb_difference(ours, ref);
        // The atlas is mostly translucent: the test must look at many texels.
        EXPECT_GT(d.texels, 10000u);
    }
    test::ReferenceImage ref;
    Prepared p;
    std::vector<std::uint8_t> ours;
    RgbDifference d;
};

TEST_F(UnassociatedAlpha, RgbaFallbackStoresThePngsUnassociatedTexelsExactly) {
    ASSERT_NO_FATAL_FAILURE(prepare(false));
    EXPECT_EQ(d.max, 0) << "mean " << d.mean << " over " << d.texels << " texels";
    EXPECT_TRUE(ours == ref.rgba) << "RGBA8 level 0 differs from libpng's decoding";
}

TEST_F(UnassociatedAlpha, Bc7TexelsMatchThePngWithinBc7Error) {
    ASSERT_NO_FATAL_FAILURE(prepare(true));
    ASSERT_EQ(p.labels->format, tex::VkFormat::Bc7SrgbBlock);
    // BC7's error over these texels is a fraction of a level on average (measured
    // 0.33); premultiplied storage differs by ~80 levels on average.
    EXPECT_LT(d.mean, 3.0) << "max " << d.max << " over " << d.texels << " texels";
    std::printf("translucent texels %zu: mean |RGB difference| %.3f, max %d, PSNR %.2f dB\n",
                d.texels, d.mean, d.max, p.labels->psnr.value_or(0.0));
    // The PSNR the pipeline reports is against the file's own texels.
    ASSERT_TRUE(p.labels->psnr.has_value());
    const double psnr = tex::squared_error(ref.rgba, ours, tex::kChannelsRgba).psnr();
    EXPECT_NEAR(*p.labels->psnr, psnr, 0.01);
}
