// Rays as ground truth (issue 17, item 7): the ray tracer's shadow and ambient-
// occlusion views against answers worked out by hand on a hand-made scene
// (tests/data/double_sided_shadow.gltf: a 2x2 plane at z = 0 and a 0.6x0.4 caster quad
// at z = -0.5 over x [-0.3, 0.3], y [0.4, 0.8], both double-sided), and the
// rasterizer's cascaded shadow maps against the rays.
#include "gpu_test_support.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/render/shadow_error.h>

namespace sherpa::test {
namespace {

constexpr std::uint32_t kShadowImageSize = 96;
// Behind the plane, the sun on the camera's side travelling along (0, -1, 1): the
// caster's shadow on the plane is x [-0.3, 0.3], y [-0.1, 0.3].
constexpr const char* kCamera = "eye=0,0,-3:target=0,0,0:fov=50:aspect=1";

class RtShadow : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
        scene_ = load(std::string(SHERPA_TEST_DATA_DIR) + "/double_sided_shadow.gltf");
        ASSERT_TRUE(scene_);
        std::string error;
        ASSERT_TRUE(render::parse_camera_spec(kCamera, settings_.camera, error)) << error;
        ASSERT_TRUE(parse_camera_spec(kCamera, spec_, error)) << error;
        settings_.width = settings_.height = kShadowImageSize;
        settings_.sun_direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));
        settings_.view = render::DebugView::Shadow;
        settings_.renderer = render::RendererKind::RayTraced;
    }

    std::unique_ptr<render::Renderer> make_renderer(std::uint32_t shadow_resolution = 2048) {
        render::RendererOptions options;
        options.ray_tracing = true;
        options.shadow_resolution = shadow_resolution;
        auto r = std::make_unique<render::Renderer>(context(), options);
        r->load(*scene_);
        return r;
    }

    // Where the ray through pixel (px, py) meets plane z = `z`.
    glm::vec3 hit(std::uint32_t px, std::uint32_t py, float z) const {
        const glm::mat4 inverse = glm::inverse(spec_.view_projection());
        const float x = (float(px) + 0.5f) / kShadowImageSize * 2.0f - 1.0f;
        const float y = 1.0f - (float(py) + 0.5f) / kShadowImageSize * 2.0f;
        auto unproject = [&](float depth) {
            const glm::vec4 p = inverse * glm::vec4(x, y, depth, 1.0f);
            return glm::vec3(p) / p.w;
        };
        const glm::vec3 a = unproject(1.0f), b = unproject(0.5f);
        return a + (b - a) * ((z - a.z) / (b.z - a.z));
    }

    // -1: not judged (the caster, off the plane); 0 shadowed, 1 lit, by the analytic outline.
    int expected(std::uint32_t px, std::uint32_t py) const {
        const glm::vec3 c = hit(px, py, -0.5f);
        if (c.x > -0.3f && c.x < 0.3f && c.y > 0.4f && c.y < 0.8f) return -1;
        const glm::vec3 p = hit(px, py, 0.0f);
        if (std::abs(p.x) > 1.0f || std::abs(p.y) > 1.0f) return -1;
        return p.x > -0.3f && p.x < 0.3f && p.y > -0.1f && p.y < 0.3f ? 0 : 1;
    }

    // Whether every neighbour of (px, py) has the same expected class (outside the 1-px band).
    bool inside_band(std::uint32_t px, std::uint32_t py) const {
        const int e = expected(px, py);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = int(px) + dx, y = int(py) + dy;
                if (x < 0 || y < 0 || x >= int(kShadowImageSize) || y >= int(kShadowImageSize))
                    return false;
                if (expected(std::uint32_t(x), std::uint32_t(y)) != e) return false;
            }
        return true;
    }

    std::vector<std::uint8_t> render(render::Renderer& r, const render::FrameRequest& s) {
        std::vector<std::uint8_t> rgba;
        r.render(s, &rgba);
        EXPECT_EQ(rgba.size(), std::size_t{kShadowImageSize} * kShadowImageSize * 4);
        return rgba;
    }

    // Pixels strictly between lit and shadowed (greys; the clear colour is not grey).
    static std::size_t grey(const std::vector<std::uint8_t>& rgba) {
        std::size_t n = 0;
        for (std::size_t p = 0; p < rgba.size(); p += 4)
            n += rgba[p] == rgba[p + 2] && rgba[p] > 2 && rgba[p] < 253;
        return n;
    }

    std::unique_ptr<scene::Scene> scene_;
    render::FrameRequest settings_;
    scene::CameraSpec spec_; // the scene layer's, for its view-projection
};

TEST_F(RtShadow, HardShadowMatchesTheProjectedOutline) {
    auto r = make_renderer();
    const auto rgba = render(*r, settings_);
    std::size_t judged = 0, shadowed = 0, wrong = 0;
    for (std::uint32_t y = 0; y < kShadowImageSize; ++y)
        for (std::uint32_t x = 0; x < kShadowImageSize; ++x) {
            const int e = expected(x, y);
            if (e < 0 || !inside_band(x, y)) continue;
            const std::uint8_t v = rgba[(std::size_t(y) * kShadowImageSize + x) * 4];
            ++judged;
            shadowed += e == 0;
            wrong += v != (e ? 255 : 0);
        }
    EXPECT_GT(judged, 3000u);
    EXPECT_GT(shadowed, 150u);
    EXPECT_EQ(wrong, 0u) << "of " << judged << " pixels outside the 1-px band";
}

TEST_F(RtShadow, SoftShadowPenumbraWidensWithTheSunsRadius) {
    auto r = make_renderer();
    const auto hard = render(*r, settings_);
    render::FrameRequest s = settings_;
    s.shadow_rays = 16;
    s.sun_angular_radius = 0.0f;
    EXPECT_EQ(render(*r, s), hard) << "a point sun with 16 rays is the hard shadow";
    std::size_t previous = grey(hard);
    EXPECT_EQ(previous, 0u);
    for (float radius : {0.03f, 0.1f, 0.25f}) {
        s.sun_angular_radius = radius;
        const auto soft = render(*r, s);
        EXPECT_GT(grey(soft), previous) << "radius " << radius;
        previous = grey(soft);
        EXPECT_EQ(render(*r, s), soft) << "reproducible, radius " << radius;
    }
}

TEST_F(RtShadow, AmbientOcclusionIsOneInTheOpenAndLessUnderTheCaster) {
    auto r = make_renderer();
    render::FrameRequest s = settings_;
    s.view = render::DebugView::AmbientOcclusion;
    s.ao_rays = 32;
    s.ao_radius = 2.0f;
    // The plane's front (+Z): nothing in its hemisphere, every ray escapes.
    std::string error;
    ASSERT_TRUE(
        render::parse_camera_spec("eye=0,0,3:target=0,0,0:fov=50:aspect=1", s.camera, error));
    const auto open = render(*r, s);
    std::size_t plane = 0;
    for (std::size_t p = 0; p < open.size(); p += 4)
        if (open[p] == open[p + 1] && open[p] != open[0]) { // not the clear colour
            ++plane;
            EXPECT_EQ(open[p], 255) << "pixel " << p / 4;
        }
    EXPECT_GT(plane, 3000u);
    // Its back: the caster 0.5 away fills part of the hemisphere of the points beside it.
    s.camera = settings_.camera;
    const auto back = render(*r, s);
    const std::size_t below =
        (std::size_t(kShadowImageSize / 2 - 6) * kShadowImageSize + kShadowImageSize / 2) *
        4; // y ~ 0.2
    EXPECT_LT(back[below], 245) << "AO under the caster";
    EXPECT_GT(back[below], 20);
    const std::size_t corner =
        (std::size_t(kShadowImageSize - 24) * kShadowImageSize + 24) * 4; // (+-0.7, -0.7)
    EXPECT_EQ(back[corner], back[corner + 2]) << "the plane, not the clear colour";
    EXPECT_GT(back[corner], back[below]) << "farther from the caster, less occluded";
}

// Maps against the rays: at 4096 texels they agree on most pixels; at 128 they
// miss part of the outline. Either way the shadow-error view counts exactly the
// pixels where the two `shadow` images disagree (thresholded at 0.5).
TEST_F(RtShadow, CascadesAgreeWithRaysAndTheErrorViewCountsTheDifference) {
    for (std::uint32_t resolution : {4096u, 128u}) {
        auto r = make_renderer(resolution);
        render::FrameRequest s = settings_;
        s.shadow_pcf_taps = 1;
        const auto rays = render(*r, s);
        s.renderer = render::RendererKind::Raster;
        const auto maps = render(*r, s);
        std::size_t covered = 0, lit = 0, disagree = 0;
        for (std::size_t p = 0; p < rays.size(); p += 4) {
            if (rays[p] != rays[p + 2] || maps[p] != maps[p + 2]) continue; // clear colour
            ++covered;
            const bool rays_lit = rays[p] >= 128, maps_lit = maps[p] >= 128;
            lit += rays_lit;
            disagree += rays_lit != maps_lit;
        }
        ASSERT_GT(lit, 2000u);
        if (resolution == 4096)
            EXPECT_LE(disagree, lit / 50) << disagree << " of " << lit << " lit pixels";
        else
            EXPECT_GT(disagree, 0u) << "128 texels over the scene must miss some pixels";
        s.renderer = render::RendererKind::RayTraced;
        s.view = render::DebugView::ShadowError;
        const render::ShadowErrorCounts n = render::count_shadow_error(render(*r, s));
        std::printf("shadow-error at %u: lit %llu agree-shadowed %llu false-shadow %llu "
                    "false-light %llu (image compare: %zu of %zu lit)\n",
                    resolution, (unsigned long long)n.agree_lit,
                    (unsigned long long)n.agree_shadowed, (unsigned long long)n.false_shadow,
                    (unsigned long long)n.false_light, disagree, lit);
        EXPECT_EQ(n.lit(), lit) << resolution;
        EXPECT_EQ(n.wrong(), disagree) << resolution;
        EXPECT_EQ(n.agree_lit + n.agree_shadowed + n.wrong(), covered) << resolution;
    }
}

TEST_F(RtShadow, RasterRefusesRaysOnlyViews) {
    auto r = make_renderer();
    render::FrameRequest s = settings_;
    s.renderer = render::RendererKind::Raster;
    for (render::DebugView v :
         {render::DebugView::AmbientOcclusion, render::DebugView::ShadowError}) {
        s.view = v;
        std::vector<std::uint8_t> rgba;
        EXPECT_THROW(r->render(s, &rgba), gpu::GpuError) << to_string(v);
    }
}

} // namespace
} // namespace sherpa::test
