// render_difference: both scenes rendered from one camera by two renderers and
// differenced per pixel on the GPU (gpu::render_comparison, the editor's difference
// view), the legend strip drawn with the same heat colours (gpu::heat_colour).
#include <sherpa/gpu/context.h>
#include <sherpa/lab/compare.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/comparison.h>
#include <sherpa/render/render_settings.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/framing.h>

#include <algorithm>
#include <exception>

namespace sherpa::lab {
namespace {

constexpr std::uint32_t kLegendRows = 12;

} // namespace

DifferenceImage render_difference(const Scene& a, const Scene& b,
                                  const DifferenceOptions& options) {
    DifferenceImage out;
    out.threshold = options.threshold;
    std::vector<std::uint8_t> heat;
    gpu::ComparisonStats stats;
    try {
        gpu::ContextOptions co;
        co.validation = options.validation;
        gpu::Context context(co);
        gpu::Renderer renderer_a(context), renderer_b(context);
        gpu::RenderSettings settings;
        gpu::copy_lighting(options.lighting.settings, settings);
        renderer_a.set_environment(options.lighting.environment.get());
        renderer_b.set_environment(options.lighting.environment.get());
        settings.width = options.width, settings.height = options.height;
        settings.shadows = false;
        FramingOptions framing;
        framing.aspect = float(options.width) / float(std::max(1u, options.height));
        CameraSpec camera = options.camera ? *options.camera : frame_box(a.bounds, framing);
        camera.aspect = framing.aspect;
        settings.camera = gpu::explicit_camera(camera);
        renderer_a.load(a);
        renderer_b.load(b);
        gpu::ComparisonSettings compare;
        compare.mode = gpu::CompareMode::Difference;
        compare.threshold = float(options.threshold) / 255.0f;
        // One stray pixel would make everything else black at a scale of the largest
        // difference: white is the 99.9th percentile of the pixels that differ at all.
        compare.heat_max = 0.0f;
        stats = gpu::render_comparison(renderer_a, settings, renderer_b, settings, compare, &heat);
        if (context.validation().count() > 0)
            out.error = "validation: " + context.validation().messages().front().text;
    } catch (const std::exception& e) {
        out.error = std::string("rendering failed: ") + e.what();
        return out;
    }
    out.mean = stats.mean * 255.0;
    out.max = stats.max * 255.0;
    out.psnr = stats.psnr_db;
    out.over_threshold_percent = stats.over_threshold_percent;
    out.scale = stats.percentile_999() * 255.0;
    tex::RgbaImage& image = out.heat;
    image.width = options.width, image.height = options.height + kLegendRows;
    image.pixels = std::move(heat);
    image.pixels.resize(std::size_t(image.width) * image.height * 4, 255);
    // Legend: 0 at the left to the scale (and above) at the right.
    const std::size_t legend = std::size_t(options.width) * options.height;
    for (std::uint32_t y = 0; y < kLegendRows; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const auto c = gpu::heat_colour(double(x) / std::max(1u, image.width - 1));
            std::copy(c.begin(), c.end(),
                      image.pixels.begin() +
                          std::ptrdiff_t(4 * (legend + std::size_t(y) * image.width + x)));
        }
    return out;
}

} // namespace sherpa::lab
