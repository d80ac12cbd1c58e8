// Every sample model and builtin:default renders with zero validation messages,
// in the lit view and in every debug view with every overlay.
#include "gpu_test_support.h"

#include <sherpa/render/frame_request.h>
#include <sherpa/scene/usage_report.h>

namespace sherpa::test {
namespace {

// Pixels that differ from the clear colour: the scene drew something.
std::size_t covered_pixels(const std::vector<std::uint8_t>& rgba,
                           const std::vector<std::uint8_t>& clear) {
    std::size_t n = 0;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
        if (std::abs(int(rgba[i]) - int(clear[0])) + std::abs(int(rgba[i + 1]) - int(clear[1])) +
                std::abs(int(rgba[i + 2]) - int(clear[2])) >
            6)
            ++n;
    return n;
}

std::vector<std::string> all_scenes() {
    std::vector<std::string> specs{"builtin:default"};
    for (const auto& name : all_gltf_models()) specs.push_back(gltf_asset(name));
    return specs;
}

class RenderAssetTest : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(RenderAssetTest, RendersValidationCleanAndDrawsSomething) {
    auto scene = load(GetParam());
    ASSERT_TRUE(scene);
    render::FrameRequest s;
    s.width = 96;
    s.height = 64;
    renderer().load(*scene);
    std::vector<std::uint8_t> rgba;
    const render::FrameStats stats = renderer().render(s, &rgba);
    ASSERT_EQ(rgba.size(), 96u * 64u * 4u);
    // The clear colour as stored: render an empty frame with the same settings.
    const bool drawable = !renderer().scene()->groups().empty();
    renderer().unload();
    std::vector<std::uint8_t> empty;
    renderer().render(s, &empty);
    if (drawable) {
        EXPECT_GT(covered_pixels(rgba, empty), 30u) << GetParam() << " drew (almost) nothing";
        EXPECT_GT(stats.fragment_invocations, 0u);
        EXPECT_GT(stats.draw_calls, 0u);
    }
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string n = info.param.substr(info.param.find_last_of("/:") + 1);
    n = n.substr(0, n.find('.'));
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

INSTANTIATE_TEST_SUITE_P(AllAssets, RenderAssetTest, ::testing::ValuesIn(all_scenes()), test_name);

class DebugViewTest : public GpuTest {};

// Every view and overlay on scenes that exercise textures, two UV sets, vertex
// colours, blending and masking.
TEST_F(DebugViewTest, EveryViewAndOverlayIsValidationClean) {
    for (const std::string name : {"MultiUVTest", "AlphaBlendModeTest", "BoxVertexColors"}) {
        auto scene = load(gltf_asset(name));
        ASSERT_TRUE(scene);
        renderer().load(*scene, streams_setup(render::StreamPolicy::AllPresent));
        render::FrameRequest s;
        s.width = 64;
        s.height = 48;
        s.overlays = render::kOverlayWireframe | render::kOverlayNormals |
                     render::kOverlayTangents | render::kOverlayBitangents | render::kOverlayBounds;
        for (std::string_view view : render::debug_view_names()) {
            s.view = *render::parse_debug_view(view);
            if (!render::raster_view(s.view)) continue; // rays only (ao, shadow-error)
            std::vector<std::uint8_t> rgba;
            renderer().render(s, &rgba);
            EXPECT_EQ(rgba.size(), 64u * 48u * 4u) << name << " " << view;
        }
    }
    renderer().unload();
}

TEST_F(DebugViewTest, NamesRoundTrip) {
    for (std::string_view name : render::debug_view_names()) {
        auto v = render::parse_debug_view(name);
        ASSERT_TRUE(v) << name;
        EXPECT_EQ(to_string(*v), name);
    }
    EXPECT_FALSE(render::parse_debug_view("nonsense"));
    for (std::string_view name : render::overlay_names())
        EXPECT_TRUE(render::parse_overlay(name)) << name;
    EXPECT_FALSE(render::parse_overlay("nonsense"));
}

// The GPU holds exactly the streams the usage report says materials read (plus
// positions); AllPresent (debug views) adds every authored or generated one.
TEST_F(DebugViewTest, GpuHoldsOnlyTheStreamsTheUsageReportAsksFor) {
    std::uint64_t used_total = 0, unified_total = 0, all_total = 0;
    for (const auto& name : all_gltf_models()) {
        auto scene = load(gltf_asset(name));
        ASSERT_TRUE(scene);
        const scene::UsageReport usage = scene::build_usage_report(*scene);
        for (render::StreamPolicy policy :
             {render::StreamPolicy::UsedByMaterials, render::StreamPolicy::AllPresent}) {
            renderer().load(*scene, streams_setup(policy));
            const render::GpuScene& g = *renderer().scene();
            for (const scene::PrimitiveUsage& u : usage.primitives) {
                if (u.instances == 0 || scene->meshes[u.mesh_id].indices.empty()) continue;
                for (scene::VertexAttribute a : scene::kAllVertexAttributes) {
                    const std::size_t i = std::size_t(a);
                    const bool expected =
                        a == scene::VertexAttribute::Position || u.used[i] ||
                        (policy == render::StreamPolicy::AllPresent && u.present[i]);
                    EXPECT_EQ(g.meshes()[u.mesh_id].stream[i] != 0, expected)
                        << name << " mesh " << u.mesh_id << " " << scene::gltf_name(a);
                }
            }
            if (policy == render::StreamPolicy::UsedByMaterials) {
                used_total += g.memory().vertex_streams;
                unified_total += g.memory().unified_vertex_bytes;
            } else {
                all_total += g.memory().vertex_streams;
            }
        }
    }
    renderer().unload();
    EXPECT_LT(used_total, unified_total)
        << "used streams should beat the 56-byte unified layout overall";
    EXPECT_LE(used_total, all_total);
}

} // namespace
} // namespace sherpa::test
