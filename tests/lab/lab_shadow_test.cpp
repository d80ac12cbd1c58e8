// Known answers of the shadows family on the hand-made caster-over-plane scene
// (tests/data/double_sided_shadow.gltf) lit by a sun travelling along (0, -1, 1):
// the caster's shadow falls on the plane's back (-Z), the front faces away.
#include <sherpa/lab/families.h>
#include <sherpa/scene/scene_loader.h>

#include "lab/lab_figures.h"
#include <gtest/gtest.h>

namespace {

using namespace sherpa;
using sherpa::test::figure;

std::unique_ptr<scene::Scene> sunlit_scene() {
    scene::LoadResult r = scene::load_scene(
        std::string(SHERPA_TEST_DATA_DIR) + "/double_sided_shadow.gltf", lab::lab_load_options());
    EXPECT_TRUE(r) << r.error;
    if (!r) return nullptr;
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    sun.intensity = 3.0f;
    r.scene->lights.push_back(sun);
    scene::PlacedLight placed;
    placed.light = std::uint32_t(r.scene->lights.size() - 1);
    placed.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));
    r.scene->placed_lights.push_back(placed);
    return std::move(r.scene);
}

lab::ShadowFamilyOptions small(bool ray_tracing) {
    lab::ShadowFamilyOptions o;
    o.resolutions = {256, 4096};
    o.pcf_taps = {1};
    o.cascades = {1};
    o.cameras = 2; // framed on the front, close up on the back
    o.width = 96;
    o.height = 72;
    o.frames = 1;
    o.ray_tracing = ray_tracing;
    o.validation = true;
    return o;
}

TEST(LabShadows, FinerMapsGetFewerPixelsWrongAndTheUnlitSideIsAFailure) {
    auto scene = sunlit_scene();
    ASSERT_TRUE(scene);
    const lab::FamilyReport r = lab::make_shadow_family(small(true))->run(*scene, {});
    ASSERT_EQ(r.methods.size(), 2u);
    EXPECT_EQ(r.chart_error, "lit_pixels_wrong_percent");
    EXPECT_EQ(r.methods[0].method.name, "256x1 pcf1");
    for (const lab::MethodResult& m : r.methods) {
        if (!m.ran && m.note.find("ray trace") != std::string::npos) GTEST_SKIP() << m.note;
        ASSERT_TRUE(m.ran) << m.method.name << ": " << m.note;
        EXPECT_GT(figure(m, "lit_pixels"), 1000.0);
        EXPECT_NEAR(figure(m, "false_shadow_percent") + figure(m, "false_light_percent"),
                    figure(m, "lit_pixels_wrong_percent"), 1e-9);
        // The camera on the front sees only surfaces facing away from the sun.
        ASSERT_EQ(m.failures.size(), 1u) << m.failures.back().cause;
        EXPECT_EQ(m.failures[0].cause, "no lit pixels (rays)");
        EXPECT_EQ(m.failures[0].where, "camera 0");
        std::printf("%s: %.3f%% of %g lit pixels wrong (%g px)\n", m.method.name.c_str(),
                    figure(m, "lit_pixels_wrong_percent"), figure(m, "lit_pixels"),
                    figure(m, "wrong_pixels"));
    }
    EXPECT_GT(figure(r.methods[0], "wrong_pixels"), 0.0) << "256 texels miss the outline";
    EXPECT_LT(figure(r.methods[1], "wrong_pixels"), figure(r.methods[0], "wrong_pixels"));
    EXPECT_LT(figure(r.methods[1], "lit_pixels_wrong_percent"), 1.0);
}

TEST(LabShadows, WithoutRayTracingNoMethodRunsAndEachSaysWhy) {
    auto scene = sunlit_scene();
    ASSERT_TRUE(scene);
    const lab::FamilyReport r = lab::make_shadow_family(small(false))->run(*scene, {});
    ASSERT_EQ(r.methods.size(), 2u);
    for (const lab::MethodResult& m : r.methods) {
        EXPECT_FALSE(m.ran) << m.method.name;
        EXPECT_NE(m.note.find("does not ray trace"), std::string::npos) << m.note;
    }
}

TEST(LabShadows, MethodNamesRoundTrip) {
    std::uint32_t res = 0, cascades = 0, taps = 0;
    ASSERT_TRUE(
        lab::parse_shadow_method(lab::shadow_method_name(2048, 3, 16), res, cascades, taps));
    EXPECT_EQ(res, 2048u);
    EXPECT_EQ(cascades, 3u);
    EXPECT_EQ(taps, 16u);
    for (const char* bad : {"", "2048", "2048x3", "2048x3 pcf", "2048x3 pcf4 ", "x3 pcf4"})
        EXPECT_FALSE(lab::parse_shadow_method(bad, res, cascades, taps)) << bad;
}

} // namespace
