// The skeleton overlay (issue 16): every joint of RiggedSimple is drawn where it
// projects (a cyan cross there, none in the plain render), in the bind pose and in a
// posed frame (FrameRequest::pose) whose last joint has moved; the selected joint is magenta;
// scenes without skins draw nothing more. The line builder is checked on the CPU: one
// bone per joint with a joint parent, three cross arms per joint. Validation-clean
// (GpuTest fails on any message). The posed render goes to skeleton_pose.png.
#include "gpu_test_support.h"
#include "skeleton_lines.h"

#include <sherpa/scene/animation.h>
#include <sherpa/texture/image.h>

#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace sherpa::test {
namespace skeleton_test {

constexpr std::uint32_t kSize = 200;

using Pixels = std::vector<std::uint8_t>;

bool cyan(const Pixels& rgba, std::size_t i) { // kJointColor, sRGB-encoded
    return rgba[i] < 150 && rgba[i + 1] > 200 && rgba[i + 2] > 230;
}
bool magenta(const Pixels& rgba, std::size_t i) { // kHighlightDetailColor
    return rgba[i] > 235 && rgba[i + 1] < 30 && rgba[i + 2] > 235;
}

// Pixels matching `test` within `radius` of where `world` projects.
template <class Test>
int near_projection(const Pixels& rgba, const glm::mat4& view_proj, glm::vec3 world, int radius,
                    Test test) {
    const glm::vec4 clip = view_proj * glm::vec4(world, 1.0f);
    // Clip +Y is up (the viewport flips it); row 0 is the top of the image.
    const int x = static_cast<int>((clip.x / clip.w * 0.5f + 0.5f) * kSize);
    const int y = static_cast<int>((0.5f - clip.y / clip.w * 0.5f) * kSize);
    int found = 0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int px = x + dx, py = y + dy;
            if (px < 0 || py < 0 || px >= int(kSize) || py >= int(kSize)) continue;
            found += test(rgba, (std::size_t(py) * kSize + std::size_t(px)) * 4);
        }
    return found;
}

class SkeletonTest : public GpuTest {
protected:
    static render::FrameRequest settings(const scene::Scene& scene) {
        render::FrameRequest s;
        s.width = s.height = kSize;
        std::string error;
        const glm::vec3 c = scene.bounds.center();
        const float r = glm::length(scene.bounds.extent());
        const glm::vec3 eye = c + glm::vec3(0.3f, 0.2f, 1.0f) * r;
        EXPECT_TRUE(render::parse_camera_spec(
            "eye=" + std::to_string(eye.x) + "," + std::to_string(eye.y) + "," +
                std::to_string(eye.z) + ":target=" + std::to_string(c.x) + "," +
                std::to_string(c.y) + "," + std::to_string(c.z),
            s.camera, error))
            << error;
        return s;
    }
    static glm::mat4 view_proj(const render::FrameRequest& s, const scene::Scene& scene) {
        const render::CameraView v = render::resolve_camera(s.camera, scene, 1.0f);
        return v.proj * v.view;
    }
};

TEST_F(SkeletonTest, JointsDrawnWhereTheyProjectInBindPoseAndPosed) {
    auto scene = load(gltf_asset("RiggedSimple"));
    ASSERT_TRUE(scene);
    ASSERT_EQ(scene->skins.size(), 1u);
    ASSERT_FALSE(scene->animations.empty());
    renderer().load(*scene);
    render::FrameRequest s = settings(*scene);
    const glm::mat4 vp = view_proj(s, *scene);
    const Pixels plain = draw(s);
    s.overlays = render::kOverlaySkeleton;
    const Pixels bind = draw(s);
    for (const std::uint32_t j : scene->skins[0].joints) {
        const glm::vec3 p(scene->node_world[j][3]);
        EXPECT_EQ(near_projection(plain, vp, p, 3, cyan), 0) << "joint " << j;
        EXPECT_GT(near_projection(bind, vp, p, 3, cyan), 3) << "joint " << j;
    }

    // A pose: RiggedSimple's animation turns its joints about their own origins (the
    // bend moves vertices, not joints), so its last joint is also moved sideways, by a
    // third of the scene's size: the crosses must follow the pose's world matrices.
    const scene::Animation& anim = scene->animations[0];
    auto pose = std::make_shared<scene::Pose>(
        scene::evaluate_pose(*scene, 0, 0.5 * (anim.start + anim.end)));
    const std::uint32_t last = scene->skins[0].joints.back();
    pose->world[last] = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.0f, 0.0f) *
                                                            glm::length(scene->bounds.extent())) *
                        pose->world[last];
    s.pose = pose;
    const Pixels posed = draw(s);
    std::string error;
    EXPECT_TRUE(tex::write_png("skeleton_pose.png", kSize, kSize, posed, error)) << error;
    int moved = 0;
    for (const std::uint32_t j : scene->skins[0].joints) {
        const glm::vec3 p(pose->world[j][3]);
        EXPECT_GT(near_projection(posed, vp, p, 3, cyan), 3) << "posed joint " << j;
        const glm::vec3 b(scene->node_world[j][3]);
        const glm::vec4 a = vp * glm::vec4(p, 1.0f), c = vp * glm::vec4(b, 1.0f);
        const float pixels =
            glm::length(glm::vec2(a) / a.w - glm::vec2(c) / c.w) * 0.5f * float(kSize);
        if (pixels > 10.0f) {
            ++moved;
            EXPECT_EQ(near_projection(posed, vp, b, 2, cyan), 0) << "joint " << j << " left";
        }
    }
    EXPECT_EQ(moved, 1) << "the moved joint";

    // The selected joint in magenta, only there.
    const std::uint32_t selected = scene->skins[0].joints.back();
    s.selected_joint = selected;
    const Pixels lit = draw(s);
    EXPECT_GT(near_projection(lit, vp, glm::vec3(pose->world[selected][3]), 4, magenta), 3);
    EXPECT_EQ(near_projection(posed, vp, glm::vec3(pose->world[selected][3]), 4, magenta), 0);
    renderer().unload();
}

TEST_F(SkeletonTest, SceneWithoutSkinsDrawsNothingMore) {
    auto scene = load(gltf_asset("BoxAnimated"));
    ASSERT_TRUE(scene);
    renderer().load(*scene);
    render::FrameRequest s = settings(*scene);
    const Pixels plain = draw(s);
    s.overlays = render::kOverlaySkeleton;
    EXPECT_EQ(draw(s), plain);
    renderer().unload();
}

TEST(SkeletonLines, BonesToParentJointsAndACrossPerJoint) {
    scene::Scene scene;
    scene.nodes.resize(4);
    // 0 (not a joint) -> 1 -> 2 -> 3; the skin's joints 1 and 3: 3's bone skips node 2.
    for (int n = 1; n < 4; ++n) scene.nodes[std::size_t(n)].parent = n - 1;
    scene::Skin skin;
    skin.joints = {3, 1};
    scene.skins.push_back(skin);
    std::vector<glm::mat4> world(4);
    for (int n = 0; n < 4; ++n)
        world[std::size_t(n)] = glm::translate(glm::mat4(1.0f), glm::vec3(0, float(n), 0));
    std::vector<render::GPULineVertex> lines;
    render::append_skeleton(lines, scene.skins, scene.nodes, world, std::nullopt, 0.1f);
    ASSERT_EQ(lines.size(), 2u * (1 + 3 * 2));                   // one bone, two crosses
    EXPECT_EQ(glm::vec3(lines[0].position), glm::vec3(0, 1, 0)); // from the parent joint
    EXPECT_EQ(glm::vec3(lines[1].position), glm::vec3(0, 3, 0));
    EXPECT_EQ(lines[0].color, render::kBoneColor);

    lines.clear();
    render::append_skeleton(lines, scene.skins, scene.nodes, world, 3u, 0.1f);
    EXPECT_EQ(lines[0].color, render::kHighlightDetailColor); // the selected joint's bone
    EXPECT_FLOAT_EQ(glm::length(glm::vec3(lines[3].position - lines[2].position)), 0.4f);

    // Joints outside the world matrices and non-finite positions are skipped.
    world[1][3].x = std::numeric_limits<float>::quiet_NaN();
    lines.clear();
    render::append_skeleton(lines, scene.skins, scene.nodes, std::span(world).first(4),
                            std::nullopt, 0.1f);
    EXPECT_EQ(lines.size(), 2u * 3); // only joint 3's cross: its bone ends at a NaN
}

} // namespace skeleton_test
} // namespace sherpa::test
