// The environment behind the scene, kept while the view holds still: a frame whose
// background was copied from the kept image is, byte for byte, the frame whose
// background was drawn where no surface is, under opaque and blended surfaces alike; a
// change of view, rotation, intensity, exposure or background level draws it anew; the
// kept image is counted in the render targets' bytes and goes with the environment.
#include "gpu_test_support.h"
#include "sphere_scenes.h"

#include <sherpa/render/environment.h>

#include <string>

namespace sherpa::test {
namespace {

class EnvironmentBackgroundTest : public GpuTest {};

// Three spheres (rough metal to smooth), opaque or blended (alpha 0.4), in a
// wide view with the environment behind them.
std::string spheres(bool blend) {
    std::string gltf = sphere_row_gltf(3, 0.5f);
    if (!blend) return gltf;
    const std::string opaque = R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1])";
    const std::string blended =
        R"({"alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorFactor":[1,0.6,0.3,0.4])";
    for (std::size_t at = gltf.find(opaque); at != std::string::npos; at = gltf.find(opaque, at))
        gltf.replace(at, opaque.size(), blended);
    return gltf;
}

render::FrameRequest wide_view(const char* camera) {
    render::FrameRequest s;
    s.width = 160;
    s.height = 90;
    std::string error;
    EXPECT_TRUE(render::parse_camera_spec(camera, s.camera, error)) << error;
    return s;
}

TEST_F(EnvironmentBackgroundTest, KeptBackgroundIsTheBackgroundDrawnEachFrame) {
    renderer().set_environment(nullptr);
    std::uint64_t without = 0; // the render targets of this size, before any is kept
    const render::EnvironmentImage room = render::room_environment(256);
    renderer().set_environment(&room);
    const render::FrameRequest a = wide_view("eye=2.5,1,6:target=2.5,0,0:fov=50");
    for (const bool blend : {false, true}) {
        auto scene = load(
            write_temp(blend ? "kept_blend.gltf" : "kept_opaque.gltf", spheres(blend)).string());
        renderer().load(*scene);
        // Each a first frame of its key (drawn where no surface is), then the same
        // again (kept, and copied), then again (copied).
        std::vector<render::FrameRequest> views(5, a);
        views[1].camera.eye.x += 0.5f; // the view
        views[2].environment_rotation = 40.0f;
        views[3].environment_intensity = 0.5f;
        views[3].exposure = 0.5f;
        views[4].background = render::Background::Blurred;
        std::vector<std::vector<std::uint8_t>> firsts;
        for (const render::FrameRequest& v : views) {
            const auto drawn = draw(v);
            if (without == 0) without = renderer().resident().render_target_bytes;
            const auto kept = draw(v);
            const auto copied = draw(v);
            EXPECT_EQ(kept, drawn) << (blend ? "blended" : "opaque") << " view " << firsts.size();
            EXPECT_EQ(copied, drawn) << (blend ? "blended" : "opaque") << " view " << firsts.size();
            for (const auto& other : firsts) EXPECT_NE(drawn, other);
            firsts.push_back(drawn);
        }
        // Back to the first view: drawn, then kept, all as before.
        EXPECT_EQ(draw(a), firsts[0]);
        EXPECT_EQ(draw(a), firsts[0]);
        // The kept image (the target's size) is counted with the render targets.
        const std::uint64_t with = renderer().resident().render_target_bytes;
        EXPECT_GE(with, without + std::uint64_t{a.width} * a.height * 4);
        // A solid background draws no environment and keeps the kept image.
        render::FrameRequest solid = a;
        solid.background = render::Background::Color;
        solid.clear_color = glm::vec4(1, 0, 1, 1);
        const auto magenta = draw(solid);
        EXPECT_NE(magenta, firsts[0]);
        EXPECT_EQ(draw(a), firsts[0]);
        renderer().unload();
    }
    // The environment removed: the kept image goes with it, before any frame.
    renderer().set_environment(nullptr);
    EXPECT_EQ(renderer().resident().render_target_bytes, without);
}

} // namespace
} // namespace sherpa::test
