#include <sherpa/texture/quality.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sherpa::tex {

double SquaredError::psnr() const {
    if (samples == 0 || sum <= 0.0) return std::numeric_limits<double>::infinity();
    const double mse = sum / double(samples);
    return 10.0 * std::log10(255.0 * 255.0 / mse);
}

namespace {
void check_same(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    if (a.size() != b.size() || a.size() % 4 != 0)
        throw std::invalid_argument("image error: RGBA8 spans differ in size");
}
} // namespace

SquaredError squared_error(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b,
                           unsigned channel_mask) {
    check_same(a, b);
    SquaredError e;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!(channel_mask >> (i & 3) & 1u)) continue;
        const double d = double(a[i]) - double(b[i]);
        e.sum += d * d;
        ++e.samples;
    }
    return e;
}

AngleError normal_angle_error(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    check_same(a, b);
    auto normal = [](const std::uint8_t* t, double n[3]) {
        n[0] = t[0] / 127.5 - 1.0;
        n[1] = t[1] / 127.5 - 1.0;
        n[2] = std::sqrt(std::max(0.0, 1.0 - n[0] * n[0] - n[1] * n[1]));
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; c < 3; ++c) n[c] /= len;
    };
    AngleError e;
    for (std::size_t i = 0; i < a.size(); i += 4) {
        double na[3], nb[3];
        normal(a.data() + i, na);
        normal(b.data() + i, nb);
        const double d = std::clamp(na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2], -1.0, 1.0);
        e.sum_degrees += std::acos(d) * (180.0 / M_PI);
        ++e.texels;
    }
    return e;
}

} // namespace sherpa::tex
