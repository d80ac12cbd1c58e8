// Presented frames of the viewport's raster / RT / split / difference switch, driven
// the way the Presenter drives a FrameSource (wait_for_slot, record, submit with its
// extra signals, submitted) into an image of the test's, on lavapipe under the
// validation layer: a ray-traced PresentedFrame, a ComparisonFrame of two renderers.
#include "comparison_test_support.h"

namespace sherpa::test {
namespace {

// The viewport's RT switch: a presented ray-traced frame is the offscreen RT image,
// on RGBA and BGRA (swapchain-like) targets, sRGB or UNORM; refusals come before
// recording.
TEST_F(ComparisonTest, PresentedRayTracedFrameIsTheOffscreenImage) {
    if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    auto scene = load(gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    auto r = make_renderer(*scene, true);
    render::FrameRequest s = small_settings(*scene, render::DebugView::Normal);
    s.renderer = render::RendererKind::RayTraced;
    std::vector<std::uint8_t> offscreen;
    r->render(s, &offscreen);
    for (VkFormat format :
         {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM}) {
        render::PresentedFrame frame(*r, s);
        const auto shown = present_offscreen(context(), r->resources(), frame, format);
        EXPECT_EQ(differing_pixels(shown, offscreen, 0, 3), 0u) << format;
        ASSERT_FALSE(frame.completed_stats().passes.empty());
        EXPECT_EQ(frame.completed_stats().passes[0].name, "rays");
        if (context().info().timestamps) {
            ASSERT_EQ(frame.completed_stats().passes.size(), 2u);
            EXPECT_EQ(frame.completed_stats().passes[1].name, "composite");
        }
    }
    // Half resolution: every pixel is one of the reduced image's, scaled up nearest.
    render::PresentedFrame half(*r, s, 0.5f);
    const auto shown = present_offscreen(context(), r->resources(), half, VK_FORMAT_R8G8B8A8_SRGB);
    render::FrameRequest small = s;
    small.width = kW / 2;
    small.height = kH / 2;
    std::vector<std::uint8_t> reduced;
    r->render(small, &reduced);
    std::size_t wrong = 0;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x)
            for (int k = 0; k < 3; ++k)
                wrong +=
                    shown[4 * (y * kW + x) + k] != reduced[4 * ((y / 2) * (kW / 2) + x / 2) + k];
    EXPECT_EQ(wrong, 0u);

    // A view the ray tracer does not draw: refused, by the presented frame as by render().
    s.view = render::DebugView::Uv0Checker;
    std::string offscreen_error, presented_error;
    try {
        r->render(s);
    } catch (const gpu::GpuError& e) {
        offscreen_error = e.what();
    }
    try {
        render::PresentedFrame refused(*r, s);
    } catch (const gpu::GpuError& e) {
        presented_error = e.what();
    }
    EXPECT_FALSE(offscreen_error.empty());
    EXPECT_EQ(presented_error, offscreen_error);
}

// Two renderers on one context, each with its own scene, drawn into one presented
// comparison frame (b's timeline signalled by the frame's submission), raster against
// rays, with the stats of the completed frames; then each renderer alone again.
TEST_F(ComparisonTest, PresentedComparisonOfTwoRenderersOnOneContext) {
    if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    auto box = load(gltf_asset("BoxTextured"));
    auto plain = load(gltf_asset("Box"));
    ASSERT_TRUE(box && plain);
    RasterAndRays r = raster_and_rays(*box, *plain, render::DebugView::Normal);
    auto& [a, b, sa, sb, alone_a, alone_b] = r;
    render::ComparisonSettings c;
    c.mode = render::CompareMode::Difference;
    render::ComparisonFrame frame(*a, sa, *b, sb, c);
    const auto composited =
        present_offscreen(context(), a->resources(), frame, VK_FORMAT_B8G8R8A8_SRGB, 4);
    const CpuStats cpu = cpu_stats(alone_a, alone_b, 2);
    const render::ComparisonStats& stats = frame.completed_comparison();
    ASSERT_TRUE(stats.valid);
    EXPECT_NEAR(stats.mean, cpu.mean, 1e-9);
    EXPECT_NEAR(stats.psnr_db, cpu.psnr, 1e-6);
    EXPECT_FALSE(frame.completed_stats_a().passes.empty());
    ASSERT_FALSE(frame.completed_stats_b().passes.empty());
    EXPECT_EQ(frame.completed_stats_b().passes[0].name, "rays");
    EXPECT_EQ(heat_mismatches(composited, cpu, 16.0), 0u);
    std::vector<std::uint8_t> again_a, again_b;
    a->render(sa, &again_a);
    b->render(sb, &again_b);
    EXPECT_EQ(again_a, alone_a);
    EXPECT_EQ(again_b, alone_b);
    EXPECT_THROW(render::ComparisonFrame(*a, sa, *a, sa, c), gpu::GpuError);
}

} // namespace
} // namespace sherpa::test
