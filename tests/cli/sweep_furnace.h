#pragma once
// A sweep file in a furnace, as the CLI tests read it: the linear radiance at the front
// of a one-sphere sweep in a uniform environment of radiance 1, and the directional
// albedo of anisotropic GGX by an independent numerical integral (what the furnace
// should show for KHR_materials_anisotropy's metals).
#include "cli/cli_run.h"
#include "cli/sweep_images.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace sherpa::test {

// The directional albedo of anisotropic GGX (the specification's D and height-
// correlated V, Schlick's F of `f0` at v . h) seen along the normal: the integral over
// half vectors h of F D(h) V (n . l) 4 (v . h), by the midpoint rule (an independent
// evaluation of the BRDF both renderers use).
inline double anisotropic_albedo_at_normal(double alpha_t, double alpha_b, double f0) {
    const double pi = 3.14159265358979;
    const int thetas = 3000, phis = 720;
    double sum = 0.0;
    for (int i = 0; i < thetas; ++i) {
        const double theta = (i + 0.5) * (pi / 4.0) / thetas; // n . l > 0 needs theta < 45 deg
        const double ct = std::cos(theta), st = std::sin(theta);
        const double n_dot_l = 2.0 * ct * ct - 1.0;
        for (int j = 0; j < phis; ++j) {
            const double phi = (j + 0.5) * 2.0 * pi / phis;
            const glm::dvec3 h(st * std::cos(phi), st * std::sin(phi), ct);
            const glm::dvec3 l = 2.0 * ct * h - glm::dvec3(0.0, 0.0, 1.0);
            const glm::dvec3 f(h.x / alpha_t, h.y / alpha_b, h.z);
            const double d = 1.0 / (pi * alpha_t * alpha_b * glm::dot(f, f) * glm::dot(f, f));
            const double gv = n_dot_l;
            const double gl = glm::length(glm::dvec3(alpha_t * l.x, alpha_b * l.y, l.z));
            const double v = 0.5 / (gv + gl);
            const double fresnel = f0 + (1.0 - f0) * std::pow(1.0 - ct, 5.0);
            sum += fresnel * d * v * n_dot_l * 4.0 * ct * st * ((pi / 4.0) / thetas) *
                   (2.0 * pi / phis);
        }
    }
    return sum;
}

// The linear radiance (per channel) at the front of a one-sphere sweep file, 48x36 seen
// from 1.5 in front, in a uniform environment of radiance 1 (a 1x1 Radiance HDR),
// tone curve linear, `options` added: the mean of 5x5 pixels about the centre (n . v
// above 0.97). The environment is `width` x width / 2 texels (at least 1x1): the raster's
// 9 SH coefficients of a 1x1 image (one texel at the horizon) are not uniform, so a
// test of the irradiance (energy compensation) takes a wider one.
inline glm::dvec3 furnace_front(const std::string& model, const std::string& options,
                                int width = 1) {
    const std::string hdr = temp_path("sherpa_cli_furnace", "furnace.hdr");
    const std::string png = temp_path("sherpa_cli_furnace", "furnace.png");
    {
        std::ofstream out(hdr, std::ios::binary);
        const int height = std::max(width / 2, 1);
        out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
        for (int i = 0; i < width * height; ++i)
            out.write("\x80\x80\x80\x81", 4); // (128, 128, 128, exponent 129): 1
    }
    const CliRun r =
        run_cli("render '" + model + "' -o " + png + " --width 48 --height 36" + " --view lit" +
                options + " --camera eye=0,0,1.5:target=0,0,0:fov=45 --environment '" + hdr +
                "' --sun off --tone-map linear --exposure 0 --validation --no-cache");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    const Png p = read_png(png);
    std::filesystem::remove(png);
    std::filesystem::remove(hdr);
    glm::dvec3 sum(0.0);
    if (p.rgba.empty()) return sum;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                const double c = p.at(24 + x, 18 + y)[ch] / 255.0; // sRGB-encoded
                sum[ch] += c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
            }
    return sum / 25.0;
}

} // namespace sherpa::test
