// A/B comparison (sherpa/render/comparison.h) and presented ray-traced frames, on
// lavapipe under the validation layer: the composited image against the two sides
// rendered alone, the GPU statistics against the same numbers computed on the CPU
// from those single renders, the heat colours against heat_colour(), and frame
// sources driven the way the Presenter drives them, into an image of the test's.
#include "gpu_test_support.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>
#include <sherpa/render/comparison.h>
#include <sherpa/render/presented_frame.h>
#include <sherpa/scene/framing.h>

#include <cmath>
#include <cstring>

namespace sherpa::test {
namespace {

constexpr std::uint32_t kW = 96, kH = 72;

// The statistics of comparison.h computed on the CPU from two RGBA8 images.
struct CpuStats {
    double mean = 0, max = 0, psnr = 0, over_percent = 0;
    std::vector<int> d; // per pixel: largest byte difference over R, G, B
};

CpuStats cpu_stats(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                   int threshold_bytes) {
    CpuStats s;
    const std::size_t n = a.size() / 4;
    double sum = 0, squared = 0;
    std::size_t over = 0;
    for (std::size_t p = 0; p < n; ++p) {
        int m = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(a[4 * p + c]) - int(b[4 * p + c]));
            m = std::max(m, d);
            squared += double(d) * d;
        }
        s.d.push_back(m);
        sum += m;
        s.max = std::max(s.max, m / 255.0);
        over += m > threshold_bytes;
    }
    s.mean = sum / 255.0 / double(n);
    s.over_percent = 100.0 * double(over) / double(n);
    s.psnr = squared == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 * 3.0 * double(n) / squared);
    return s;
}

gpu::RenderSettings small_settings(const Scene& scene, gpu::DebugView view) {
    gpu::RenderSettings s;
    s.width = kW;
    s.height = kH;
    s.shadows = false;
    s.view = view;
    FramingOptions framing;
    framing.aspect = float(kW) / float(kH);
    s.camera = gpu::explicit_camera(frame_box(scene.bounds, framing));
    return s;
}

// Drives `source` as the Presenter does (wait_for_slot, record, submit with its extra
// signals, submitted), `frames` times into one image of `format` owned by the test,
// then reads the image back as RGBA rows.
std::vector<std::uint8_t> present_offscreen(gpu::Context& context, gpu::ResourceManager& resources,
                                            gpu::FrameSource& source, VkFormat format,
                                            int frames = 3) {
    gpu::ImageDesc d;
    d.format = format;
    d.width = kW;
    d.height = kH;
    d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
              VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.name = "test target";
    gpu::ImageHandle image = resources.images().create(d);
    gpu::BufferHandle readback =
        resources.create_buffer({VkDeviceSize(kW) * kH * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 gpu::MemoryUsage::Readback, "test readback"});
    const gpu::Image& img = resources.images().get(image);
    std::vector<std::unique_ptr<gpu::CommandRecorder>> recorders;
    for (std::uint32_t i = 0; i < source.frames_in_flight(); ++i)
        recorders.push_back(std::make_unique<gpu::CommandRecorder>(context));
    std::uint64_t last = 0;
    for (int f = 0; f < frames; ++f) {
        const std::uint32_t slot = std::uint32_t(f) % source.frames_in_flight();
        source.wait_for_slot(slot);
        VkCommandBuffer cmd = recorders[slot]->begin();
        const gpu::RenderTarget target{img.image.get(),
                                       img.view.get(),
                                       format,
                                       kW,
                                       kH,
                                       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                       true};
        source.record(cmd, slot, target);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {kW, kH, 1};
        vkCmdCopyImageToBuffer(cmd, img.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               resources.get(readback).buffer.get(), 1, &region);
        gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        const auto signals = source.signals(slot);
        last = recorders[slot]->submit(resources, nullptr, 0, signals.data(),
                                       std::uint32_t(signals.size()));
        source.submitted(slot, last);
    }
    resources.timeline().wait_for(last);
    for (std::uint32_t slot = 0; slot < source.frames_in_flight(); ++slot)
        source.wait_for_slot(slot); // results of the frames in flight
    std::vector<std::uint8_t> rgba(std::size_t(kW) * kH * 4);
    std::memcpy(rgba.data(), resources.get(readback).mapped, rgba.size());
    if (format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_B8G8R8A8_UNORM)
        for (std::size_t i = 0; i < rgba.size(); i += 4) std::swap(rgba[i], rgba[i + 2]);
    resources.images().destroy(image);
    resources.destroy(readback);
    return rgba;
}

class ComparisonTest : public GpuTest {
protected:
    std::unique_ptr<gpu::Renderer> make_renderer(const Scene& scene, bool rt = false) {
        gpu::RendererOptions options;
        options.ray_tracing = rt;
        options.textures = test_texture_settings();
        auto r = std::make_unique<gpu::Renderer>(context(), options);
        r->load(scene, gpu::StreamPolicy::AllPresent);
        return r;
    }
};

TEST(HeatColour, EndpointsAndStops) {
    using C = std::array<std::uint8_t, 3>;
    EXPECT_EQ(gpu::heat_colour(0.0), (C{0, 0, 0}));
    EXPECT_EQ(gpu::heat_colour(0.25), (C{0, 0, 255}));
    EXPECT_EQ(gpu::heat_colour(0.5), (C{255, 0, 0}));
    EXPECT_EQ(gpu::heat_colour(0.75), (C{255, 255, 0}));
    EXPECT_EQ(gpu::heat_colour(1.0), (C{255, 255, 255}));
    EXPECT_EQ(gpu::heat_colour(-3.0), (C{0, 0, 0}));
    EXPECT_EQ(gpu::heat_colour(7.0), (C{255, 255, 255}));
    EXPECT_EQ(gpu::heat_colour(NAN), (C{0, 0, 0}));
    EXPECT_EQ(gpu::parse_compare_mode("split"), gpu::CompareMode::Split);
    EXPECT_EQ(gpu::parse_compare_mode(gpu::to_string(gpu::CompareMode::Difference)),
              gpu::CompareMode::Difference);
    EXPECT_FALSE(gpu::parse_compare_mode("blend"));
}

// Split: side A's own pixels left of the divider, B's right of it, the divider line
// (two pixels) between; both sides are raster frames of two renderers of one scene.
TEST_F(ComparisonTest, SplitShowsSideALeftAndSideBRight) {
    auto scene = load(gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    auto a = make_renderer(*scene), b = make_renderer(*scene);
    const gpu::RenderSettings sa = small_settings(*scene, gpu::DebugView::Lit);
    const gpu::RenderSettings sb = small_settings(*scene, gpu::DebugView::Normal);
    std::vector<std::uint8_t> alone_a, alone_b, split;
    a->render(sa, &alone_a);
    b->render(sb, &alone_b);
    ASSERT_GT(differing_pixels(alone_a, alone_b, 8), 500u) << "the sides must differ";
    gpu::ComparisonSettings c;
    c.mode = gpu::CompareMode::Split;
    c.divider = 0.25f; // x = 24: pixels 23 and 24 are the line
    const gpu::ComparisonStats stats = gpu::render_comparison(*a, sa, *b, sb, c, &split);
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
    const gpu::RenderSettings s = small_settings(*scene, gpu::DebugView::Lit);
    gpu::ComparisonSettings c;
    c.mode = gpu::CompareMode::Difference;
    c.heat_max = 0.0f; // automatic: statistics first, composite in a second submission
    std::vector<std::uint8_t> image;
    const gpu::ComparisonStats stats = gpu::render_comparison(*a, s, *b, s, c, &image);
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
    auto a = make_renderer(*scene), b = make_renderer(*scene, true);
    const gpu::RenderSettings sa = small_settings(*scene, gpu::DebugView::BaseColor);
    gpu::RenderSettings sb = sa;
    sb.renderer = gpu::RendererKind::RayTraced;
    std::vector<std::uint8_t> raster, rays, heat;
    a->render(sa, &raster);
    b->render(sb, &rays);
    const CpuStats cpu = cpu_stats(raster, rays, 2);
    ASSERT_GT(cpu.max, 0.0) << "the test needs a difference";
    gpu::ComparisonSettings c;
    c.mode = gpu::CompareMode::Difference;
    c.heat_max = 24.0f / 255;
    const gpu::ComparisonStats stats = gpu::render_comparison(*a, sa, *b, sb, c, &heat);
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
    std::size_t off = 0;
    for (std::size_t p = 0; p < cpu.d.size(); ++p) {
        const auto want = gpu::heat_colour(cpu.d[p] / 24.0);
        for (int k = 0; k < 3; ++k) off += std::abs(int(heat[4 * p + k]) - int(want[k])) > 1;
    }
    EXPECT_EQ(off, 0u);
}

// A known difference: two empty scenes whose clear colours differ by a known byte
// amount in red only; the heat colour at each heat scale is heat_colour()'s.
TEST_F(ComparisonTest, ShaderHeatAgreesWithHeatColour) {
    Scene empty;
    auto a = make_renderer(empty), b = make_renderer(empty);
    gpu::RenderSettings sa;
    sa.width = 8;
    sa.height = 4;
    sa.shadows = false;
    gpu::RenderSettings sb = sa;
    sa.clear_color = {0.0f, 0.0f, 0.0f, 1.0f};
    std::vector<std::uint8_t> alone;
    for (float red : {0.002f, 0.01f, 0.05f, 0.2f, 1.0f}) {
        sb.clear_color = {red, 0.0f, 0.0f, 1.0f};
        b->render(sb, &alone);
        const int d = alone[0]; // A is black: the difference is B's red byte
        for (float heat_max : {8.0f, 64.0f, 255.0f}) {
            gpu::ComparisonSettings c;
            c.mode = gpu::CompareMode::Difference;
            c.heat_max = heat_max / 255.0f;
            std::vector<std::uint8_t> heat;
            const gpu::ComparisonStats s = gpu::render_comparison(*a, sa, *b, sb, c, &heat);
            const auto want = gpu::heat_colour(d / double(heat_max));
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(heat[k], want[k], 1) << "d " << d << " heat_max " << heat_max;
            EXPECT_DOUBLE_EQ(s.max, d / 255.0);
            EXPECT_EQ(s.histogram[std::size_t(d)], 32u);
        }
    }
}

// The viewport's RT switch: a presented ray-traced frame is the offscreen RT image,
// on an RGBA and a BGRA (swapchain-like) target; refusals come before recording.
TEST_F(ComparisonTest, PresentedRayTracedFrameIsTheOffscreenImage) {
    if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    auto scene = load(gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    auto r = make_renderer(*scene, true);
    gpu::RenderSettings s = small_settings(*scene, gpu::DebugView::Normal);
    s.renderer = gpu::RendererKind::RayTraced;
    std::vector<std::uint8_t> offscreen;
    r->render(s, &offscreen);
    for (VkFormat format : {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB}) {
        gpu::PresentedFrame frame(*r, s);
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
    gpu::PresentedFrame half(*r, s, 0.5f);
    const auto shown = present_offscreen(context(), r->resources(), half, VK_FORMAT_R8G8B8A8_SRGB);
    gpu::RenderSettings small = s;
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

    s.view = gpu::DebugView::Lit; // the ray tracer has no lighting: refused, as render() does
    std::string offscreen_error, presented_error;
    try {
        r->render(s);
    } catch (const gpu::GpuError& e) {
        offscreen_error = e.what();
    }
    try {
        gpu::PresentedFrame refused(*r, s);
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
    auto duck = load(gltf_asset("Box"));
    ASSERT_TRUE(box && duck);
    auto a = make_renderer(*box), b = make_renderer(*duck, true);
    const gpu::RenderSettings sa = small_settings(*box, gpu::DebugView::Normal);
    gpu::RenderSettings sb = sa;
    sb.renderer = gpu::RendererKind::RayTraced;
    std::vector<std::uint8_t> alone_a, alone_b, composited;
    a->render(sa, &alone_a);
    b->render(sb, &alone_b);
    gpu::ComparisonSettings c;
    c.mode = gpu::CompareMode::Difference;
    gpu::ComparisonFrame frame(*a, sa, *b, sb, c);
    composited = present_offscreen(context(), a->resources(), frame, VK_FORMAT_B8G8R8A8_SRGB, 4);
    const CpuStats cpu = cpu_stats(alone_a, alone_b, 2);
    const gpu::ComparisonStats& stats = frame.completed_comparison();
    ASSERT_TRUE(stats.valid);
    EXPECT_NEAR(stats.mean, cpu.mean, 1e-9);
    EXPECT_NEAR(stats.psnr_db, cpu.psnr, 1e-6);
    EXPECT_FALSE(frame.completed_stats_a().passes.empty());
    ASSERT_FALSE(frame.completed_stats_b().passes.empty());
    EXPECT_EQ(frame.completed_stats_b().passes[0].name, "rays");
    std::size_t off = 0;
    for (std::size_t p = 0; p < cpu.d.size(); ++p) {
        const auto want = gpu::heat_colour(cpu.d[p] / 16.0);
        for (int k = 0; k < 3; ++k) off += std::abs(int(composited[4 * p + k]) - int(want[k])) > 1;
    }
    EXPECT_EQ(off, 0u);
    std::vector<std::uint8_t> again_a, again_b;
    a->render(sa, &again_a);
    b->render(sb, &again_b);
    EXPECT_EQ(again_a, alone_a);
    EXPECT_EQ(again_b, alone_b);
    EXPECT_THROW(gpu::ComparisonFrame(*a, sa, *a, sa, c), gpu::GpuError);
}

} // namespace
} // namespace sherpa::test
