#include <sherpa/render/path_trace.h>

#include <algorithm>
#include <cmath>

namespace sherpa::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

double luminance(const float* rgb) {
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

// Prefix sums of `w` normalised to 0 .. 1 into out[0 .. w.size()]; false if they sum to 0.
bool normalised_cdf(const std::vector<double>& w, float* out) {
    double total = 0.0;
    out[0] = 0.0f;
    std::vector<double> prefix(w.size() + 1, 0.0);
    for (std::size_t i = 0; i < w.size(); ++i) prefix[i + 1] = total += w[i];
    if (!(total > 0.0) || !std::isfinite(total)) {
        for (std::size_t i = 0; i <= w.size(); ++i) out[i] = float(i) / float(w.size());
        return false;
    }
    for (std::size_t i = 1; i <= w.size(); ++i) out[i] = float(prefix[i] / total);
    out[w.size()] = 1.0f;
    return true;
}

} // namespace

EnvironmentDistribution environment_distribution(const EnvironmentImage& image,
                                                 std::uint32_t max_width) {
    EnvironmentDistribution d;
    if (!image.valid() || max_width == 0) return d;
    const std::uint32_t w = std::min(image.width, max_width);
    const std::uint32_t h = std::max(1u, std::min(image.height, (w + 1) / 2));
    std::vector<double> weight(std::size_t(w) * h, 0.0);
    for (std::uint32_t y = 0; y < h; ++y) {
        const std::uint32_t y0 = std::uint32_t(std::uint64_t(y) * image.height / h);
        const std::uint32_t y1 =
            std::max(y0 + 1, std::uint32_t(std::uint64_t(y + 1) * image.height / h));
        const double sin_theta = std::sin(kPi * (y + 0.5) / h);
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::uint32_t x0 = std::uint32_t(std::uint64_t(x) * image.width / w);
            const std::uint32_t x1 =
                std::max(x0 + 1, std::uint32_t(std::uint64_t(x + 1) * image.width / w));
            double sum = 0.0;
            for (std::uint32_t sy = y0; sy < y1; ++sy)
                for (std::uint32_t sx = x0; sx < x1; ++sx) {
                    const double l =
                        luminance(&image.rgba[(std::size_t(sy) * image.width + sx) * 4]);
                    if (std::isfinite(l) && l > 0.0) sum += l;
                }
            weight[std::size_t(y) * w + x] = sum / double((y1 - y0) * (x1 - x0)) * sin_theta;
        }
    }
    d.cdf.assign(std::size_t(h) + 1 + std::size_t(h) * (w + 1), 0.0f);
    std::vector<double> rows(h, 0.0);
    for (std::uint32_t y = 0; y < h; ++y) {
        const std::vector<double> row(weight.begin() + std::ptrdiff_t(y) * w,
                                      weight.begin() + std::ptrdiff_t(y + 1) * w);
        for (double v : row) rows[y] += v;
        normalised_cdf(row, &d.cdf[h + 1 + std::size_t(y) * (w + 1)]);
    }
    if (!normalised_cdf(rows, d.cdf.data())) {
        d.cdf.clear();
        return d; // no light to sample
    }
    d.width = w;
    d.height = h;
    return d;
}

float environment_pdf(const EnvironmentDistribution& d, glm::vec3 e) {
    if (d.empty()) return 0.0f;
    const double u = std::atan2(double(e.z), double(e.x)) / (2.0 * kPi) + 0.5;
    const double theta = std::acos(std::clamp(double(e.y), -1.0, 1.0));
    const std::uint32_t col = std::min(std::uint32_t(u * d.width), d.width - 1);
    const std::uint32_t row = std::min(std::uint32_t(theta / kPi * d.height), d.height - 1);
    const double p_row = double(d.cdf[row + 1]) - d.cdf[row];
    const std::size_t base = d.height + 1 + std::size_t(row) * (d.width + 1);
    const double p_col = double(d.cdf[base + col + 1]) - d.cdf[base + col];
    const double sin_theta = std::sin(theta);
    if (!(sin_theta > 0.0)) return 0.0f;
    return float(p_row * p_col * double(d.width) * d.height / (2.0 * kPi * kPi * sin_theta));
}

PathTraceError estimate_error(const PathTraceImage& image) {
    PathTraceError e;
    e.samples = image.samples;
    const std::size_t pixels = std::size_t(image.width) * image.height;
    if (pixels == 0 || image.samples == 0 || image.sums.size() < pixels * 4 ||
        image.moments.size() < pixels)
        return e;
    const double n = image.samples;
    double lum = 0.0, se = 0.0, se2 = 0.0;
    for (std::size_t p = 0; p < pixels; ++p) {
        const double mean = luminance(&image.sums[p * 4]) / n;
        const double second = double(image.moments[p]) / n;
        // The unbiased sample variance; one sample has none to estimate.
        const double variance = n > 1.0 ? std::max(0.0, second - mean * mean) * n / (n - 1.0) : 0.0;
        const double error = std::sqrt(variance / n);
        lum += mean;
        se += error;
        se2 += error * error;
    }
    e.mean_luminance = lum / double(pixels);
    e.mean_standard_error = se / double(pixels);
    e.rms_standard_error = std::sqrt(se2 / double(pixels));
    e.relative_error = e.mean_luminance > 0.0 ? e.mean_standard_error / e.mean_luminance : 0.0;
    return e;
}

} // namespace sherpa::render
