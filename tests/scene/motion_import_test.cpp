// Issue #16: skins, morph targets and animations are imported, validated and
// evaluated. Reference values come from the files themselves (hand-computed for the
// generated tests/data/motion_*.gltf, see make_motion_cases.py) and the glTF spec;
// the independent oracle (three.js) is motion_oracle_test.cpp.
#include "load_error_check.h"
#include "test_support.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene_loader.h>

#include <cmath>

#include <gtest/gtest.h>

namespace {

namespace test = sherpa::test;
using sherpa::scene::AnimationPath;

std::string data(const char* name) {
    return (test::data_dir() / name).string();
}

bool warned(const sherpa::scene::Scene& s, const std::string& fragment) {
    for (const auto& w : s.warnings)
        if (w.find(fragment) != std::string::npos) return true;
    return false;
}

TEST(MotionImport, RiggedSimpleHasItsSkinWeightsAndAnimation) {
    const auto s = sherpa::test::load_scene_or_fail(test::gltf_asset("RiggedSimple"));
    ASSERT_EQ(s->skins.size(), 1u);
    EXPECT_EQ(s->skins[0].joints.size(), 2u);
    EXPECT_EQ(s->skins[0].skeleton, 2);
    ASSERT_EQ(s->motions.size(), 1u);
    const auto& m = s->motions[0];
    EXPECT_EQ(m.influences, 4u);
    EXPECT_EQ(m.base_positions.size(), s->primitives[0].vertices);
    for (std::size_t v = 0; v < m.base_positions.size(); ++v) {
        float sum = 0.0f;
        for (std::uint32_t k = 0; k < 4; ++k) sum += m.weights[v * 4 + k];
        EXPECT_NEAR(sum, 1.0f, 1e-5f) << v;
    }
    ASSERT_EQ(s->animations.size(), 1u);
    EXPECT_EQ(s->animations[0].channels.size(), 6u);
    // Drawn skinned now: no warning of a bind pose or unused JOINTS/WEIGHTS.
    EXPECT_FALSE(warned(*s, "bind pose"));
    EXPECT_FALSE(warned(*s, "not used for drawing"));
}

TEST(MotionImport, StaticScenesCarryNoMotionData) {
    for (const char* name : {"Box", "DamagedHelmet", "BoxTextured"}) {
        const auto s = sherpa::test::load_scene_or_fail(test::gltf_asset(name));
        EXPECT_TRUE(s->motions.empty()) << name;
        EXPECT_TRUE(s->skins.empty() && s->animations.empty()) << name;
    }
}

TEST(MotionImport, MorphTargetsAndDefaultWeights) {
    const auto s = sherpa::test::load_scene_or_fail(test::gltf_asset("SimpleMorph"));
    ASSERT_EQ(s->motions.size(), 1u);
    EXPECT_EQ(s->motions[0].targets.size(), 2u);
    EXPECT_EQ(s->primitives[0].morph_targets, 2u);
    EXPECT_EQ(s->mesh_weights[0], (std::vector<float>{0.5f, 0.5f}));
    EXPECT_EQ(s->nodes[0].weights, (std::vector<float>{0.5f, 0.5f}));
    const auto sphere = sherpa::test::load_scene_or_fail(test::gltf_asset("AnimatedMorphSphere"));
    ASSERT_EQ(sphere->motions.size(), 1u);
    const auto& attrs = sphere->motions[0].target_attributes;
    EXPECT_NE(std::find(attrs.begin(), attrs.end(), "NORMAL"), attrs.end());
    EXPECT_EQ(sphere->motions[0].targets[0].normal.size(),
              sphere->motions[0].base_positions.size());
}

// motion_valid.gltf, vertex 1 (weights 0.5/0.5 on joints 1 (node 1, at origin) and 2
// (node 2, at y = 1 with inverse bind -1 in y): bind pose = identity for both), at
// t = 1: the rotation key is 1 rad about z on node 2, weights (1, 0) from the weights
// sampler; mesh default weights are (0.25, 0.5).
TEST(MotionEval, HandComputedPoseOfTheGeneratedRig) {
    const auto s = sherpa::test::load_scene_or_fail(data("motion_valid.gltf"));
    const sherpa::scene::Pose bind = sherpa::scene::evaluate_pose(*s, -1, 0.0);
    EXPECT_EQ(bind.weights[0], (std::vector<float>{0.25f, 0.5f}));
    const sherpa::scene::Pose pose = sherpa::scene::evaluate_pose(*s, 0, 1.0);
    EXPECT_EQ(pose.weights[0], (std::vector<float>{1.0f, 0.0f}));
    const auto p = sherpa::scene::posed_positions(*s, pose, 0, s->primitives[0]);
    ASSERT_EQ(p.size(), 4u);
    // Vertex 3 = (1,1,0) + target 0's delta (0,0,0.25), fully on joint 2: (1,0,0)
    // rotated about z by 1 rad, then up 1.
    EXPECT_NEAR(p[3].x, std::cos(1.0), 1e-6);
    EXPECT_NEAR(p[3].y, 1.0 + std::sin(1.0), 1e-6);
    EXPECT_NEAR(p[3].z, 0.25, 1e-6);
    // Vertex 0 = (0,0,0) + (0,0,0.5) on joint 1 (identity).
    EXPECT_NEAR(p[0].x, 0.0, 1e-6);
    EXPECT_NEAR(p[0].z, 0.5, 1e-6);
    // Vertex 1 = (1,0,0), half on each joint.
    const glm::vec3 v(1.0f, 0.0f, 0.0f), r = v - glm::vec3(0, 1, 0);
    const glm::vec3 rot(r.x * std::cos(1.0f) - r.y * std::sin(1.0f),
                        r.x * std::sin(1.0f) + r.y * std::cos(1.0f) + 1.0f, 0.0f);
    EXPECT_NEAR(p[1].x, 0.5f * (v.x + rot.x), 1e-6);
    EXPECT_NEAR(p[1].y, 0.5f * (v.y + rot.y), 1e-6);
}

TEST(MotionEval, TimesOutsideTheKeysClampAndNaNTimeIsTheFirstKey) {
    const auto s = sherpa::test::load_scene_or_fail(data("motion_valid.gltf"));
    const auto& a = s->animations[0];
    float before[4], first[4], after[4], last[4], nan_t[4];
    const auto& rot = a.samplers[a.channels[0].sampler];
    sherpa::scene::sample_animation(rot, AnimationPath::Rotation, -5.0, before);
    sherpa::scene::sample_animation(rot, AnimationPath::Rotation, 0.0, first);
    sherpa::scene::sample_animation(rot, AnimationPath::Rotation, 1e30, after);
    sherpa::scene::sample_animation(rot, AnimationPath::Rotation, 2.0, last);
    sherpa::scene::sample_animation(rot, AnimationPath::Rotation, std::nan(""), nan_t);
    for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(before[c], first[c]);
        EXPECT_EQ(after[c], last[c]);
        EXPECT_EQ(nan_t[c], first[c]);
    }
}

// A double time just below the last key rounds onto it in float: the key search
// returned the end and the interval read one key past the values (found by the pose
// fuzz target under ASan: heap-buffer-overflow in sample_animation). Every
// interpolation now lands on the last interval, at the last key's value.
TEST(MotionEval, TimeJustBelowTheLastKeyStaysInsideTheKeys) {
    for (const auto interpolation :
         {sherpa::scene::Interpolation::Step, sherpa::scene::Interpolation::Linear,
          sherpa::scene::Interpolation::CubicSpline}) {
        sherpa::scene::AnimationSampler s;
        s.interpolation = interpolation;
        s.width = 3;
        s.times = {0.0f, 2.0f};
        const std::size_t per_key =
            interpolation == sherpa::scene::Interpolation::CubicSpline ? 3 : 1;
        for (std::size_t k = 0; k < 2 * per_key; ++k)
            for (float c : {1.0f, 2.0f, 3.0f}) s.values.push_back(c * float(k + 1));
        const double t = std::nextafter(2.0, 0.0);
        ASSERT_EQ(static_cast<float>(t), 2.0f);
        float out[3];
        sherpa::scene::sample_animation(s, AnimationPath::Translation, t, out);
        const float* last = &s.values[(per_key == 3 ? 4 : 1) * 3];
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(out[c],
                        interpolation == sherpa::scene::Interpolation::Step
                            ? s.values[per_key == 3 ? 3 + c : c]
                            : last[c],
                        1e-4f)
                << c;
    }
}

TEST(MotionEval, LinearRotationIsShortestArcSlerp) {
    sherpa::scene::AnimationSampler s;
    s.width = 4;
    s.times = {0.0f, 1.0f};
    // 0 and 270 degrees about z, the second stored negated (q and -q are one rotation):
    // slerp must take the short 90 degree way, through 315 degrees.
    const float h = static_cast<float>(3 * M_PI / 4);
    s.values = {0, 0, 0, 1, 0, 0, -std::sin(h), -std::cos(h)};
    float q[4];
    sherpa::scene::sample_animation(s, AnimationPath::Rotation, 0.5, q);
    const float angle = 2.0f * std::atan2(q[2], q[3]);
    EXPECT_NEAR(std::remainder(angle, 2 * M_PI), -M_PI / 4, 1e-5);
}

TEST(MotionEval, CubicSplineTangentsScaleByTheKeyInterval) {
    sherpa::scene::AnimationSampler s;
    s.interpolation = sherpa::scene::Interpolation::CubicSpline;
    s.width = 3;
    s.times = {0.0f, 2.0f};
    // (in, value, out) per key: value 0 -> 0, out-tangent of key 0 is 1 per second.
    s.values = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    float v[3];
    sherpa::scene::sample_animation(s, AnimationPath::Translation, 0.5, v);
    // u = 0.25: h10 = u^3 - 2u^2 + u = 0.140625, times dt = 2.
    EXPECT_NEAR(v[0], 0.28125f, 1e-6f);
}

class MotionBadFile : public ::testing::TestWithParam<test::BadCase> {};

TEST_P(MotionBadFile, FailsWithAClearMessage) {
    test::expect_clear_load_error(data(GetParam().file), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Issue16, MotionBadFile,
    ::testing::Values(test::BadCase{
        "motion_joint_out_of_range.gltf",
        "nodes[0]: meshes[0].primitives[0] uses joint 5 but skins[0] has 2 joints"}),
    test::case_name);

// A broken animation channel no longer refuses the file: the channel is skipped and named
// (SHERPA_ANIMATION_CHANNEL_SKIPPED); the scene and the other channels load.
class MotionBadChannel : public ::testing::TestWithParam<test::BadCase> {};

TEST_P(MotionBadChannel, LoadsAndNamesTheChannel) {
    test::expect_loads_naming(data(GetParam().file), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    LoadAndWarn, MotionBadChannel,
    ::testing::Values(
        test::BadCase{"motion_times_not_increasing.gltf",
                      "animations[0].samplers[0].input: key times are not strictly increasing"},
        test::BadCase{"motion_nan_key.gltf", "animations[0].samplers[0].output: value 4 is not "
                                             "finite"},
        test::BadCase{"motion_output_count.gltf",
                      "animations[0].samplers[0].output: has 8 values; 3 keys need 12"}),
    test::case_name);

TEST(MotionImport, RepairedInputIsWarnedAndNeverNaN) {
    const std::pair<const char*, const char*> cases[] = {
        {"motion_more_targets_than_weights.gltf", "1 weights for 2 morph targets"},
        {"motion_unnormalized_weights.gltf", "4 vertices' skin weights do not sum to 1"},
        {"motion_zero_weights.gltf", "1 vertices have all skin weights 0"}};
    for (const auto& [file, fragment] : cases) {
        const auto s = sherpa::test::load_scene_or_fail(data(file));
        EXPECT_TRUE(warned(*s, fragment)) << file;
        for (double t : {0.0, 0.7, 1.5, 2.0, 99.0}) {
            const auto pose = sherpa::scene::evaluate_pose(*s, 0, t);
            const auto p = sherpa::scene::posed_positions(*s, pose, 0, s->primitives[0]);
            for (const auto& v : p) EXPECT_TRUE(sherpa::core::is_finite(v)) << file << " t " << t;
        }
    }
    // Unnormalised weights become exactly the valid file's.
    const auto a = sherpa::test::load_scene_or_fail(data("motion_unnormalized_weights.gltf"));
    const auto b = sherpa::test::load_scene_or_fail(data("motion_valid.gltf"));
    EXPECT_EQ(a->motions[0].weights, b->motions[0].weights);
}

} // namespace

namespace {

// Culling while moving must never lose a vertex: at 50 times of every animation of
// every skinned, morphed or animated sample, each instance's conservative bounds (from
// the per-joint boxes made at load) contain every exactly posed vertex.
TEST(MotionBounds, CullingBoundsContainEveryPosedVertex) {
    std::vector<std::string> files;
    for (const char* m : {"RiggedSimple", "SimpleMorph", "AnimatedMorphSphere", "AnimatedCube",
                          "BoxAnimated", "AnimatedTriangle", "VC"})
        files.push_back(test::gltf_asset(m));
    for (const char* f : {"motion_valid.gltf", "motion_zero_weights.gltf",
                          "sweep_quat_far_from_unit.gltf", "sweep_scale_zero.gltf"})
        files.push_back(data(f));
    for (const auto& file : files) {
        const auto s = sherpa::test::load_scene_or_fail(file);
        std::size_t checked = 0;
        for (int a = -1; a < static_cast<int>(s->animations.size()); ++a) {
            const double d = a >= 0 ? s->animations[static_cast<std::size_t>(a)].end : 0.0;
            for (int i = 0; i < 50; ++i) {
                const sherpa::scene::Pose pose = sherpa::scene::evaluate_pose(*s, a, d * i / 49.0);
                for (std::uint32_t n : s->displayed_nodes) {
                    if (s->nodes[n].mesh < 0) continue;
                    for (const auto& p : s->primitives) {
                        if (p.mesh != static_cast<std::uint32_t>(s->nodes[n].mesh)) continue;
                        const sherpa::core::Aabb box =
                            sherpa::scene::culling_bounds(*s, pose, n, p);
                        for (const glm::vec3& v : sherpa::scene::posed_positions(*s, pose, n, p)) {
                            ASSERT_TRUE(glm::all(glm::lessThanEqual(box.min, v)) &&
                                        glm::all(glm::lessThanEqual(v, box.max)))
                                << file << " animation " << a << " step " << i << " node " << n;
                            ++checked;
                        }
                    }
                }
            }
        }
        EXPECT_GT(checked, 0u) << file;
    }
}

// A finite pose can still put positions past the float range: an animated scale of
// 3e38 (STEP key 1, from t = 1) or an inverse bind matrix of 3e38. The skinned node is
// named and left out; the posed bounds stay finite and are those of the still triangle
// beside it (x in [3, 4]). Before the fix they were [-inf nan -inf] .. [inf nan inf].
TEST(MotionBounds, PosesPastTheFloatRangeAreNamedAndLeftOut) {
    for (const char* file : {"pose_overflow_scale.gltf", "pose_overflow_ibm.gltf"}) {
        SCOPED_TRACE(file);
        const auto s = sherpa::test::load_scene_or_fail(data(file));
        ASSERT_TRUE(s);
        const sherpa::scene::Pose pose = sherpa::scene::evaluate_pose(*s, 0, 1.3);
        const sherpa::scene::PosedBounds b = sherpa::scene::posed_scene_bounds(*s, pose);
        EXPECT_EQ(b.overflow, std::vector<std::uint32_t>{0});
        ASSERT_TRUE(b.exact.valid() && b.culling.valid());
        for (const sherpa::core::Aabb& box : {b.exact, b.culling})
            EXPECT_TRUE(sherpa::core::is_finite(box.min) && sherpa::core::is_finite(box.max));
        EXPECT_EQ(b.exact.min, glm::vec3(3, 0, 0));
        EXPECT_EQ(b.exact.max, glm::vec3(4, 1, 0));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(b.culling.min, b.exact.min)) &&
                    glm::all(glm::greaterThanEqual(b.culling.max, b.exact.max)));
        // The cheap per-frame check (the editor's, the CLI's render and cull) agrees.
        EXPECT_EQ(sherpa::scene::posed_overflow_nodes(*s, pose), std::vector<std::uint32_t>{0});
        const std::string w = sherpa::scene::posed_overflow_warning(*s, 0);
        EXPECT_NE(w.find("nodes[0]"), std::string::npos) << w;
        EXPECT_NE(w.find("overflow the float range"), std::string::npos) << w;
    }
    // Before the huge key (t < 1) the scaled rig is in range: nothing to say.
    const auto s = sherpa::test::load_scene_or_fail(data("pose_overflow_scale.gltf"));
    const sherpa::scene::Pose early = sherpa::scene::evaluate_pose(*s, 0, 0.5);
    const sherpa::scene::PosedBounds b = sherpa::scene::posed_scene_bounds(*s, early);
    EXPECT_TRUE(b.overflow.empty());
    EXPECT_TRUE(sherpa::scene::posed_overflow_nodes(*s, early).empty());
    EXPECT_LT(b.exact.min.x, 3.0f) << "the rig is in the bounds again";
}

} // namespace

// The editor logs the importer's warnings and has a timeline: the CLI's sentence about
// `--animation N --time T` belongs to `render` and `cull` alone, never to the scene.
TEST(MotionImport, AnimatedFilesCarryNoCliPoseSentence) {
    for (const char* name : {"RiggedSimple", "SimpleMorph", "AnimatedTriangle"}) {
        const auto s = sherpa::test::load_scene_or_fail(test::gltf_asset(name));
        ASSERT_TRUE(s);
        EXPECT_FALSE(s->animations.empty()) << name;
        EXPECT_FALSE(warned(*s, "--animation")) << name;
        EXPECT_FALSE(warned(*s, "default pose")) << name;
    }
}
