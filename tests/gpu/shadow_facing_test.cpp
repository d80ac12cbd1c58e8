// Shadows follow the facing of the shaded side: a surface that nothing else can
// shadow is exactly as bright with shadows as without (no acne), on the back of a
// double-sided surface too, while real shadows still fall. Judged against the
// same render with shadows off, and against the analytic shadow of a hand-made
// scene (tests/data/make_shadow_scene.py), not against our own earlier output.
#include "gpu_test_support.h"

#include <sherpa/render/frame_request.h>
#include <sherpa/texture/image.h>

#include <glm/gtc/matrix_inverse.hpp>

namespace sherpa::test {
namespace {

// A pixel is darkened when shadows take more than this (of 255, mean of RGB) from it.
constexpr int kDarkened = 10;

bool darkened(const std::vector<std::uint8_t>& lit, const std::vector<std::uint8_t>& unshadowed,
              std::size_t pixel) {
    int with = 0, without = 0;
    for (int ch = 0; ch < 3; ++ch) {
        with += lit[pixel * 4 + ch];
        without += unshadowed[pixel * 4 + ch];
    }
    return (without - with) / 3 > kDarkened;
}

class ShadowFacingTest : public GpuTest {
protected:
    // Renders the scene with and without shadows (writes both next to the test binary
    // when asked, to be looked at).
    void render_pair(const scene::Scene& scene, render::FrameRequest s, const std::string& name) {
        renderer().load(scene);
        s.shadows = true;
        renderer().render(s, &lit_);
        s.shadows = false;
        renderer().render(s, &unshadowed_);
        renderer().unload();
        ASSERT_EQ(lit_.size(), std::size_t{s.width} * s.height * 4);
        if (std::getenv("SHERPA_WRITE_SHADOW_IMAGES")) {
            std::string error;
            tex::write_png("shadow_" + name + "_lit.png", s.width, s.height, lit_, error);
            tex::write_png("shadow_" + name + "_unshadowed.png", s.width, s.height, unshadowed_,
                           error);
        }
    }

    // Fraction of the pixels in [x0, x1) x [y0, y1) (rows from the top) that shadows darken.
    double darkened_fraction(std::uint32_t width, int x0, int y0, int x1, int y1) const {
        std::size_t n = 0, total = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x, ++total)
                n += darkened(lit_, unshadowed_, std::size_t(y) * width + std::size_t(x));
        return double(n) / double(total);
    }

    std::vector<std::uint8_t> lit_, unshadowed_;
};

TEST_F(ShadowFacingTest, DoubleSidedBackFaceLitFromItsSideShadowsOnlyWhereTheCasterDoes) {
    auto scene = load(std::string(SHERPA_TEST_DATA_DIR) + "/double_sided_shadow.gltf");
    ASSERT_TRUE(scene);
    constexpr std::uint32_t kSize = 200;
    render::FrameRequest s;
    s.width = s.height = kSize;
    // Behind the plane (its normal is +Z), with the sun on the camera's side at 45 degrees.
    // The caster, white and lit like the plane, does not stand out; its shadow does.
    const char* camera = "eye=0,0,-3:target=0,0,0:fov=50:aspect=1";
    std::string error;
    ASSERT_TRUE(render::parse_camera_spec(camera, s.camera, error)) << error;
    s.sun_direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));
    render_pair(*scene, s, "double_sided");

    scene::CameraSpec spec;
    ASSERT_TRUE(parse_camera_spec(camera, spec, error)) << error;
    const glm::mat4 inverse = glm::inverse(spec.view_projection());
    auto unproject = [&](float x, float y, float depth) {
        const glm::vec4 p = inverse * glm::vec4(x, y, depth, 1.0f);
        return glm::vec3(p) / p.w;
    };
    // Where the ray through each pixel meets plane z = `z`.
    auto hit = [&](std::uint32_t px, std::uint32_t py, float z) {
        const float x = (float(px) + 0.5f) / kSize * 2.0f - 1.0f;
        const float y = 1.0f - (float(py) + 0.5f) / kSize * 2.0f;
        const glm::vec3 a = unproject(x, y, 1.0f), b = unproject(x, y, 0.5f);
        return a + (b - a) * ((z - a.z) / (b.z - a.z));
    };
    auto inside = [](glm::vec3 p, float x0, float x1, float y0, float y1, float grow) {
        return p.x > x0 - grow && p.x < x1 + grow && p.y > y0 - grow && p.y < y1 + grow;
    };
    std::size_t shadow_total = 0, shadow_dark = 0, lit_total = 0, lit_dark = 0;
    for (std::uint32_t py = 0; py < kSize; ++py)
        for (std::uint32_t px = 0; px < kSize; ++px) {
            // Pixels of the caster itself, and near the plane's edge, are not judged.
            if (inside(hit(px, py, -0.5f), -0.3f, 0.3f, 0.4f, 0.8f, 0.03f)) continue;
            const glm::vec3 p = hit(px, py, 0.0f);
            if (!inside(p, -1.0f, 1.0f, -1.0f, 1.0f, -0.05f)) continue;
            // The caster's shadow along (0, -1, 1): x [-0.3, 0.3], y [-0.1, 0.3]; a band of
            // 0.05 around its edge (filtering, texel size) is not judged.
            const bool in_shadow = inside(p, -0.3f, 0.3f, -0.1f, 0.3f, -0.05f);
            const bool out_of_shadow = !inside(p, -0.3f, 0.3f, -0.1f, 0.3f, 0.05f);
            const bool dark = darkened(lit_, unshadowed_, std::size_t(py) * kSize + px);
            if (in_shadow) {
                ++shadow_total;
                shadow_dark += dark;
            } else if (out_of_shadow) {
                ++lit_total;
                lit_dark += dark;
            }
        }
    ASSERT_GT(shadow_total, 500u);
    ASSERT_GT(lit_total, 10000u);
    // No acne where nothing casts a shadow; the real shadow is there.
    EXPECT_LE(lit_dark, lit_total / 1000) << lit_dark << " of " << lit_total;
    EXPECT_GE(shadow_dark, shadow_total * 95 / 100) << shadow_dark << " of " << shadow_total;
}

TEST_F(ShadowFacingTest, TextureSettingsTestCellsAreNotShadowed) {
    auto scene = load(gltf_asset("TextureSettingsTest"));
    ASSERT_TRUE(scene);
    render::FrameRequest s;
    s.width = 400;
    s.height = 300;
    std::string error;
    // The single- and double-sided rows of the Test and Sample pass columns, face on.
    ASSERT_TRUE(render::parse_camera_spec("eye=1,2.5,8:target=1,2.5,0:fov=25", s.camera, error))
        << error;
    render_pair(*scene, s, "texture_settings");
    // Cell rectangles in that view (measured on the render), inset by a few pixels:
    // nothing lies between them and the default sun. The single-sided test hides a
    // wrong-way polygon in front of its cell (it may cast no shadow the camera could
    // not see cast), the double-sided one shows that polygon's back.
    const struct {
        const char* what;
        int x0, y0, x1, y1;
    } cells[] = {{"single-sided test", 122, 114, 186, 178},
                 {"double-sided test", 122, 202, 186, 266},
                 {"single-sided sample", 302, 114, 366, 178},
                 {"double-sided sample", 302, 202, 366, 266}};
    for (const auto& c : cells)
        EXPECT_LE(darkened_fraction(s.width, c.x0, c.y0, c.x1, c.y1), 0.001) << c.what;
    // The labels and cells still cast their drop shadows onto the board.
    EXPECT_GT(darkened_fraction(s.width, 0, 0, int(s.width), int(s.height)), 0.03);
}

} // namespace
} // namespace sherpa::test
