// The path tracer (render --renderer rt --view lit, docs/path_tracer.md): its CPU
// parts (the environment's sampling density, the error estimate) against closed forms;
// on lavapipe under the validation layer the white furnace, agreement with the raster
// where the two must agree (metal in a uniform environment, where split-sum is exact),
// determinism, progressive accumulation equal to one-shot, and error falling as
// 1/sqrt(spp). Small images: lavapipe traces on the CPU.
#include "gpu_test_support.h"
#include "path_trace_renderer.h"
#include "sphere_scenes.h"

#include <sherpa/render/path_trace.h>

#include <cmath>
#include <cstdio>

namespace sherpa::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ∫ pdf dω over the sphere, by the midpoint rule on a fine (theta, phi) grid.
double integrate_pdf(const render::EnvironmentDistribution& d) {
    const int rows = 512, cols = 1024;
    double sum = 0.0;
    for (int r = 0; r < rows; ++r) {
        const double theta = kPi * (r + 0.5) / rows;
        for (int c = 0; c < cols; ++c) {
            const double phi = 2.0 * kPi * (c + 0.5) / cols - kPi;
            const glm::vec3 dir(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                float(std::sin(theta) * std::sin(phi)));
            sum += render::environment_pdf(d, dir) * std::sin(theta) * (kPi / rows) *
                   (2.0 * kPi / cols);
        }
    }
    return sum;
}

TEST(PathTraceCpu, EnvironmentDistributionIsADensityThatFollowsLuminance) {
    const render::EnvironmentDistribution room =
        render::environment_distribution(render::room_environment());
    ASSERT_FALSE(room.empty());
    EXPECT_LE(room.width, render::kEnvironmentDistributionWidth);
    EXPECT_NEAR(integrate_pdf(room), 1.0, 0.01);
    // A uniform environment is sampled uniformly over the sphere: 1 / 4pi everywhere.
    const render::EnvironmentDistribution uniform =
        render::environment_distribution(render::uniform_environment(glm::vec3(2.0f)));
    for (const glm::vec3 d :
         {glm::vec3(1, 0, 0), glm::vec3(0, 0.8f, 0.6f), glm::vec3(0, -0.6f, 0.8f)})
        EXPECT_NEAR(render::environment_pdf(uniform, d) * 4.0 * kPi, 1.0, 0.02);
    // One bright texel takes (almost) all the density.
    render::EnvironmentImage spot = render::uniform_environment(glm::vec3(0.0f), 64);
    spot.rgba[(8 * 64 + 16) * 4 + 1] = 100.0f; // row 8 (elevation ~ 62°), column 16 (-Z)
    const render::EnvironmentDistribution s = render::environment_distribution(spot);
    ASSERT_FALSE(s.empty());
    const double theta = kPi * 8.5 / 32.0, phi = 2.0 * kPi * (16.5 / 64.0 - 0.5);
    const glm::vec3 at(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                       float(std::sin(theta) * std::sin(phi)));
    const double texel_solid_angle = (2.0 * kPi / 64.0) * (kPi / 32.0) * std::sin(theta);
    EXPECT_NEAR(render::environment_pdf(s, at) * texel_solid_angle, 1.0, 0.01);
    EXPECT_EQ(render::environment_pdf(s, glm::vec3(0, -1, 0)), 0.0f);
    // Nothing to sample: black, NaN or empty images give an empty distribution.
    EXPECT_TRUE(
        render::environment_distribution(render::uniform_environment(glm::vec3(0.0f))).empty());
    render::EnvironmentImage nan = render::uniform_environment(glm::vec3(NAN), 16);
    EXPECT_TRUE(render::environment_distribution(nan).empty());
    EXPECT_TRUE(render::environment_distribution(render::EnvironmentImage{}).empty());
}

TEST(PathTraceCpu, ErrorEstimateIsTheStandardErrorOfEachPixelMean) {
    render::PathTraceImage image;
    image.width = 2;
    image.height = 1;
    image.samples = 4;
    // Pixel 0: samples of luminance 0, 0, 2, 2 (grey): mean 1, sample variance 4/3.
    // Pixel 1: four samples of 3: no variance.
    image.sums = {4, 4, 4, 4, 12, 12, 12, 4};
    image.moments = {8, 36};
    const render::PathTraceError e = render::estimate_error(image);
    const double se0 = std::sqrt(4.0 / 3.0 / 4.0);
    EXPECT_NEAR(e.mean_luminance, 2.0, 1e-5);
    EXPECT_NEAR(e.mean_standard_error, se0 / 2.0, 1e-5);
    EXPECT_NEAR(e.rms_standard_error, std::sqrt(se0 * se0 / 2.0), 1e-5);
    EXPECT_NEAR(e.relative_error, se0 / 4.0, 1e-5);
    image.samples = 0;
    EXPECT_EQ(render::estimate_error(image).mean_standard_error, 0.0);
}

// The directional albedo of brdf.glsl's BRDF for a white metal (F0 = 1, so F = 1) at
// n.v = mu and perceptual roughness r, ∫ D V (n.l) dω by the midpoint rule, averaged over
// a sphere's silhouette disc seen from far away (mu has density 2 mu there): what a
// white metal sphere in a uniform environment of radiance 1 reflects on average.
double metal_sphere_albedo(double roughness) {
    const double a = std::max(roughness * roughness, 1e-3), a2 = a * a;
    const int mus = 32, thetas = 256, phis = 256;
    double disc = 0.0;
    for (int m = 0; m < mus; ++m) {
        const double mu = (m + 0.5) / mus;
        const glm::dvec3 v(std::sqrt(1.0 - mu * mu), 0.0, mu);
        double e = 0.0;
        for (int t = 0; t < thetas; ++t) {
            const double theta = 0.5 * kPi * (t + 0.5) / thetas, nl = std::cos(theta);
            for (int p = 0; p < phis; ++p) {
                const double phi = 2.0 * kPi * (p + 0.5) / phis;
                const glm::dvec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                   nl);
                const double nh = glm::normalize(l + v).z;
                const double d = nh * nh * (a2 - 1.0) + 1.0;
                const double D = a2 / (kPi * d * d);
                const double V = 0.5 / (nl * std::sqrt(mu * mu * (1.0 - a2) + a2) +
                                        mu * std::sqrt(nl * nl * (1.0 - a2) + a2));
                e += D * V * nl * std::sin(theta) * (0.5 * kPi / thetas) * (2.0 * kPi / phis);
            }
        }
        disc += e * 2.0 * mu / mus;
    }
    return disc;
}

// One ray-tracing renderer for the GPU tests of this binary.
class PathTraceTest : public GpuTest {
protected:
    static render::Renderer& rt() { return path_trace_renderer(); }
    static void TearDownTestSuite() { rt().unload(); }

    // A row of `count` white unit spheres (roughness i / (count - 1)), 48 px apart,
    // seen from far away; linear tone mapping at -1 EV on a black background.
    render::FrameRequest sphere_row(int count, float metallic, const char* name) {
        auto scene = load(write_temp(name, sphere_row_gltf(count, metallic, 96)).string());
        rt().load(*scene);
        render::FrameRequest s = furnace_view(count, 48);
        s.renderer = render::RendererKind::RayTraced;
        s.path.restart = true;
        return s;
    }

    // Mean red radiance of sphere `index` over the pixels every sample of which hit it.
    static double sphere_mean(const render::PathTraceImage& img, std::uint32_t index) {
        double sum = 0.0;
        int n = 0;
        for (std::uint32_t y = 0; y < img.height; ++y)
            for (std::uint32_t x = 48 * index; x < 48 * (index + 1); ++x) {
                const float* p = &img.sums[(std::size_t(y) * img.width + x) * 4];
                if (p[3] < float(img.samples)) continue; // an edge or the background
                sum += p[0] / img.samples;
                ++n;
            }
        EXPECT_GT(n, 600) << "sphere " << index;
        return sum / std::max(n, 1);
    }

    // Sums of the frame of `s` with every sphere but `index` hidden (a sphere in the
    // furnace must not see its neighbours).
    render::PathTraceImage alone(render::FrameRequest s, std::uint32_t index, std::uint32_t count) {
        auto hidden = std::make_shared<std::vector<bool>>(count, true);
        (*hidden)[index] = false;
        rt().set_hidden_nodes(hidden);
        rt().render(s);
        render::PathTraceImage image = render::read_path_trace(rt());
        rt().set_hidden_nodes(nullptr); // the next frame shows every sphere again
        return image;
    }

    // Mean red radiance of each sphere in a raster frame (8-bit sRGB at -1 EV).
    static std::vector<double> raster_means(const std::vector<std::uint8_t>& rgba,
                                            std::uint32_t width, int count) {
        std::vector<double> sum(count, 0.0);
        std::vector<int> n(count, 0);
        for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
            if (rgba[i] == 0) continue;
            const double c = rgba[i] / 255.0;
            const double linear = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
            sum[(i / 4 % width) / 48] += 2.0 * linear;
            ++n[(i / 4 % width) / 48];
        }
        for (int i = 0; i < count; ++i) sum[i] /= std::max(n[i], 1);
        return sum;
    }
};

struct RemoveEnvironment {
    render::Renderer& r;
    ~RemoveEnvironment() { r.set_environment(nullptr); }
};

// A white sphere in a uniform environment of radiance 1: a mirror metal reflects
// exactly 1. Rougher metals reflect GGX's single-scattering albedo (brdf.glsl has no
// multiple scattering), integrated here on the CPU from the BRDF's definition. The
// raster's split-sum without energy compensation (its lookup table) is printed beside.
TEST_F(PathTraceTest, FurnaceMatchesOneForAMirrorAndTheAlbedoOfRoughMetal) {
    RemoveEnvironment guard{rt()};
    const render::EnvironmentImage uniform = render::uniform_environment(glm::vec3(1.0f));
    rt().set_environment(&uniform);
    constexpr std::uint32_t kCount = 3; // roughness 0, 0.5, 1
    for (const float metallic : {1.0f, 0.0f}) {
        render::FrameRequest s =
            sphere_row(kCount, metallic, metallic > 0 ? "pt_metal.gltf" : "pt_dielectric.gltf");
        s.path.samples = 64;
        std::vector<double> pt;
        for (std::uint32_t i = 0; i < kCount; ++i) {
            const render::PathTraceImage img = alone(s, i, kCount);
            ASSERT_EQ(img.samples, 64u);
            pt.push_back(sphere_mean(img, i));
        }
        s.renderer = render::RendererKind::Raster;
        s.energy_compensation = false;
        std::vector<std::uint8_t> rgba;
        rt().render(s, &rgba);
        const std::vector<double> raster = raster_means(rgba, s.width, kCount);
        for (std::uint32_t i = 0; i < kCount; ++i) {
            // The quadrature cannot resolve a mirror's lobe: it reflects 1 by definition.
            const double reference =
                metallic > 0 && i > 0 ? metal_sphere_albedo(i / (kCount - 1.0)) : 1.0;
            std::printf("furnace %s roughness %.1f: path traced %.4f, reference %.4f, raster (no "
                        "compensation) %.4f\n",
                        metallic > 0 ? "metal" : "dielectric", i / (kCount - 1.0), pt[i], reference,
                        raster[i]);
            if (metallic > 0) {
                EXPECT_NEAR(pt[i], reference, 0.02) << i;
            }
        }
        if (metallic > 0) {
            EXPECT_NEAR(pt[0], 1.0, 0.01);
            EXPECT_LT(pt[2], 0.9); // single scattering loses energy at roughness 1
        } else {
            // The glTF BRDF's white dielectric (Fresnel-weighted Lambert + GGX) is not
            // exactly energy-conserving: stated tolerance 3% of 1.
            for (std::uint32_t i = 0; i < kCount; ++i) EXPECT_NEAR(pt[i], 1.0, 0.03) << i;
        }
    }
}

// The same seed and sample count give the same bytes; samples added frame by frame
// give the same sums as all at once; the estimated error halves when spp quadruples.
TEST_F(PathTraceTest, DeterministicProgressiveAndErrorFallsAsOneOverRootSpp) {
    RemoveEnvironment guard{rt()};
    const render::EnvironmentImage room = render::room_environment(256);
    rt().set_environment(&room);
    render::FrameRequest s = sphere_row(3, 0.0f, "pt_room.gltf");
    s.tone_map = render::ToneMap::Neutral;
    s.exposure = 0.0f;
    s.sun = true; // a sun with its angular radius, traced shadows
    s.background = render::Background::Environment;
    s.path.samples = 16;
    std::vector<std::uint8_t> a, b;
    rt().render(s, &a);
    const render::PathTraceImage once = render::read_path_trace(rt());
    rt().render(s, &b);
    EXPECT_EQ(a, b);
    EXPECT_EQ(once.sums, render::read_path_trace(rt()).sums);
    s.path.seed = 7;
    rt().render(s, &b);
    EXPECT_NE(a, b);
    s.path.seed = 0;

    // 4 + 12 samples progressively (nothing changes between the frames).
    s.path.samples = 4;
    render::FrameStats f = rt().render(s);
    EXPECT_TRUE(f.path.restarted);
    const render::PathTraceError e4 = render::path_trace_error(rt());
    s.path.restart = false;
    s.path.samples = 12;
    f = rt().render(s);
    EXPECT_FALSE(f.path.restarted);
    EXPECT_EQ(f.path.samples, 16u);
    EXPECT_EQ(f.path.added, 12u);
    const render::PathTraceImage progressive = render::read_path_trace(rt());
    EXPECT_EQ(progressive.sums, once.sums);
    EXPECT_EQ(progressive.moments, once.moments);
    const render::PathTraceError e16 = estimate_error(progressive);
    s.path.samples = 48;
    rt().render(s);
    const render::PathTraceError e64 = render::path_trace_error(rt());
    std::printf("estimated error (relative): 4 spp %.5f, 16 spp %.5f, 64 spp %.5f\n",
                e4.relative_error, e16.relative_error, e64.relative_error);
    EXPECT_NEAR(e4.mean_standard_error / e16.mean_standard_error, 2.0, 0.4);
    EXPECT_NEAR(e16.mean_standard_error / e64.mean_standard_error, 2.0, 0.3);
    // A change starts over.
    s.exposure = 1.0f;
    f = rt().render(s);
    EXPECT_TRUE(f.path.restarted);
    EXPECT_EQ(f.path.samples, 48u);
}

} // namespace
} // namespace sherpa::test
