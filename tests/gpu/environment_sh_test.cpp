// SH9 irradiance (environment_sh.h) against closed forms: a constant environment's
// irradiance / pi is the constant, a linear one's (a + b.w) is a + 2/3 b.n; both are
// exact in bands 0-1, so only the texel quadrature is left.
#include "sphere_scenes.h"

#include <sherpa/render/environment_sh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace sherpa::test {
namespace {

using test::environment_of;

std::vector<glm::vec3> directions() {
    std::vector<glm::vec3> out;
    for (int i = 0; i < 64; ++i) {
        // A Fibonacci sphere: every region of the sphere, the poles and seams among them.
        const float y = 1.0f - 2.0f * (float(i) + 0.5f) / 64.0f;
        const float r = std::sqrt(1.0f - y * y), phi = 2.39996323f * float(i);
        out.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
    }
    for (const glm::vec3 axis : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                                 glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)})
        out.push_back(axis);
    return out;
}

TEST(EnvironmentSh9, ConstantRadianceGivesItsIrradianceEverywhere) {
    const glm::vec3 c(0.5f, 1.0f, 2.0f);
    const render::Sh9 sh = render::irradiance_sh9(
        render::project_sh9(environment_of(256, [&](glm::vec3) { return c; })));
    for (const glm::vec3 n : directions()) {
        const glm::vec3 e = render::evaluate_sh9(sh, n);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[k], c[k], 1e-3f * c[k]) << n.x << n.y << n.z;
    }
    // Bands 1 and 2 of a constant are zero.
    for (int k = 1; k < 9; ++k) EXPECT_NEAR(glm::length(sh[k]), 0.0f, 1e-4f) << k;
}

TEST(EnvironmentSh9, TinyConstantImagesAreIntegratedExactly) {
    // Each texel is integrated over its patch of the sphere, not sampled at its centre:
    // a 1x1 image (one texel for the whole sphere) must give the same irradiance as a
    // large one. The centre-sample rule gave 0.45 of it at the poles for 1x1.
    const glm::vec3 c(1.0f, 0.25f, 3.0f);
    for (const auto& [w, h] : {std::pair{1u, 1u}, std::pair{2u, 1u}, std::pair{1u, 2u},
                               std::pair{3u, 2u}, std::pair{4u, 2u}, std::pair{5u, 3u}}) {
        render::EnvironmentImage image;
        image.width = w;
        image.height = h;
        image.rgba.assign(std::size_t(4) * w * h, 1.0f);
        for (std::size_t t = 0; t < std::size_t(w) * h; ++t)
            for (int k = 0; k < 3; ++k) image.rgba[4 * t + k] = c[k];
        const render::Sh9 sh = render::irradiance_sh9(render::project_sh9(image));
        for (const glm::vec3 n : directions()) {
            const glm::vec3 e = render::evaluate_sh9(sh, n);
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(e[k], c[k], 1e-4f * c[k])
                    << w << "x" << h << " at " << n.x << " " << n.y << " " << n.z;
        }
    }
}

TEST(EnvironmentSh9, LinearRadianceGivesTwoThirdsOfItsGradient) {
    // L(w) = a + b.w per channel, b along a different axis per channel, so that the
    // image convention (u from atan2(z, x), v from asin(y)) is checked on every axis.
    const glm::vec3 a(1.0f, 1.0f, 1.0f);
    const glm::vec3 bx(0.8f, 0.0f, 0.0f), by(0.0f, 0.6f, 0.0f), bz(0.0f, 0.0f, -0.7f);
    const render::Sh9 sh =
        render::irradiance_sh9(render::project_sh9(environment_of(512, [&](glm::vec3 d) {
            return a + glm::vec3(glm::dot(bx, d), glm::dot(by, d), glm::dot(bz, d));
        })));
    for (const glm::vec3 n : directions()) {
        const glm::vec3 exact =
            a + (2.0f / 3.0f) * glm::vec3(glm::dot(bx, n), glm::dot(by, n), glm::dot(bz, n));
        const glm::vec3 e = render::evaluate_sh9(sh, n);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(e[k], exact[k], 2e-3f) << n.x << " " << n.y << " " << n.z;
    }
}

TEST(EnvironmentSh9, ClampedCosineLightIsWithinTheKnownBandLimitError) {
    // L = max(0, w.y): irradiance / pi at n = +Y is the integral of cos^2 over the upper
    // hemisphere / pi = 2/3; at n = -Y it is 0. Band 2 keeps most of it: the error of the
    // 9 coefficients is a few hundredths (the clamped cosine's bands above 2).
    const render::Sh9 sh = render::irradiance_sh9(render::project_sh9(
        environment_of(512, [](glm::vec3 d) { return glm::vec3(std::max(0.0f, d.y)); })));
    const float up = render::evaluate_sh9(sh, glm::vec3(0, 1, 0)).g;
    const float down = render::evaluate_sh9(sh, glm::vec3(0, -1, 0)).g;
    const float side = render::evaluate_sh9(sh, glm::vec3(1, 0, 0)).g;
    // At the horizon, n = +X: the integral of w.y w.x over the quarter sphere where both
    // are positive is 4/3 * 1/2, so irradiance / pi is 2 / (3 pi).
    std::printf("SH9 clamped cosine: up %.4f (2/3), down %.4f (0), side %.4f (%.4f)\n", up, down,
                side, 2.0 / (3.0 * 3.14159265));
    EXPECT_NEAR(up, 2.0f / 3.0f, 0.03f);
    EXPECT_NEAR(down, 0.0f, 0.03f);
    EXPECT_NEAR(side, 2.0f / (3.0f * 3.14159265f), 0.03f);
}

TEST(EnvironmentSh9, NonFiniteTexelsCountAsBlackAndInvalidImagesGiveZero) {
    render::EnvironmentImage image = environment_of(64, [](glm::vec3) { return glm::vec3(1.0f); });
    const render::Sh9 clean = render::project_sh9(image);
    image.rgba[0] = std::numeric_limits<float>::quiet_NaN();
    image.rgba[5] = std::numeric_limits<float>::infinity();
    const render::Sh9 dirty = render::project_sh9(image);
    for (int k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(std::isfinite(dirty[k][c]));
            EXPECT_NEAR(dirty[k][c], clean[k][c], 1e-2f);
        }
    const render::Sh9 none = render::project_sh9(render::EnvironmentImage{});
    for (const glm::vec3& c : none) EXPECT_EQ(c, glm::vec3(0.0f));
}

TEST(EnvironmentSh9, ModesParseBothWays) {
    for (const auto m : {render::IrradianceMode::Cube, render::IrradianceMode::Sh9})
        EXPECT_EQ(render::parse_irradiance_mode(to_string(m)), m);
    EXPECT_FALSE(render::parse_irradiance_mode("sh4").has_value());
}

} // namespace
} // namespace sherpa::test
