// GPU skinning and morphing (motion.glsl) against an independent path: the same
// geometry posed on the CPU (posed_positions(), itself checked against three.js;
// normals posed by this test's own code) and uploaded as a static mesh. And culling
// while moving: culling never changes the image of a posed frame, on either path.
#include "gpu_test_support.h"

#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/animation.h>

#include <cstdio>
#include <cstdlib>

#include <sherpa/texture/image.h>

namespace sherpa::test {
namespace {

// A camera looking at `box` from the front, a little above, the box filling the view.
render::CameraSpec camera_on(const core::Aabb& box) {
    const glm::vec3 c = box.center();
    const float r = std::max(0.5f * glm::length(box.extent()), 1e-3f);
    const glm::vec3 eye = c + glm::normalize(glm::vec3(0.35f, 0.3f, 1.0f)) * (2.2f * r);
    char text[256];
    std::snprintf(text, sizeof(text), "eye=%g,%g,%g:target=%g,%g,%g:near=%g", eye.x, eye.y, eye.z,
                  c.x, c.y, c.z, 0.01f * r);
    render::CameraSpec spec;
    std::string error;
    EXPECT_TRUE(render::parse_camera_spec(text, spec, error)) << error;
    return spec;
}

double mid_time(const scene::Scene& s, std::size_t a) {
    return s.animations[a].start + 0.37 * (s.animations[a].end - s.animations[a].start);
}

using MotionRenderTest = GpuTest;

TEST_F(MotionRenderTest, GpuSkinningAndMorphingMatchTheCpuPosedStaticMesh) {
    for (const char* name : {"RiggedSimple", "SimpleMorph", "AnimatedMorphSphere"}) {
        SCOPED_TRACE(name);
        const auto scene = load(gltf_asset(name));
        ASSERT_TRUE(scene);
        ASSERT_FALSE(scene->animations.empty());
        const auto pose = std::make_shared<const scene::Pose>(
            scene::evaluate_pose(*scene, 0, mid_time(*scene, 0)));
        const scene::Scene cpu = scene::freeze_pose(*scene, *pose);
        render::FrameRequest s;
        s.width = 160;
        s.height = 120;
        s.shadows = false;
        s.camera = camera_on(scene::posed_scene_bounds(*scene, *pose).exact);
        for (render::DebugView view : {render::DebugView::BaseColor, render::DebugView::Normal}) {
            s.view = view;
            renderer().load(*scene, streams_setup(render::StreamPolicy::AllPresent));
            ASSERT_GT(renderer().scene()->memory().motion, 0u) << "moving meshes hold streams";
            s.pose = pose;
            const auto gpu_posed = draw(s);
            s.pose = nullptr; // the scene as loaded: default pose and weights
            const auto gpu_bind = draw(s);
            renderer().load(cpu, streams_setup(render::StreamPolicy::AllPresent));
            EXPECT_EQ(renderer().scene()->memory().motion, 0u) << "the CPU-posed copy is static";
            const auto cpu_posed = draw(s);
            const std::size_t pixels = std::size_t{s.width} * s.height;
            const std::size_t differ = differing_pixels(gpu_posed, cpu_posed, 2);
            const std::size_t moved = differing_pixels(gpu_posed, gpu_bind, 2);
            std::printf("%s %s: GPU against CPU posing %zu of %zu pixels differ by > 2/255; "
                        "posed against bind pose %zu\n",
                        name, std::string(to_string(view)).c_str(), differ, pixels, moved);
            EXPECT_LE(differ, pixels / 200) << to_string(view) << ": " << differ << " of " << pixels
                                            << " pixels differ by more than 2/255";
            // A renderer that ignored the pose would draw the bind pose.
            EXPECT_GT(moved, pixels / 100) << to_string(view);
        }
    }
    renderer().unload();
}

// Every sampled time of every animation of the sample models that move: the posed
// frame drawn without culling, with CPU culling and with GPU culling (check mode
// comparing the two) is the same image. A moving instance culled with bounds that do
// not hold its posed vertices would vanish from it.
TEST_F(MotionRenderTest, CullingNeverRemovesAMovingInstanceFromTheImage) {
    for (const char* name : {"RiggedSimple", "SimpleMorph", "AnimatedMorphSphere", "AnimatedCube",
                             "BoxAnimated", "AnimatedTriangle", "VC"}) {
        SCOPED_TRACE(name);
        const auto scene = load(gltf_asset(name));
        ASSERT_TRUE(scene);
        renderer().load(*scene);
        for (std::size_t a = 0; a < scene->animations.size(); ++a) {
            const scene::Animation& anim = scene->animations[a];
            for (int k = 0; k <= 5; ++k) { // six times across the animation, both ends included
                const double t = anim.start + (anim.end - anim.start) * k / 5.0;
                SCOPED_TRACE("animation " + std::to_string(a) + " at " + std::to_string(t));
                auto pose =
                    std::make_shared<const scene::Pose>(scene::evaluate_pose(*scene, int(a), t));
                render::FrameRequest s;
                s.width = 96;
                s.height = 72;
                s.pose = pose;
                s.cache_shadows = false;
                // Where things are now: all of the posed bounds, and the top tenth of
                // them alone (e.g. BoxAnimated's box risen far above its bounds as loaded).
                const core::Aabb posed = scene::posed_scene_bounds(*scene, *pose).exact;
                core::Aabb top = posed;
                top.min.y = posed.max.y - 0.1f * (posed.max.y - posed.min.y);
                for (const core::Aabb& look : {posed, top}) {
                    s.camera = camera_on(look);
                    s.cull = render::CullPath::None;
                    s.cull_check = false;
                    const auto all = draw(s);
                    s.cull = render::CullPath::Cpu;
                    const auto cpu = draw(s);
                    s.cull = render::CullPath::Gpu;
                    s.cull_check = true;
                    std::vector<std::uint8_t> gpu_image;
                    const render::FrameStats st = renderer().render(s, &gpu_image);
                    EXPECT_EQ(differing_pixels(all, cpu, 0), 0u);
                    EXPECT_EQ(differing_pixels(all, gpu_image, 0), 0u);
                    for (const scene::CullStats& c : st.culling)
                        EXPECT_EQ(c.cpu_gpu_differences, 0) << c.pass;
                }
            }
        }
    }
    renderer().unload();
}

TEST_F(MotionRenderTest, StaticScenesCarryNoMotionBytes) {
    for (const char* name : {"Box", "BoxTextured"}) {
        const auto scene = load(gltf_asset(name));
        ASSERT_TRUE(scene);
        renderer().load(*scene);
        EXPECT_EQ(renderer().scene()->memory().motion, 0u) << name;
        for (const render::GpuMesh& m : renderer().scene()->meshes()) EXPECT_EQ(m.motion, 0u);
    }
    renderer().unload();
}

// The joint-influence view: the selected joint's weight as a heat map (dark blue 0,
// red 1); another joint gives another picture, and no selection is all 0.
TEST_F(MotionRenderTest, JointInfluenceShowsTheSelectedJointsWeight) {
    const auto scene = load(gltf_asset("RiggedSimple"));
    ASSERT_TRUE(scene);
    ASSERT_FALSE(scene->skins.empty());
    ASSERT_GE(scene->skins[0].joints.size(), 2u);
    renderer().load(*scene);
    render::FrameRequest s;
    s.width = 96;
    s.height = 96;
    s.view = render::DebugView::JointInfluence;
    s.camera =
        camera_on(scene::posed_scene_bounds(*scene, scene::evaluate_pose(*scene, -1, 0.0)).exact);
    const auto none = draw(s);
    s.selected_joint = scene->skins[0].joints[0];
    const auto first = draw(s);
    s.selected_joint = scene->skins[0].joints[1];
    const auto second = draw(s);
    auto hot = [](const std::vector<std::uint8_t>& img) { // red-dominant pixels (weight > 2/3)
        std::size_t n = 0;
        for (std::size_t i = 0; i + 3 < img.size(); i += 4) n += img[i] > 180 && img[i + 2] < 100;
        return n;
    };
    if (const char* dir = std::getenv("SHERPA_TEST_DUMP")) { // for a look at the views
        std::string error;
        for (auto [img, file] : {std::pair{&first, "/joint0.png"}, {&second, "/joint1.png"}})
            tex::write_png(dir + std::string(file), s.width, s.height, *img, error);
    }
    EXPECT_EQ(hot(none), 0u);
    EXPECT_GT(hot(first), 20u);
    EXPECT_GT(hot(second), 20u);
    EXPECT_GT(differing_pixels(first, second, 8), 100u);
    renderer().unload();
}

} // namespace
} // namespace sherpa::test
