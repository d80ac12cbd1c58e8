// render_difference: both scenes rendered from one camera, differenced per pixel.
#include <sherpa/gpu/context.h>
#include <sherpa/lab/compare.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/render_settings.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/framing.h>
#include <sherpa/texture/quality.h>

#include <algorithm>
#include <array>
#include <exception>

namespace sherpa::lab {
namespace {

constexpr std::uint32_t kLegendRows = 12;

// Black, blue, red, yellow, white over t in 0..1.
std::array<std::uint8_t, 3> heat_colour(double t) {
    static constexpr std::array<std::array<double, 3>, 5> stops{
        {{0, 0, 0}, {0, 0, 255}, {255, 0, 0}, {255, 255, 0}, {255, 255, 255}}};
    t = std::clamp(t, 0.0, 1.0) * 4.0;
    const std::size_t i = std::min<std::size_t>(3, std::size_t(t));
    const double f = t - double(i);
    std::array<std::uint8_t, 3> c{};
    for (int k = 0; k < 3; ++k)
        c[k] = std::uint8_t(stops[i][k] + f * (stops[i + 1][k] - stops[i][k]) + 0.5);
    return c;
}

} // namespace

DifferenceImage render_difference(const Scene& a, const Scene& b,
                                  const DifferenceOptions& options) {
    DifferenceImage out;
    out.threshold = options.threshold;
    std::vector<std::uint8_t> pa, pb;
    try {
        gpu::ContextOptions co;
        co.validation = options.validation;
        gpu::Context context(co);
        gpu::Renderer renderer(context);
        gpu::RenderSettings settings;
        settings.width = options.width, settings.height = options.height;
        settings.shadows = false;
        FramingOptions framing;
        framing.aspect = float(options.width) / float(std::max(1u, options.height));
        CameraSpec camera = options.camera ? *options.camera : frame_box(a.bounds, framing);
        camera.aspect = framing.aspect;
        settings.camera = gpu::explicit_camera(camera);
        renderer.load(a);
        renderer.render(settings, &pa);
        renderer.load(b);
        renderer.render(settings, &pb);
        if (context.validation().count() > 0)
            out.error = "validation: " + context.validation().messages().front().text;
    } catch (const std::exception& e) {
        out.error = std::string("rendering failed: ") + e.what();
        return out;
    }
    const std::size_t pixels = std::size_t(options.width) * options.height;
    std::vector<std::uint8_t> d(pixels);
    double sum = 0.0;
    std::uint64_t over = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        int m = 0;
        for (int k = 0; k < 3; ++k)
            m = std::max(m, std::abs(int(pa[4 * p + k]) - int(pb[4 * p + k])));
        d[p] = std::uint8_t(m);
        sum += m;
        out.max = std::max(out.max, double(m));
        over += std::uint32_t(m) > options.threshold ? 1 : 0;
    }
    out.mean = pixels ? sum / double(pixels) : 0.0;
    out.over_threshold_percent = pixels ? 100.0 * double(over) / double(pixels) : 0.0;
    out.psnr = tex::squared_error(pa, pb, tex::kChannelsRgb).psnr();
    tex::RgbaImage& heat = out.heat;
    heat.width = options.width, heat.height = options.height + kLegendRows;
    heat.pixels.assign(std::size_t(heat.width) * heat.height * 4, 255);
    // One stray pixel would make everything else black at a scale of the largest d:
    // the scale is the 99.9th percentile of the pixels that differ at all.
    std::vector<std::uint8_t> nonzero;
    for (std::uint8_t v : d)
        if (v) nonzero.push_back(v);
    if (!nonzero.empty()) {
        const std::size_t rank =
            std::min(nonzero.size() - 1, std::size_t(0.999 * double(nonzero.size())));
        std::nth_element(nonzero.begin(), nonzero.begin() + std::ptrdiff_t(rank), nonzero.end());
        out.scale = nonzero[rank];
    }
    const double scale = std::max(1.0, out.scale);
    auto put = [&](std::size_t at, double t) {
        const auto c = heat_colour(t);
        std::copy(c.begin(), c.end(), heat.pixels.begin() + std::ptrdiff_t(4 * at));
    };
    for (std::size_t p = 0; p < pixels; ++p) put(p, d[p] / scale);
    // Legend: 0 at the left to `scale` (and above) at the right.
    for (std::uint32_t y = 0; y < kLegendRows; ++y)
        for (std::uint32_t x = 0; x < heat.width; ++x)
            put(pixels + std::size_t(y) * heat.width + x, double(x) / std::max(1u, heat.width - 1));
    return out;
}

} // namespace sherpa::lab
