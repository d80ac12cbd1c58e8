// A/B comparison offscreen (sherpa/render/comparison.h, render_comparison), on
// lavapipe under the validation layer: the composited image against the two sides
// rendered alone, the GPU statistics against the same numbers computed on the CPU
// from those single renders, the heat colours against heat_colour(), degenerate input.
#include "comparison_test_support.h"

namespace sherpa::test {
namespace {

TEST(HeatColour, EndpointsAndStops) {
    using C = std::array<std::uint8_t, 3>;
    EXPECT_EQ(render::heat_colour(0.0), (C{0, 0, 0}));
    EXPECT_EQ(render::heat_colour(0.25), (C{0, 0, 255}));
    EXPECT_EQ(render::heat_colour(0.5), (C{255, 0, 0}));
    EXPECT_EQ(render::heat_colour(0.75), (C{255, 255, 0}));
    EXPECT_EQ(render::heat_colour(1.0), (C{255, 255, 255}));
    EXPECT_EQ(render::heat_colour(-3.0), (C{0, 0, 0}));
    EXPECT_EQ(render::heat_colour(7.0), (C{255, 255, 255}));
    EXPECT_EQ(render::heat_colour(NAN), (C{0, 0, 0}));
    EXPECT_EQ(render::parse_compare_mode("split"), render::CompareMode::Split);
    EXPECT_EQ(render::parse_compare_mode(to_string(render::CompareMode::Difference)),
              render::CompareMode::Difference);
    EXPECT_FALSE(render::parse_compare_mode("blend"));
}

// Split: side A's own pixels left of the divider, B's right of it, the divider line
// (two pixels) between; both sides are raster frames of two renderers of one scene.
TEST_F(ComparisonTest, SplitShowsSideALeftAndSideBRight) {
    auto scene = load(gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    auto a = make_renderer(*scene), b = make_renderer(*scene);
    const render::FrameRequest sa = small_settings(*scene, render::DebugView::Lit);
    const render::FrameRequest sb = small_settings(*scene, render::DebugView::Normal);
    std::vector<std::uint8_t> alone_a, alone_b, split;
    a->render(sa, &alone_a);
    b->render(sb, &alone_b);
    ASSERT_GT(differing_pixels(alone_a, alone_b, 8), 500u) << "the sides must differ";
    render::ComparisonSettings c;
    c.mode = render::CompareMode::Split;
    c.divider = 0.25f; // x = 24: pixels 23 and 24 are the line
    const render::ComparisonStats stats = render::render_comparison(*a, sa, *b, sb, c, &split);
    ASSERT_EQ(split.size(), alone_a.size());
    std::size_t wrong = 0, line = 0;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x) {
            const std::size_t p = 4 * (std::size_t(y) * kW + x);
            const auto& want = x < 23 ? alone_a : alone_b;
            if (x == 23 || x == 24) {
                line += split[p] == 255 && split[p + 1] == 200 && split[p + 2] == 40;
                continue;
            }
            for (int k = 0; k < 3; ++k) wrong += split[p + k] != want[p + k];
        }
    EXPECT_EQ(wrong, 0u);
    EXPECT_EQ(line, 2u * kH);
    // Split frames still carry the difference statistics of the whole image.
    const CpuStats cpu = cpu_stats(alone_a, alone_b, 2);
    EXPECT_TRUE(stats.valid);
    EXPECT_NEAR(stats.mean, cpu.mean, 1e-9);
    EXPECT_DOUBLE_EQ(stats.max, cpu.max);
}

TEST_F(ComparisonTest, DifferenceOfASceneWithItselfIsBlack) {
    auto scene = load(gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    auto a = make_renderer(*scene), b = make_renderer(*scene);
    const render::FrameRequest s = small_settings(*scene, render::DebugView::Lit);
    render::ComparisonSettings c;
    c.mode = render::CompareMode::Difference;
    c.heat_max = 0.0f; // automatic: statistics first, composite in a second submission
    std::vector<std::uint8_t> image;
    const render::ComparisonStats stats = render::render_comparison(*a, s, *b, s, c, &image);
    if (context().info().timestamps) {
        EXPECT_GT(stats.composite_ms, 0.0);
    }
    ASSERT_TRUE(stats.valid);
    EXPECT_EQ(stats.pixels, std::uint64_t(kW) * kH);
    EXPECT_EQ(stats.mean, 0.0);
    EXPECT_EQ(stats.max, 0.0);
    EXPECT_EQ(stats.over_threshold_percent, 0.0);
    EXPECT_TRUE(std::isinf(stats.psnr_db));
    EXPECT_EQ(stats.histogram[0], stats.pixels);
    std::size_t lit = 0;
    for (std::size_t i = 0; i < image.size(); i += 4)
        lit += image[i] || image[i + 1] || image[i + 2];
    EXPECT_EQ(lit, 0u);
}

// Raster against rays on a textured model without a common mip level (the
// rasterizer's derivative LOD against the rays' level 0): the GPU statistics match
// the CPU's from the two single renders, and every heat pixel is heat_colour() of
// that pixel's difference.
TEST_F(ComparisonTest, RasterAgainstRaysMatchesCpuStatisticsAndHeatColours) {
    if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    auto scene = load(gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    RasterAndRays r = raster_and_rays(*scene, *scene, render::DebugView::BaseColor);
    std::vector<std::uint8_t> heat;
    const CpuStats cpu = cpu_stats(r.alone_a, r.alone_b, 2);
    ASSERT_GT(cpu.max, 0.0) << "the test needs a difference";
    render::ComparisonSettings c;
    c.mode = render::CompareMode::Difference;
    c.heat_max = 24.0f / 255;
    const render::ComparisonStats stats =
        render::render_comparison(*r.a, r.sa, *r.b, r.sb, c, &heat);
    std::printf("raster vs rays: mean %.5f max %.4f psnr %.2f dB over %.2f%% (CPU: %.5f %.4f "
                "%.2f %.2f%%)\n",
                stats.mean, stats.max, stats.psnr_db, stats.over_threshold_percent, cpu.mean,
                cpu.max, cpu.psnr, cpu.over_percent);
    EXPECT_NEAR(stats.mean, cpu.mean, 1.0 / 255);
    EXPECT_NEAR(stats.max, cpu.max, 1.0 / 255);
    EXPECT_NEAR(stats.psnr_db, cpu.psnr, 0.05);
    EXPECT_NEAR(stats.over_threshold_percent, cpu.over_percent, 100.0 / (kW * kH) + 1e-9);
    if (context().info().timestamps) {
        EXPECT_GT(stats.reduce_ms, 0.0);
        EXPECT_GT(stats.composite_ms, 0.0);
    }
    EXPECT_EQ(heat_mismatches(heat, cpu, 24.0), 0u);
}

// A known difference: two empty scenes whose clear colours differ by a known byte
// amount in red only; the heat colour at each heat scale is heat_colour()'s.
TEST_F(ComparisonTest, ShaderHeatAgreesWithHeatColour) {
    scene::Scene empty;
    auto a = make_renderer(empty), b = make_renderer(empty);
    render::FrameRequest sa;
    sa.width = 8;
    sa.height = 4;
    sa.shadows = false;
    render::FrameRequest sb = sa;
    sa.clear_color = {0.0f, 0.0f, 0.0f, 1.0f};
    std::vector<std::uint8_t> alone;
    for (float red : {0.002f, 0.01f, 0.05f, 0.2f, 1.0f}) {
        sb.clear_color = {red, 0.0f, 0.0f, 1.0f};
        b->render(sb, &alone);
        const int d = alone[0]; // A is black: the difference is B's red byte
        for (float heat_max : {8.0f, 64.0f, 255.0f}) {
            render::ComparisonSettings c;
            c.mode = render::CompareMode::Difference;
            c.heat_max = heat_max / 255.0f;
            std::vector<std::uint8_t> heat;
            const render::ComparisonStats s = render::render_comparison(*a, sa, *b, sb, c, &heat);
            const auto want = render::heat_colour(d / double(heat_max));
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(heat[k], want[k], 1) << "d " << d << " heat_max " << heat_max;
            EXPECT_DOUBLE_EQ(s.max, d / 255.0);
            EXPECT_EQ(s.histogram[std::size_t(d)], 32u);
        }
    }
}

// Degenerate input: one-pixel and odd sizes (a row shorter than one reduction run),
// dividers outside the image or NaN, threshold 0, an empty side B; and a side the
// ray tracer refuses fails with its message before anything is recorded.
TEST_F(ComparisonTest, DegenerateSizesDividersAndSidesNeitherCrashNorLie) {
    auto scene = load(gltf_asset("Box"));
    ASSERT_TRUE(scene);
    scene::Scene empty;
    auto a = make_renderer(*scene), b = make_renderer(empty);
    for (auto [w, h] : {std::pair{1u, 1u}, std::pair{3u, 1u}, std::pair{17u, 5u}}) {
        render::FrameRequest sa = small_settings(*scene, render::DebugView::Normal);
        sa.width = w;
        sa.height = h;
        std::vector<std::uint8_t> alone_a, alone_b, image;
        a->render(sa, &alone_a);
        b->render(sa, &alone_b);
        for (float divider : {-1.0f, 0.0f, 1.0f, 2.0f, NAN}) {
            render::ComparisonSettings c;
            c.divider = divider;
            c.threshold = 0.0f;
            const render::ComparisonStats s = render::render_comparison(*a, sa, *b, sa, c, &image);
            ASSERT_EQ(image.size(), std::size_t(w) * h * 4);
            const CpuStats cpu = cpu_stats(alone_a, alone_b, 0);
            EXPECT_EQ(s.pixels, std::uint64_t(w) * h);
            EXPECT_NEAR(s.mean, cpu.mean, 1e-9) << w << "x" << h;
            EXPECT_NEAR(s.over_threshold_percent, cpu.over_percent, 1e-9);
        }
    }
    // A ray-traced side of a morphed file draws its pose (SimpleMorph's default weights
    // 0.5), as the rasterizer does: a bind-pose side would differ along the moved edge.
    auto morph = load(gltf_asset("SimpleMorph"));
    ASSERT_TRUE(morph);
    if (!context().info().ray_tracing_enabled) return;
    auto raster = make_renderer(*morph), rays = make_renderer(*morph, true);
    const render::FrameRequest sm = small_settings(*morph, render::DebugView::Normal);
    render::FrameRequest sr = sm;
    sr.renderer = render::RendererKind::RayTraced;
    render::ComparisonSettings c;
    c.mode = render::CompareMode::Difference;
    const render::ComparisonStats s = render::render_comparison(*raster, sm, *rays, sr, c);
    EXPECT_TRUE(s.valid);
    EXPECT_LT(s.over_threshold_percent, 0.5) << "raster and rays of the default pose";
}

} // namespace
} // namespace sherpa::test
