// Auto framing (`--camera auto`, the editor's load and Frame all) over every sample
// model: every corner of the scene bounds inside the frustum, the eye outside the
// bounds with a margin and above their top (so a box shows its top face), filling
// most of the view, for tall, square and wide viewports. No GPU needed.
#include "test_support.h"

#include <sherpa/render/camera.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

namespace sherpa::test {
namespace {

glm::vec3 corner(const core::Aabb& b, int i) {
    return {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
}

// Distance from p to the box (0 inside).
float distance_to_box(const core::Aabb& b, glm::vec3 p) {
    return glm::length(glm::max(glm::max(b.min - p, p - b.max), glm::vec3(0.0f)));
}

void expect_framed(const core::Aabb& b, const render::CameraView& v, const std::string& what) {
    const glm::mat4 vp = v.proj * v.view;
    float widest = 0.0f; // the largest |x| or |y| of a corner in NDC
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 c = vp * glm::vec4(corner(b, i), 1.0f);
        ASSERT_GT(c.w, 0.0f) << what << " corner " << i;
        widest = std::max({widest, std::abs(c.x / c.w), std::abs(c.y / c.w)});
        EXPECT_LE(std::abs(c.x / c.w), 1.0f) << what << " corner " << i;
        EXPECT_LE(std::abs(c.y / c.w), 1.0f) << what << " corner " << i;
        // Reverse-Z: in front of the near plane (depth <= 1) and before the far one.
        EXPECT_GT(c.z / c.w, 0.0f) << what << " corner " << i;
        EXPECT_LE(c.z / c.w, 1.0f) << what << " corner " << i;
    }
    // Framed, not just inside: tall flat panels (RiggedSimple, TextureSettingsTest) are
    // the loosest, as the eye rises above their top; 0.95 where the fit decides.
    EXPECT_GE(widest, 0.75f) << what;
    const float radius = 0.5f * glm::length(b.extent());
    EXPECT_GE(distance_to_box(b, v.position), 0.049f * radius) << what << ": eye in or at the box";
    EXPECT_GT(v.position.y, b.max.y) << what << ": eye below the top of the box";
}

TEST(AutoFramingTest, EverySampleModelIsInViewFromOutsideAndAbove) {
    const auto models = all_gltf_models();
    ASSERT_GE(models.size(), 20u);
    for (const auto& name : models) {
        const scene::LoadResult r = scene::load_scene(gltf_asset(name));
        ASSERT_TRUE(r) << name << ": " << r.error;
        ASSERT_TRUE(r.scene->bounds.valid()) << name;
        for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f, 3.0f}) {
            const render::CameraView v =
                render::resolve_camera(render::CameraSpec{}, *r.scene, aspect);
            expect_framed(r.scene->bounds, v, name + " aspect " + std::to_string(aspect));
        }
    }
}

TEST(AutoFramingTest, LooksAtTheThinnerSideAsTheFrontFromThreeQuartersAbove) {
    // Wide across X (shoulders), thin along Z: the front is +Z.
    const glm::vec3 z_front =
        scene::auto_view_direction(core::Aabb::from_min_max({-1, 0, -0.2f}, {1, 2, 0.2f}));
    EXPECT_GT(z_front.z, std::abs(z_front.x));
    // Thin along X: the model faces +X and is not seen in profile.
    const glm::vec3 x_front =
        scene::auto_view_direction(core::Aabb::from_min_max({-0.2f, 0, -1}, {0.2f, 2, 1}));
    EXPECT_GT(x_front.x, std::abs(x_front.z));
    for (glm::vec3 d : {z_front, x_front}) {
        // Raised (elevation 20..35 degrees) and off the axis (a 3/4 view: both horizontal
        // components at least sin(20 degrees) of the horizontal direction).
        EXPECT_NEAR(glm::degrees(std::asin(d.y)), 27.5f, 7.5f);
        const glm::vec2 h = glm::normalize(glm::vec2(d.x, d.z));
        EXPECT_GT(std::abs(h.x), 0.34f);
        EXPECT_GT(std::abs(h.y), 0.34f);
    }
    // A hint wins over the extents.
    const glm::vec3 hinted = scene::auto_view_direction(
        core::Aabb::from_min_max({-1, 0, -0.2f}, {1, 2, 0.2f}), {-1, 0, 0});
    EXPECT_LT(hinted.x, -std::abs(hinted.z));
}

TEST(AutoFramingTest, FramingAlongAGivenDirectionKeepsItAndFits) {
    // What the editor's Frame selection does: keep the viewing direction.
    const core::Aabb box = core::Aabb::from_min_max({-3, -1, -2}, {5, 4, 1});
    const glm::vec3 to_eye = glm::normalize(glm::vec3(-1.0f, -0.8f, 2.0f));
    scene::FramingOptions options;
    options.aspect = 1.5f;
    const scene::CameraSpec s = scene::frame_box_along(box, to_eye, options);
    EXPECT_NEAR(glm::dot(glm::normalize(s.eye - s.target), to_eye), 1.0f, 1e-5f);
    render::CameraView v;
    v.view = s.view();
    v.proj = s.projection();
    v.position = s.eye;
    // Looking up from below: the eye stays below the box instead of above it.
    const glm::mat4 vp = v.proj * v.view;
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 c = vp * glm::vec4(corner(box, i), 1.0f);
        EXPECT_LE(std::abs(c.x / c.w), 1.0f) << i;
        EXPECT_LE(std::abs(c.y / c.w), 1.0f) << i;
        EXPECT_GT(c.z / c.w, 0.0f) << i;
        EXPECT_LE(c.z / c.w, 1.0f) << i;
    }
    EXPECT_LT(s.eye.y, box.min.y);
    EXPECT_GE(distance_to_box(box, s.eye), 0.049f * 0.5f * glm::length(box.extent()));
}

// Fitting points: for any direction and aspect, every point inside the frustum, the
// tighter axis spanning exactly `fill` of the view and both axes centred (the
// extreme points at +-fill or symmetric about the centre), every point in front of
// the eye by the margin; the direction kept.
TEST(AutoFramingTest, PointsFillTheTighterSideAndAreCentred) {
    std::vector<glm::vec3> points;
    std::uint32_t seed = 12345;
    const auto next = [&] {
        seed = seed * 1664525u + 1013904223u;
        return float(seed >> 8) / float(1u << 24);
    };
    for (int i = 0; i < 500; ++i) // a lopsided cloud: a tall stick and a ball beside it
        points.push_back(i % 2 ? glm::vec3(3.0f + 0.1f * next(), 4.0f * next(), 0.1f * next())
                               : glm::vec3(next(), next(), next()) - 0.5f);
    for (const glm::vec3 to_eye :
         {glm::vec3(0.3f, 0.5f, 1.0f), glm::vec3(-1.0f, 0.2f, -0.3f), glm::vec3(0.0f, 1.0f, 0.0f)})
        for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f, 3.0f}) {
            scene::FramingOptions options;
            options.aspect = aspect;
            const scene::CameraSpec s = scene::frame_points_along(points, to_eye, options);
            EXPECT_NEAR(glm::dot(glm::normalize(s.eye - s.target), glm::normalize(to_eye)), 1.0f,
                        1e-5f);
            const glm::mat4 vp = s.view_projection();
            float lo_x = 1e9f, hi_x = -1e9f, lo_y = 1e9f, hi_y = -1e9f, nearest = 1e9f;
            for (const glm::vec3& p : points) {
                const glm::vec4 c = vp * glm::vec4(p, 1.0f);
                ASSERT_GT(c.w, 0.0f);
                lo_x = std::min(lo_x, c.x / c.w), hi_x = std::max(hi_x, c.x / c.w);
                lo_y = std::min(lo_y, c.y / c.w), hi_y = std::max(hi_y, c.y / c.w);
                nearest = std::min(nearest, glm::dot(p - s.eye, glm::normalize(s.target - s.eye)));
            }
            const std::string what = "aspect " + std::to_string(aspect);
            EXPECT_NEAR(lo_x, -hi_x, 1e-4f) << what;
            EXPECT_NEAR(lo_y, -hi_y, 1e-4f) << what;
            // Filled, unless the nearest point decides: looking straight down the tall
            // stick, its top is as close to the eye as the margin allows.
            core::Aabb box;
            for (const glm::vec3& p : points) box.expand(p);
            const float margin = options.margin * 0.5f * glm::length(box.extent());
            if (std::abs(nearest - margin) > 1e-3f * margin)
                EXPECT_NEAR(std::max(hi_x, hi_y), options.fill, 1e-4f) << what;
            else
                EXPECT_LT(std::max(hi_x, hi_y), options.fill) << what;
            EXPECT_LE(std::min(hi_x, hi_y), options.fill + 1e-4f) << what;
            EXPECT_GT(nearest, s.near_plane) << what;
        }
}

// No finite point: the unit cube's framing, never a NaN camera.
TEST(AutoFramingTest, NoFinitePointsFrameTheUnitCube) {
    const std::vector<glm::vec3> none{glm::vec3(NAN), glm::vec3(INFINITY, 0.0f, 0.0f)};
    const scene::CameraSpec s = scene::frame_points_along(none, {0, 0, 1}, scene::FramingOptions{});
    EXPECT_TRUE(core::is_finite(s.eye));
    EXPECT_TRUE(core::is_finite(s.target));
    EXPECT_GT(glm::length(s.eye - s.target), 1.0f);
    const scene::CameraSpec empty =
        scene::frame_points_along({}, {0, 0, 1}, scene::FramingOptions{});
    EXPECT_EQ(empty.eye, s.eye);
}

} // namespace
} // namespace sherpa::test
