// Projection of an equirectangular environment on 9 SH coefficients (environment_sh.h).
#include <sherpa/render/environment_sh.h>

#include <cmath>
#include <vector>

namespace sherpa::gpu {

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
    // Sums in double: a 16384-wide image adds 1e8 texels.
    std::array<glm::dvec3, 9> sum{};
    std::vector<glm::vec3> dir(w);
    for (std::uint32_t j = 0; j < h; ++j) {
        // Row j (0 at the top) spans latitudes [top, bottom]; v = asin(y) / pi + 0.5.
        const double lat_top = pi * (0.5 - double(j) / h);
        const double lat_bottom = pi * (0.5 - double(j + 1) / h);
        const double lat = 0.5 * (lat_top + lat_bottom);
        // The texel's exact solid angle: dphi * (sin(top) - sin(bottom)).
        const double solid_angle = (2.0 * pi / w) * (std::sin(lat_top) - std::sin(lat_bottom));
        const double c = std::cos(lat), s = std::sin(lat);
        for (std::uint32_t i = 0; i < w; ++i) {
            // u = atan2(z, x) / 2pi + 0.5
            const double phi = 2.0 * pi * ((i + 0.5) / w - 0.5);
            dir[i] = glm::vec3(float(c * std::cos(phi)), float(s), float(c * std::sin(phi)));
        }
        for (std::uint32_t i = 0; i < w; ++i) {
            const float* t = &image.rgba[4 * (std::size_t(j) * w + i)];
            glm::dvec3 radiance(t[0], t[1], t[2]);
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(radiance[k])) radiance[k] = 0.0;
            const std::array<float, 9> y = sh9_basis(dir[i]);
            for (int k = 0; k < 9; ++k) sum[k] += radiance * (double(y[k]) * solid_angle);
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

} // namespace sherpa::gpu
