#include <sherpa/texture/bc5_normal.h>
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

namespace {
// Unit normal from R, G (and B when `use_blue`, else Z = sqrt(1 - x^2 - y^2)).
void decode_normal(const std::uint8_t* t, bool use_blue, double n[3]) {
    n[0] = t[0] / 127.5 - 1.0;
    n[1] = t[1] / 127.5 - 1.0;
    n[2] = use_blue ? t[2] / 127.5 - 1.0 : bc5_normal_z(n[0], n[1]);
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len < 1e-12) {
        n[0] = n[1] = 0.0, n[2] = 1.0;
        return;
    }
    for (int c = 0; c < 3; ++c) n[c] /= len;
}

AngleError angle_error(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b,
                       bool a_blue) {
    check_same(a, b);
    AngleError e;
    for (std::size_t i = 0; i < a.size(); i += 4) {
        double na[3], nb[3];
        decode_normal(a.data() + i, a_blue, na);
        decode_normal(b.data() + i, false, nb);
        const double d = std::clamp(na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2], -1.0, 1.0);
        e.sum_degrees += std::acos(d) * (180.0 / M_PI);
        ++e.texels;
    }
    return e;
}
} // namespace

AngleError normal_angle_error(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    return angle_error(a, b, false);
}

AngleError normal_angle_error_vs_rgb(std::span<const std::uint8_t> source,
                                     std::span<const std::uint8_t> two_channel) {
    return angle_error(source, two_channel, true);
}

} // namespace sherpa::tex
