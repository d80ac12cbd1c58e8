// Issue #16 against an independent implementation: three.js (GLTFLoader + AnimationMixer,
// tools/motion/three_oracle.mjs, installed by the three_oracle fixture) poses every
// skinned, morphed or animated sample model at several times per animation; our node
// TRS and our skinned + morphed world positions of every vertex must agree with it to
// 1e-4 of the scene size. The generated InterpolationTest equivalent is compared at
// 100 times per animation. The CLI's posed bounds against it: tests/cli/cli_motion_oracle_test.cpp.
#include "motion/three_oracle.h"
#include "test_support.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene_loader.h>

#include <cctype>
#include <cstdio>

#include <gtest/gtest.h>

namespace {

namespace test = sherpa::test;
using nlohmann::json;

struct Agreement {
    double max_position = 0.0, max_trs = 0.0;
    std::size_t vertices = 0, nodes = 0;
};

double quat_distance(const glm::quat& a, const json& r) {
    const glm::quat b(r[3].get<float>(), r[0].get<float>(), r[1].get<float>(), r[2].get<float>());
    return std::min(glm::length(a - b), glm::length(a + b)); // q and -q are one rotation
}

// Compares one animation of `file` at `times`; returns the largest differences.
Agreement compare(const std::string& file, int animation, const std::vector<double>& times) {
    Agreement a;
    auto loaded = sherpa::scene::load_scene(file);
    EXPECT_TRUE(loaded) << loaded.error;
    if (!loaded) return a;
    const sherpa::scene::Scene& scene = *loaded.scene;
    const json oracle = test::run_three_oracle(file, animation, times);
    if (!oracle.contains("frames")) return a;
    const double size = glm::length(scene.bounds.extent());
    for (const json& frame : oracle["frames"]) {
        const double t = frame["time"].get<double>();
        const sherpa::scene::Pose pose = sherpa::scene::evaluate_pose(scene, animation, t);
        for (const json& n : frame["nodes"]) {
            const auto i = n["node"].get<std::size_t>();
            if (scene.nodes[i].has_matrix) continue; // three decomposes it; glTF keeps it
            const auto& tr = n["t"];
            const auto& sc = n["s"];
            for (int c = 0; c < 3; ++c) {
                a.max_trs = std::max(a.max_trs,
                                     std::abs(pose.translation[i][c] - tr[c].get<double>()) / size);
                a.max_trs = std::max(a.max_trs, std::abs(pose.scale[i][c] - sc[c].get<double>()));
            }
            a.max_trs = std::max(a.max_trs, quat_distance(pose.rotation[i], n["r"]));
            ++a.nodes;
        }
        for (const json& p : frame["primitives"]) {
            const auto node = p["node"].get<std::uint32_t>();
            const auto mesh = p["mesh"].get<std::uint32_t>();
            const auto prim = p["primitive"].get<std::uint32_t>();
            const sherpa::scene::PrimitiveInfo* info = nullptr;
            for (const auto& pi : scene.primitives)
                if (pi.mesh == mesh && pi.primitive == prim) info = &pi;
            if (!info || info->engine_mesh < 0) continue; // points/lines: not posed by us
            const auto ours = sherpa::scene::posed_positions(scene, pose, node, *info);
            const auto& theirs = p["positions"];
            const std::size_t count = theirs.size() / 3;
            EXPECT_EQ(count, info->vertices) << file << " mesh " << mesh;
            // Motion meshes are posed in file order; static engine meshes are too unless
            // they were unwelded (flat normals) or split for tangents.
            if (ours.size() != count) {
                EXPECT_LT(info->motion, 0);
                continue;
            }
            for (std::size_t v = 0; v < count; ++v)
                for (int c = 0; c < 3; ++c)
                    a.max_position =
                        std::max(a.max_position,
                                 std::abs(ours[v][c] - theirs[3 * v + c].get<double>()) / size);
            a.vertices += count;
        }
    }
    return a;
}

std::vector<double> sample_times(double duration, int n) {
    std::vector<double> t;
    for (int i = 0; i < n; ++i) t.push_back(duration * i / (n - 1));
    return t;
}

class MotionOracle : public ::testing::TestWithParam<std::string> {};

TEST_P(MotionOracle, PosedVerticesAndNodesAgreeWithThreeJs) {
    const std::string file =
        GetParam().find('/') == std::string::npos ? test::gltf_asset(GetParam()) : GetParam();
    auto loaded = sherpa::scene::load_scene(file);
    ASSERT_TRUE(loaded) << loaded.error;
    const auto& anims = loaded.scene->animations;
    std::size_t checked_vertices = 0;
    // Default pose (default morph weights), then every animation at 7 times (odd
    // fractions: between keys, not only on them) plus its ends.
    for (int anim = -1; anim < static_cast<int>(anims.size()); ++anim) {
        const double d = anim >= 0 ? anims[static_cast<std::size_t>(anim)].end : 0.0;
        std::vector<double> times = {0.0};
        if (anim >= 0)
            for (double f : {0.013, 0.137, 0.29, 0.5, 0.618, 0.871, 1.0}) times.push_back(f * d);
        const Agreement a = compare(file, anim, times);
        EXPECT_LT(a.max_position, 1e-4) << GetParam() << " animation " << anim;
        EXPECT_LT(a.max_trs, 1e-4) << GetParam() << " animation " << anim;
        EXPECT_GT(a.nodes, 0u);
        checked_vertices += a.vertices;
        std::printf("%s animation %d: max |posed position diff| %.3g of the scene size, max "
                    "TRS diff %.3g over %zu nodes, %zu vertices\n",
                    GetParam().c_str(), anim, a.max_position, a.max_trs, a.nodes, a.vertices);
    }
    if (!loaded.scene->motions.empty()) {
        EXPECT_GT(checked_vertices, 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Issue16, MotionOracle,
    ::testing::Values("RiggedSimple", "SimpleMorph", "AnimatedMorphSphere", "AnimatedCube",
                      "BoxAnimated", "AnimatedTriangle", "VC",
                      std::string(SHERPA_TEST_DATA_DIR) + "/motion_valid.gltf",
                      std::string(SHERPA_TEST_DATA_DIR) + "/motion_unnormalized_weights.gltf",
                      std::string(SHERPA_TEST_DATA_DIR) + "/motion_quantized.gltf",
                      std::string(SHERPA_TEST_DATA_DIR) + "/motion_quantized_u16.gltf",
                      std::string(SHERPA_TEST_DATA_DIR) + "/motion_sparse_target.gltf"),
    [](const auto& param_info) {
        std::string n = param_info.param.substr(param_info.param.find_last_of('/') + 1);
        for (char& c : n)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        return n;
    });

// InterpolationTest's equivalent: nine animations (STEP, LINEAR, CUBICSPLINE on
// translation, rotation, scale), each at 100 times across and a little beyond its keys.
TEST(MotionOracle, InterpolationTestAgreesAt100Times) {
    const std::string file = std::string(SHERPA_TEST_DATA_DIR) + "/interpolation_test.gltf";
    auto loaded = sherpa::scene::load_scene(file);
    ASSERT_TRUE(loaded) << loaded.error;
    ASSERT_EQ(loaded.scene->animations.size(), 9u);
    for (int anim = 0; anim < 9; ++anim) {
        const double d = loaded.scene->animations[static_cast<std::size_t>(anim)].end;
        const Agreement a = compare(file, anim, sample_times(d * 1.02, 100));
        EXPECT_LT(a.max_trs, 1e-4) << loaded.scene->animations[static_cast<std::size_t>(anim)].name;
        EXPECT_LT(a.max_position, 1e-4) << anim;
        std::printf("%s: max TRS diff %.3g\n",
                    loaded.scene->animations[static_cast<std::size_t>(anim)].name.c_str(),
                    a.max_trs);
    }
}

} // namespace
