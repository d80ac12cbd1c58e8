// render_difference: both scenes rendered from one camera by two renderers and
// differenced per pixel on the GPU (render::render_comparison, the editor's difference
// view), then laid out as one picture a reader can take in without stdout: the heat
// over a dimmed side A, both sides at half size, and the legend with its numbers
// (tex::draw_text's built-in font; the heat colours are render::heat_colour's).
#include <sherpa/gpu/context.h>
#include <sherpa/lab/compare.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/comparison.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/framing.h>
#include <sherpa/texture/image_text.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

namespace sherpa::lab {
namespace {

constexpr std::uint32_t kBarRows = 12;                 // the heat colour strip
constexpr std::uint32_t kLine = tex::kGlyphHeight + 4; // one line of text
constexpr tex::Rgb8 kPaper{24, 24, 24}, kInk{255, 255, 255};
// Side A under the heat: grey at this share of its luminance, so that every heat
// colour (from dark blue up) stands out from it by hue.
constexpr double kDim = 0.35;

std::string format(const char* f, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, a);
    return buf;
}

// `text` cut to `width` pixels ("..." at the end when cut).
std::string fit(std::string text, std::uint32_t width) {
    const std::size_t chars = (width + 1) / tex::kGlyphAdvance;
    if (text.size() > chars) text = chars > 3 ? text.substr(0, chars - 3) + "..." : "";
    return text;
}

// A label on a dark box, so that it reads over any picture.
void label(tex::RgbaImage& image, int x, int y, const std::string& text) {
    tex::fill_rect(image, x, y, int(tex::text_width(text)) + 4, int(kLine), kPaper);
    tex::draw_text(image, x + 2, y + 2, text, kInk);
}

const std::uint8_t* texel(const std::vector<std::uint8_t>& rgba, std::uint32_t width,
                          std::uint32_t x, std::uint32_t y) {
    return &rgba[4 * (std::size_t(y) * width + x)];
}

// Side `rgba` (width x height) at half size (2x2 box) with its top-left at (x0, y0).
void paste_half(tex::RgbaImage& out, const std::vector<std::uint8_t>& rgba, std::uint32_t width,
                std::uint32_t height, std::uint32_t x0, std::uint32_t y0) {
    for (std::uint32_t y = 0; y < height / 2; ++y)
        for (std::uint32_t x = 0; x < width / 2; ++x) {
            std::uint8_t* o = &out.pixels[4 * (std::size_t(y0 + y) * out.width + x0 + x)];
            for (int c = 0; c < 3; ++c)
                o[c] = std::uint8_t((texel(rgba, width, 2 * x, 2 * y)[c] +
                                     texel(rgba, width, 2 * x + 1, 2 * y)[c] +
                                     texel(rgba, width, 2 * x, 2 * y + 1)[c] +
                                     texel(rgba, width, 2 * x + 1, 2 * y + 1)[c] + 2) /
                                    4);
            o[3] = 255;
        }
}

void draw_legend(tex::RgbaImage& image, const DifferenceImage& d, std::uint32_t top) {
    const std::uint32_t w = image.width;
    for (std::uint32_t y = 0; y < kBarRows; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const auto c = render::heat_colour(double(x) / std::max(1u, w - 1));
            std::copy(c.begin(), c.end(),
                      image.pixels.begin() + std::ptrdiff_t(4 * ((top + y) * std::size_t(w) + x)));
        }
    // Ticks under the strip: 0 at the left, half the scale, the scale (white) at the right.
    const int ticks = int(top + kBarRows + 2);
    if (d.scale > 0.0) {
        const std::string half = format("%.3g", 0.5 * d.scale);
        const std::string full = format(">= %.3g", d.scale);
        tex::draw_text(image, 2, ticks, "0", kInk);
        tex::draw_text(image, int(w / 2) - int(tex::text_width(half) / 2), ticks, half, kInk);
        tex::draw_text(image, int(w) - int(tex::text_width(full)) - 2, ticks, full, kInk);
    } else {
        tex::draw_text(image, 2, ticks, "no pixel differs", kInk);
    }
    const std::string scale_line = fit(
        "colour: |A - B|, largest of R, G, B in 8-bit steps (white: " + format("%.3g", d.scale) +
            ")",
        w - 4);
    const std::string psnr = std::isfinite(d.psnr) ? format("%.2f dB", d.psnr) : "inf dB";
    const std::string numbers =
        fit("mean " + format("%.3g", d.mean) + "  max " + format("%.0f", d.max) + "  PSNR " + psnr +
                "  " + format("%.2f", d.over_threshold_percent) + "% of pixels over " +
                std::to_string(d.threshold),
            w - 4);
    tex::draw_text(image, 2, ticks + int(kLine), scale_line, kInk);
    tex::draw_text(image, 2, ticks + 2 * int(kLine), numbers, kInk);
}

} // namespace

DifferenceImage render_difference(const scene::Scene& a, const scene::Scene& b,
                                  const DifferenceOptions& options) {
    DifferenceImage out;
    out.threshold = options.threshold;
    const std::uint32_t w = std::max(options.width, 2u), h = std::max(options.height, 2u);
    std::vector<std::uint8_t> heat, side_a, side_b;
    render::ComparisonStats stats;
    try {
        gpu::ContextOptions co;
        co.validation = options.validation;
        gpu::Context context(co);
        render::Renderer renderer_a(context), renderer_b(context);
        render::FrameRequest settings;
        render::copy_lighting(options.lighting.settings, settings);
        renderer_a.set_environment(options.lighting.environment.get());
        renderer_b.set_environment(options.lighting.environment.get());
        settings.width = w, settings.height = h;
        settings.shadows = false;
        scene::FramingOptions framing;
        framing.aspect = float(w) / float(h);
        scene::CameraSpec camera =
            options.camera ? *options.camera : scene::frame_scene(a, nullptr, framing);
        camera.aspect = framing.aspect;
        settings.camera = render::explicit_camera(camera);
        renderer_a.load(a);
        renderer_b.load(b);
        render::ComparisonSettings compare;
        compare.mode = render::CompareMode::Difference;
        compare.threshold = float(options.threshold) / 255.0f;
        // One stray pixel would make everything else black at a scale of the largest
        // difference: white is the 99.9th percentile of the pixels that differ at all.
        compare.heat_max = 0.0f;
        stats =
            render::render_comparison(renderer_a, settings, renderer_b, settings, compare, &heat);
        renderer_a.render(settings, &side_a);
        renderer_b.render(settings, &side_b);
        if (context.validation().count() > 0)
            out.error = "validation: " + context.validation().messages().front().text;
    } catch (const std::exception& e) {
        out.error = std::string("rendering failed: ") + e.what();
        return out;
    }
    const std::size_t pixels = std::size_t(w) * h;
    if (heat.size() < 4 * pixels || side_a.size() < 4 * pixels || side_b.size() < 4 * pixels) {
        out.error = "rendering failed: a side was not read back";
        return out;
    }
    out.mean = stats.mean * 255.0;
    out.max = stats.max * 255.0;
    out.psnr = stats.psnr_db;
    out.over_threshold_percent = stats.over_threshold_percent;
    out.scale = stats.percentile_999() * 255.0;

    const std::uint32_t sides_top = h, legend_top = h + h / 2;
    const std::uint32_t captions_top = legend_top + kBarRows + 2 + 3 * kLine + 2;
    tex::RgbaImage& image = out.image;
    image.width = w;
    image.height = captions_top + std::uint32_t(options.captions.size()) * kLine + 2;
    image.pixels.assign(std::size_t(image.width) * image.height * 4, 255);
    tex::fill_rect(image, 0, 0, int(w), int(image.height), kPaper);
    // The heat where a pixel differs at all (any d > 0 has a colour other than black),
    // else side A dimmed to grey.
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* hp = &heat[4 * i];
        std::uint8_t* o = &image.pixels[4 * i];
        if (hp[0] | hp[1] | hp[2]) {
            o[0] = hp[0], o[1] = hp[1], o[2] = hp[2];
        } else {
            const std::uint8_t* pa = &side_a[4 * i];
            const double grey = kDim * (0.2126 * pa[0] + 0.7152 * pa[1] + 0.0722 * pa[2]);
            o[0] = o[1] = o[2] = std::uint8_t(std::lround(grey));
        }
        o[3] = 255;
    }
    label(image, 0, 0, fit("|A - B| over A (grey)", w));
    paste_half(image, side_a, w, h, 0, sides_top);
    paste_half(image, side_b, w, h, w / 2, sides_top);
    label(image, 0, int(sides_top), fit(options.label_a, w / 2 - 4));
    label(image, int(w / 2), int(sides_top), fit(options.label_b, w / 2 - 4));
    out.legend_top = legend_top;
    draw_legend(image, out, legend_top);
    for (std::size_t i = 0; i < options.captions.size(); ++i)
        tex::draw_text(image, 2, int(captions_top + i * kLine), fit(options.captions[i], w - 4),
                       kInk);
    return out;
}

} // namespace sherpa::lab
