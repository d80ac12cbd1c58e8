// Projection of an equirectangular environment on 9 SH coefficients (environment_sh.h).
#include <sherpa/render/environment_sh.h>

#include <cmath>
#include <vector>

namespace sherpa::render {

std::array<float, 9> sh9_basis(glm::vec3 d) {
    const float x = d.x, y = d.y, z = d.z;
    return {0.282095f,
            0.488603f * y,
            0.488603f * z,
            0.488603f * x,
            1.092548f * x * y,
            1.092548f * y * z,
            0.315392f * (3.0f * z * z - 1.0f),
            1.092548f * x * z,
            0.546274f * (x * x - y * y)};
}

Sh9 project_sh9(const EnvironmentImage& image) {
    Sh9 out{};
    if (!image.valid()) return out;
    const double pi = 3.14159265358979323846;
    const std::uint32_t w = image.width, h = image.height;
    // Every basis function is a polynomial in x = c cos(phi), y = s, z = c sin(phi)
    // (c, s: cosine and sine of the row's latitude): a row contributes through the
    // sums of its radiance times 1, cos, sin, cos^2 and cos sin of the columns' phi
    // (sin^2 = 1 - cos^2), five multiply-adds per channel and texel, in float over
    // one row (at most 16384 texels) and in double across rows.
    std::vector<float> cos_phi(w), sin_phi(w);
    for (std::uint32_t i = 0; i < w; ++i) {
        // u = atan2(z, x) / 2pi + 0.5
        const double phi = 2.0 * pi * ((i + 0.5) / w - 0.5);
        cos_phi[i] = float(std::cos(phi));
        sin_phi[i] = float(std::sin(phi));
    }
    std::array<glm::dvec3, 9> sum{};
    for (std::uint32_t j = 0; j < h; ++j) {
        // Row j (0 at the top) spans latitudes [top, bottom]; v = asin(y) / pi + 0.5.
        const double lat_top = pi * (0.5 - double(j) / h);
        const double lat_bottom = pi * (0.5 - double(j + 1) / h);
        const double lat = 0.5 * (lat_top + lat_bottom);
        // The texel's exact solid angle: dphi * (sin(top) - sin(bottom)).
        const double solid_angle = (2.0 * pi / w) * (std::sin(lat_top) - std::sin(lat_bottom));
        const double c = std::cos(lat), s = std::sin(lat);
        // Radiance times 1, cos, sin, cos^2, cos sin, per channel: fifteen independent
        // sums, kept in registers.
        float r0 = 0, rc = 0, rs = 0, rcc = 0, rcs = 0, g0 = 0, gc = 0, gs = 0, gcc = 0, gcs = 0,
              b0 = 0, bc = 0, bs = 0, bcc = 0, bcs = 0;
        const float* row = &image.rgba[4 * std::size_t(j) * w];
        for (std::uint32_t i = 0; i < w; ++i) {
            const float cp = cos_phi[i], sp = sin_phi[i], cc = cp * cp, cs = cp * sp;
            const float* t = row + 4 * i;
            const float r = std::isfinite(t[0]) ? t[0] : 0.0f;
            const float g = std::isfinite(t[1]) ? t[1] : 0.0f;
            const float b = std::isfinite(t[2]) ? t[2] : 0.0f;
            r0 += r, rc += r * cp, rs += r * sp, rcc += r * cc, rcs += r * cs;
            g0 += g, gc += g * cp, gs += g * sp, gcc += g * cc, gcs += g * cs;
            b0 += b, bc += b * cp, bs += b * sp, bcc += b * cc, bcs += b * cs;
        }
        const float m[5][3] = {
            {r0, g0, b0}, {rc, gc, bc}, {rs, gs, bs}, {rcc, gcc, bcc}, {rcs, gcs, bcs}};
        for (int k = 0; k < 3; ++k) {
            const double m0 = m[0][k], mc = m[1][k], ms = m[2][k], mcc = m[3][k], mcs = m[4][k];
            const double mss = m0 - mcc;
            const double y[9] = {0.282095 * m0,
                                 0.488603 * s * m0,
                                 0.488603 * c * ms,
                                 0.488603 * c * mc,
                                 1.092548 * c * s * mc,
                                 1.092548 * s * c * ms,
                                 0.315392 * (3.0 * c * c * mss - m0),
                                 1.092548 * c * c * mcs,
                                 0.546274 * (c * c * mcc - s * s * m0)};
            for (int b = 0; b < 9; ++b) sum[b][k] += y[b] * solid_angle;
        }
    }
    for (int k = 0; k < 9; ++k) out[k] = glm::vec3(sum[k]);
    return out;
}

Sh9 irradiance_sh9(const Sh9& radiance) {
    // A_l / pi: 1, 2/3, 1/4.
    constexpr float band[9] = {1.0f,  2.0f / 3.0f, 2.0f / 3.0f, 2.0f / 3.0f, 0.25f,
                               0.25f, 0.25f,       0.25f,       0.25f};
    Sh9 out{};
    for (int k = 0; k < 9; ++k) out[k] = radiance[k] * band[k];
    return out;
}

glm::vec3 evaluate_sh9(const Sh9& coefficients, glm::vec3 n) {
    const std::array<float, 9> y = sh9_basis(n);
    glm::vec3 out(0.0f);
    for (int k = 0; k < 9; ++k) out += coefficients[k] * y[k];
    return out;
}

std::string_view to_string(IrradianceMode m) {
    return m == IrradianceMode::Sh9 ? "sh9" : "cube";
}

std::optional<IrradianceMode> parse_irradiance_mode(std::string_view name) {
    if (name == "cube") return IrradianceMode::Cube;
    if (name == "sh9") return IrradianceMode::Sh9;
    return std::nullopt;
}

} // namespace sherpa::render
