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
    // (c, s: cosine and sine of the latitude). Each texel is taken as constant radiance
    // over its patch of the sphere and integrated exactly: its column's mean of cos,
    // sin, cos^2 and cos sin of phi, and its row's integrals of 1, s, c, c s, c^2 and
    // s^2 over the latitude band weighted by the solid angle's cos(lat). A midpoint rule
    // (the texel's centre direction) is exact only in the limit: a 1x1 uniform image
    // came out as 0.45 of its irradiance at the poles' normal, and a 4x2 one as 0.9.
    // Five multiply-adds per channel and texel, in float over one row (at most 16384
    // texels) and in double across rows.
    const double dphi = 2.0 * pi / w;
    std::vector<float> cos_phi(w), sin_phi(w), cos2_phi(w), cos_sin_phi(w);
    for (std::uint32_t i = 0; i < w; ++i) {
        // u = atan2(z, x) / 2pi + 0.5: column i spans phi in [p0, p1].
        const double p0 = 2.0 * pi * (double(i) / w - 0.5), p1 = p0 + dphi;
        cos_phi[i] = float((std::sin(p1) - std::sin(p0)) / dphi);
        sin_phi[i] = float((std::cos(p0) - std::cos(p1)) / dphi);
        cos2_phi[i] = float(0.5 + (std::sin(2.0 * p1) - std::sin(2.0 * p0)) / (4.0 * dphi));
        cos_sin_phi[i] =
            float((std::sin(p1) * std::sin(p1) - std::sin(p0) * std::sin(p0)) / (2.0 * dphi));
    }
    std::array<glm::dvec3, 9> sum{};
    for (std::uint32_t j = 0; j < h; ++j) {
        // Row j (0 at the top) spans latitudes [bottom, top]; v = asin(y) / pi + 0.5.
        const double t = pi * (0.5 - double(j) / h), b = pi * (0.5 - double(j + 1) / h);
        const double st = std::sin(t), sb = std::sin(b), ct = std::cos(t), cb = std::cos(b);
        // Integrals over the band of f(lat) cos(lat) dlat, for f = 1, s, c, c s, c^2, s^2.
        const double i_1 = st - sb;
        const double i_s = 0.5 * (st * st - sb * sb);
        const double i_c = 0.5 * (t - b) + 0.25 * (std::sin(2.0 * t) - std::sin(2.0 * b));
        const double i_cs = (cb * cb * cb - ct * ct * ct) / 3.0;
        const double i_cc = (st - st * st * st / 3.0) - (sb - sb * sb * sb / 3.0);
        const double i_ss = (st * st * st - sb * sb * sb) / 3.0;
        // Radiance times 1, cos, sin, cos^2, cos sin, per channel: fifteen independent
        // sums, kept in registers.
        float r0 = 0, rc = 0, rs = 0, rcc = 0, rcs = 0, g0 = 0, gc = 0, gs = 0, gcc = 0, gcs = 0,
              b0 = 0, bc = 0, bs = 0, bcc = 0, bcs = 0;
        const float* row = &image.rgba[4 * std::size_t(j) * w];
        for (std::uint32_t i = 0; i < w; ++i) {
            const float cp = cos_phi[i], sp = sin_phi[i], cc = cos2_phi[i], cs = cos_sin_phi[i];
            const float* px = row + 4 * i;
            const float r = std::isfinite(px[0]) ? px[0] : 0.0f;
            const float g = std::isfinite(px[1]) ? px[1] : 0.0f;
            const float bl = std::isfinite(px[2]) ? px[2] : 0.0f;
            r0 += r, rc += r * cp, rs += r * sp, rcc += r * cc, rcs += r * cs;
            g0 += g, gc += g * cp, gs += g * sp, gcc += g * cc, gcs += g * cs;
            b0 += bl, bc += bl * cp, bs += bl * sp, bcc += bl * cc, bcs += bl * cs;
        }
        const float m[5][3] = {
            {r0, g0, b0}, {rc, gc, bc}, {rs, gs, bs}, {rcc, gcc, bcc}, {rcs, gcs, bcs}};
        for (int k = 0; k < 3; ++k) {
            const double m0 = m[0][k], mc = m[1][k], ms = m[2][k], mcc = m[3][k], mcs = m[4][k];
            const double mss = m0 - mcc;
            const double y[9] = {0.282095 * m0 * i_1,
                                 0.488603 * m0 * i_s,
                                 0.488603 * ms * i_c,
                                 0.488603 * mc * i_c,
                                 1.092548 * mc * i_cs,
                                 1.092548 * ms * i_cs,
                                 0.315392 * (3.0 * mss * i_cc - m0 * i_1),
                                 1.092548 * mcs * i_cc,
                                 0.546274 * (mcc * i_cc - m0 * i_ss)};
            for (int n = 0; n < 9; ++n) sum[n][k] += y[n] * dphi;
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
