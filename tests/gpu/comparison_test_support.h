#pragma once
// What the comparison tests share (comparison_test.cpp, presented_comparison_test.cpp):
// the statistics of comparison.h computed on the CPU, small framed settings, a frame
// source driven the way the Presenter drives it, and a fixture making renderers.
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

inline constexpr std::uint32_t kW = 96, kH = 72;

// The statistics of comparison.h computed on the CPU from two RGBA8 images.
struct CpuStats {
    double mean = 0, max = 0, psnr = 0, over_percent = 0;
    std::vector<int> d; // per pixel: largest byte difference over R, G, B
};

inline CpuStats cpu_stats(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
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

inline render::FrameRequest small_settings(const scene::Scene& scene, render::DebugView view) {
    render::FrameRequest s;
    s.width = kW;
    s.height = kH;
    s.shadows = false;
    s.view = view;
    scene::FramingOptions framing;
    framing.aspect = float(kW) / float(kH);
    s.camera = render::explicit_camera(scene::frame_box(scene.bounds, framing));
    return s;
}

// Drives `source` as the Presenter does (wait_for_slot, record, submit with its extra
// signals, submitted), `frames` times into one image of `format` owned by the test,
// then reads the image back as RGBA rows.
inline std::vector<std::uint8_t> present_offscreen(gpu::Context& context,
                                                   gpu::ResourceManager& resources,
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

// Channels of a heat image more than one step away from heat_colour() of each
// pixel's CPU difference at `heat_max` 8-bit steps.
inline std::size_t heat_mismatches(const std::vector<std::uint8_t>& heat, const CpuStats& cpu,
                                   double heat_max) {
    std::size_t off = 0;
    for (std::size_t p = 0; p < cpu.d.size(); ++p) {
        const auto want = render::heat_colour(cpu.d[p] / heat_max);
        for (int k = 0; k < 3; ++k) off += std::abs(int(heat[4 * p + k]) - int(want[k])) > 1;
    }
    return off;
}

// Side A rasterized, side B ray traced, in `view`, each with its own renderer, and
// each side's image rendered alone.
struct RasterAndRays {
    std::unique_ptr<render::Renderer> a, b;
    render::FrameRequest sa, sb;
    std::vector<std::uint8_t> alone_a, alone_b;
};

class ComparisonTest : public GpuTest {
protected:
    RasterAndRays raster_and_rays(const scene::Scene& a_scene, const scene::Scene& b_scene,
                                  render::DebugView view) {
        RasterAndRays r{make_renderer(a_scene),
                        make_renderer(b_scene, true),
                        small_settings(a_scene, view),
                        {},
                        {},
                        {}};
        r.sb = r.sa;
        r.sb.renderer = render::RendererKind::RayTraced;
        r.a->render(r.sa, &r.alone_a);
        r.b->render(r.sb, &r.alone_b);
        return r;
    }
    std::unique_ptr<render::Renderer> make_renderer(const scene::Scene& scene, bool rt = false) {
        render::RendererOptions options;
        options.ray_tracing = rt;
        options.textures = test_texture_settings();
        auto r = std::make_unique<render::Renderer>(context(), options);
        r->load(scene, streams_setup(render::StreamPolicy::AllPresent));
        return r;
    }
};

} // namespace sherpa::test
