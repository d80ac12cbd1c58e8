#include <sherpa/texture/mips.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace sherpa::tex {

float srgb_to_linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
float linear_to_srgb(float l) {
    return l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f;
}

std::uint32_t full_mip_count(std::uint32_t width, std::uint32_t height) {
    std::uint32_t n = 1;
    for (std::uint32_t s = std::max(width, height); s > 1; s >>= 1) ++n;
    return n;
}

namespace {

// A level in working form: four floats per texel. Colour: linear RGB, alpha.
// Normals: unit xyz, alpha. Linear data: the values / 255.
struct FloatImage {
    std::uint32_t width = 0, height = 0;
    std::vector<float> texels;
};

// Source texels and weights covering destination texel i along one axis: the
// interval [i * src / dst, (i + 1) * src / dst), weighted by overlap.
struct Tap {
    std::uint32_t first = 0;
    std::vector<float> weights;
};
std::vector<Tap> footprints(std::uint32_t src, std::uint32_t dst) {
    std::vector<Tap> taps(dst);
    const double ratio = double(src) / double(dst);
    for (std::uint32_t i = 0; i < dst; ++i) {
        const double lo = i * ratio, hi = (i + 1) * ratio;
        Tap& t = taps[i];
        t.first = static_cast<std::uint32_t>(std::floor(lo));
        for (std::uint32_t j = t.first; j < src && j < hi; ++j)
            t.weights.push_back(
                static_cast<float>(std::min<double>(hi, j + 1) - std::max<double>(lo, j)));
    }
    return taps;
}

FloatImage to_float(const RgbaImage& img, MipFilter filter) {
    std::array<float, 256> srgb{};
    for (int i = 0; i < 256; ++i) srgb[i] = srgb_to_linear(i / 255.0f);
    FloatImage f{img.width, img.height, std::vector<float>(img.pixels.size())};
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) {
        float* d = &f.texels[i];
        const std::uint8_t* s = &img.pixels[i];
        for (int c = 0; c < 4; ++c) d[c] = s[c] / 255.0f;
        if (filter == MipFilter::Color) {
            for (int c = 0; c < 3; ++c) d[c] = srgb[s[c]];
        } else if (filter == MipFilter::Normal) {
            for (int c = 0; c < 3; ++c) d[c] = s[c] / 127.5f - 1.0f;
        }
    }
    return f;
}

std::uint8_t to_byte(float v) {
    return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

RgbaImage to_bytes(const FloatImage& f, MipFilter filter) {
    RgbaImage img{f.width, f.height, std::vector<std::uint8_t>(f.texels.size())};
    for (std::size_t i = 0; i < f.texels.size(); i += 4) {
        const float* s = &f.texels[i];
        std::uint8_t* d = &img.pixels[i];
        for (int c = 0; c < 3; ++c) {
            const float v = filter == MipFilter::Color    ? linear_to_srgb(std::max(s[c], 0.0f))
                            : filter == MipFilter::Normal ? (s[c] + 1.0f) * 0.5f
                                                          : s[c];
            d[c] = to_byte(v);
        }
        d[3] = to_byte(s[3]);
    }
    return img;
}

FloatImage downsample(const FloatImage& src, MipFilter filter) {
    const std::uint32_t w = std::max(1u, src.width / 2), h = std::max(1u, src.height / 2);
    const auto tx = footprints(src.width, w), ty = footprints(src.height, h);
    FloatImage dst{w, h, std::vector<float>(std::size_t{w} * h * 4)};
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            double sum[4] = {0, 0, 0, 0}, weight = 0, alpha_weight = 0;
            for (std::size_t j = 0; j < ty[y].weights.size(); ++j)
                for (std::size_t i = 0; i < tx[x].weights.size(); ++i) {
                    const double wt = double(ty[y].weights[j]) * tx[x].weights[i];
                    const float* s =
                        &src.texels[((std::size_t{ty[y].first} + j) * src.width + tx[x].first + i) *
                                    4];
                    // Colour is weighted by alpha (premultiplied filtering).
                    const double cw = filter == MipFilter::Color ? wt * s[3] : wt;
                    for (int c = 0; c < 3; ++c) sum[c] += cw * s[c];
                    sum[3] += wt * s[3];
                    weight += wt, alpha_weight += cw;
                }
            float* d = &dst.texels[(std::size_t{y} * w + x) * 4];
            const double cnorm = alpha_weight > 1e-12 ? alpha_weight : weight;
            if (alpha_weight <= 1e-12 && filter == MipFilter::Color) {
                // Fully transparent footprint: plain average keeps a sensible colour.
                for (std::size_t j = 0; j < ty[y].weights.size(); ++j)
                    for (std::size_t i = 0; i < tx[x].weights.size(); ++i) {
                        const double wt = double(ty[y].weights[j]) * tx[x].weights[i];
                        const float* s = &src.texels[((std::size_t{ty[y].first} + j) * src.width +
                                                      tx[x].first + i) *
                                                     4];
                        for (int c = 0; c < 3; ++c) sum[c] += wt * s[c];
                    }
            }
            for (int c = 0; c < 3; ++c) d[c] = static_cast<float>(sum[c] / cnorm);
            d[3] = static_cast<float>(sum[3] / weight);
            if (filter == MipFilter::Normal) {
                const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                if (len > 1e-6f)
                    for (int c = 0; c < 3; ++c) d[c] /= len;
                else
                    d[0] = d[1] = 0.0f, d[2] = 1.0f; // opposing normals cancel: face outwards
            }
        }
    return dst;
}

// Scales alpha so that alpha_coverage(level, cutoff) matches `target`, by
// bisection on the scale factor (coverage grows monotonically with it).
void preserve_coverage(RgbaImage& level, float cutoff, double target) {
    const RgbaImage original = level;
    auto apply = [&](float scale) {
        for (std::size_t i = 3; i < level.pixels.size(); i += 4)
            level.pixels[i] = to_byte(original.pixels[i] / 255.0f * scale);
    };
    float lo = 0.0f, hi = 8.0f;
    for (int iter = 0; iter < 20; ++iter) {
        const float mid = 0.5f * (lo + hi);
        apply(mid);
        (alpha_coverage(level, cutoff) < target ? lo : hi) = mid;
    }
    // The upper bound reaches at least the target coverage.
    apply(hi);
}

} // namespace

double alpha_coverage(const RgbaImage& image, float cutoff) {
    if (image.empty()) return 0.0;
    std::size_t covered = 0;
    for (std::size_t i = 3; i < image.pixels.size(); i += 4)
        covered += image.pixels[i] / 255.0f >= cutoff;
    return double(covered) / double(image.pixels.size() / 4);
}

std::vector<RgbaImage> build_mip_chain(const RgbaImage& base, const MipSettings& settings) {
    if (base.empty() || base.pixels.size() != std::size_t{base.width} * base.height * 4)
        throw std::invalid_argument("build_mip_chain: empty or malformed base image");
    std::vector<RgbaImage> chain{base};
    const std::uint32_t count = full_mip_count(base.width, base.height);
    FloatImage current = to_float(base, settings.filter);
    const double coverage = settings.alpha_coverage_cutoff
                                ? alpha_coverage(base, *settings.alpha_coverage_cutoff)
                                : 0.0;
    for (std::uint32_t l = 1; l < count; ++l) {
        current = downsample(current, settings.filter);
        RgbaImage level = to_bytes(current, settings.filter);
        if (settings.alpha_coverage_cutoff)
            preserve_coverage(level, *settings.alpha_coverage_cutoff, coverage);
        chain.push_back(std::move(level));
    }
    return chain;
}

} // namespace sherpa::tex
