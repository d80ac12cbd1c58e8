// The renderer's speed choices must not change what a frame shows: the depth
// prepass (on or off; Auto decides per device and scene density) and forward pipelines specialised
// for the vertex streams a mesh holds give the same pixels as the general paths.
#include "gpu_test_support.h"

#include <sherpa/render/frame_request.h>

#include <cstdlib>

namespace sherpa::test {
namespace {

TEST(PrepassModeTest, AutoIsOnForGpusAndOnCpuDevicesUpToOneTrianglePerFourPixels) {
    constexpr std::uint64_t kPixels = 1280 * 720;
    EXPECT_TRUE(render::prepass_enabled(render::PrepassMode::Auto, false, 15452, kPixels));
    EXPECT_TRUE(render::prepass_enabled(render::PrepassMode::Auto, false, 1040409, kPixels));
    EXPECT_TRUE(render::prepass_enabled(render::PrepassMode::Auto, true, 15452, kPixels));
    EXPECT_TRUE(render::prepass_enabled(render::PrepassMode::Auto, true, kPixels / 4, kPixels));
    EXPECT_FALSE(
        render::prepass_enabled(render::PrepassMode::Auto, true, kPixels / 4 + 1, kPixels));
    EXPECT_FALSE(render::prepass_enabled(render::PrepassMode::Auto, true, 1040409, kPixels));
    for (bool cpu : {true, false})
        for (std::uint64_t triangles : {std::uint64_t{1}, kPixels}) {
            EXPECT_TRUE(render::prepass_enabled(render::PrepassMode::On, cpu, triangles, kPixels));
            EXPECT_FALSE(
                render::prepass_enabled(render::PrepassMode::Off, cpu, triangles, kPixels));
        }
}

class RenderPathTest : public GpuTest, public ::testing::WithParamInterface<const char*> {
protected:
    std::vector<std::uint8_t> render(const scene::Scene& scene, render::StreamPolicy policy,
                                     render::PrepassMode prepass) {
        render::FrameRequest s;
        s.width = 128;
        s.height = 96;
        s.depth_prepass = prepass;
        renderer().load(scene, streams_setup(policy));
        std::vector<std::uint8_t> rgba;
        renderer().render(s, &rgba);
        renderer().unload();
        return rgba;
    }
};

// Opaque, alpha-masked, blended, double-sided, vertex colours, two UV sets, normal
// maps: each path of forward shading.
const char* const kScenes[] = {"DamagedHelmet", "AlphaBlendModeTest", "VertexColorTest",
                               "MultiUVTest",   "TwoSidedPlane",      "NormalTangentMirrorTest"};

TEST_P(RenderPathTest, PrepassOnAndOffShowTheSameImage) {
    auto scene = load(gltf_asset(GetParam()));
    ASSERT_TRUE(scene);
    const auto with =
        render(*scene, render::StreamPolicy::UsedByMaterials, render::PrepassMode::On);
    const auto without =
        render(*scene, render::StreamPolicy::UsedByMaterials, render::PrepassMode::Off);
    // Equal depths resolve alike (GREATER_OR_EQUAL after the prepass, GREATER
    // without): only coplanar ties may differ.
    EXPECT_LE(differing_pixels(with, without, 2), with.size() / 4 / 1000) << GetParam();
}

TEST_P(RenderPathTest, LitImageDoesNotDependOnTheStreamsUploaded) {
    // AllPresent uploads streams the materials do not read, so the forward
    // pipelines are specialised differently (varyings instead of constants); lit
    // shading never reads those streams, so the pixels must not change.
    auto scene = load(gltf_asset(GetParam()));
    ASSERT_TRUE(scene);
    const auto used =
        render(*scene, render::StreamPolicy::UsedByMaterials, render::PrepassMode::Auto);
    const auto all = render(*scene, render::StreamPolicy::AllPresent, render::PrepassMode::Auto);
    EXPECT_EQ(differing_pixels(used, all, 1), 0u) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Scenes, RenderPathTest, ::testing::ValuesIn(kScenes),
                         [](const ::testing::TestParamInfo<const char*>& p) {
                             return std::string(p.param);
                         });

} // namespace
} // namespace sherpa::test
