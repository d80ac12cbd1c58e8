// Golden images: small renders of a handful of scenes and debug views compared
// with committed PNGs within a tolerance. SHERPA_UPDATE_GOLDENS=1 rewrites them
// (look at every one before committing it). A failing comparison writes the
// actual image next to the test binary as golden_actual_NAME.png.
#include "gpu_test_support.h"

#include <sherpa/texture/image.h>

#include <cstdlib>
#include <ostream>

namespace sherpa::test {
namespace {

struct GoldenCase {
    const char* name;
    const char* scene; // sample model name or builtin spec
    const char* view;
    std::uint32_t overlays;
    const char* camera;
    std::uint32_t width, height;
    float glyph_length = 0.0f; // 0: automatic
};

// Test names and failure messages show the case's name, not its bytes.
void PrintTo(const GoldenCase& c, std::ostream* os) {
    *os << c.name;
}

// NormalTangentMirrorTest is seen straight on, as its upstream screenshot is.
constexpr const char* kMirrorCamera = "eye=0,0,2.45:target=0,0,0:fov=50";
// AlphaBlendModeTest from the front and a little above, as its upstream screenshot
// is (what `auto` showed before it became a 3/4 view): the panels' stripes and
// labels stay readable to compare with it.
constexpr const char* kAlphaBlendCamera = "eye=0,2.7399,5.36711:target=0,1.09977,-0.1:near=0.05";

const GoldenCase kCases[] = {
    {"helmet_lit", "DamagedHelmet", "lit", 0, "eye=1.6,0.5,2.6:target=0,0,0", 160, 160},
    {"mirror_lit", "NormalTangentMirrorTest", "lit", 0, kMirrorCamera, 200, 160},
    {"mirror_tangent", "NormalTangentMirrorTest", "tangent", 0, kMirrorCamera, 200, 160},
    {"mirror_tangent_w", "NormalTangentMirrorTest", "tangent-w", 0, kMirrorCamera, 200, 160},
    {"alpha_blend_lit", "AlphaBlendModeTest", "lit", 0, kAlphaBlendCamera, 200, 120},
    {"multiuv_uv1_checker", "MultiUVTest", "uv1-checker", 0, "auto", 128, 128},
    {"default_wireframe_aabb", "builtin:default", "lit",
     render::kOverlayWireframe | render::kOverlayBounds, "auto", 200, 120},
    {"box_normals_glyphs", "BoxTextured", "normal",
     render::kOverlayNormals | render::kOverlayTangents, "eye=1.5,1.2,2:target=0,0,0", 128, 128,
     0.3f},
};

std::string scene_spec(const char* scene) {
    const std::string s = scene;
    return s.rfind("builtin:", 0) == 0 ? s : gltf_asset(s);
}

class GoldenTest : public GpuTest, public ::testing::WithParamInterface<GoldenCase> {};

TEST_P(GoldenTest, MatchesCommittedImage) {
    const GoldenCase& c = GetParam();
    auto scene = load(scene_spec(c.scene));
    ASSERT_TRUE(scene);
    render::FrameRequest s;
    s.width = c.width;
    s.height = c.height;
    s.view = *render::parse_debug_view(c.view);
    s.overlays = c.overlays;
    s.glyph_length = c.glyph_length;
    std::string error;
    ASSERT_TRUE(render::parse_camera_spec(c.camera, s.camera, error)) << error;
    renderer().load(*scene, streams_setup(render::stream_policy(s)));
    std::vector<std::uint8_t> actual;
    renderer().render(s, &actual);
    renderer().unload();

    const std::string golden = std::string(SHERPA_GOLDEN_DIR) + "/" + c.name + ".png";
    if (const char* update = std::getenv("SHERPA_UPDATE_GOLDENS");
        update && std::string(update) == "1") {
        ASSERT_TRUE(tex::write_png(golden, c.width, c.height, actual, error)) << error;
        GTEST_SKIP() << "wrote " << golden;
    }
    std::uint32_t w = 0, h = 0;
    std::vector<std::uint8_t> expected;
    ASSERT_TRUE(tex::read_png_rgba8(golden, w, h, expected, error)) << error;
    ASSERT_EQ(w, c.width);
    ASSERT_EQ(h, c.height);
    // Tolerance: rasterizers may differ by rounding; a pixel counts as different
    // when a channel is off by more than 12, and at most 0.5% may differ.
    const std::size_t differing = differing_pixels(actual, expected, 12, 3);
    const double fraction = double(differing) / double(std::size_t(w) * h);
    if (fraction > 0.005) {
        tex::write_png(std::string("golden_actual_") + c.name + ".png", c.width, c.height, actual,
                       error);
        FAIL() << c.name << ": " << differing << " pixels (" << fraction * 100.0
               << "%) differ; actual written to golden_actual_" << c.name << ".png";
    }
}

INSTANTIATE_TEST_SUITE_P(Goldens, GoldenTest, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<GoldenCase>& p) {
                             return std::string(p.param.name);
                         });

} // namespace
} // namespace sherpa::test
