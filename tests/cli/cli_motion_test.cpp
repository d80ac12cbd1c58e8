// sherpa-cli info on skins, morph targets and animations (issue #16): the JSON keys,
// --time/--animation, and usage errors; render and cull with a pose. The posed bounds are checked
// against three.js in motion_oracle_test.cpp.
#include "cli/cli_json.h"
#include "cli/cli_run.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <regex>

#include <sherpa/texture/image.h>

namespace {

using nlohmann::json;
using sherpa::test::CliRun;
using sherpa::test::info_json;
using sherpa::test::run_cli;

std::string data(const char* name) {
    return (sherpa::test::data_dir() / name).string();
}

TEST(CliMotion, SkinsAnimationsAndMorphTargetsAreListed) {
    const json rigged = info_json(sherpa::test::gltf_asset("RiggedSimple"));
    ASSERT_EQ(rigged["skins"].size(), 1u);
    EXPECT_EQ(rigged["skins"][0]["joints"], json({2, 3}));
    EXPECT_EQ(rigged["skins"][0]["skeleton"], 2);
    ASSERT_EQ(rigged["animations"].size(), 1u);
    EXPECT_EQ(rigged["animations"][0]["channels"], 6);
    EXPECT_EQ(rigged["animations"][0]["channels_by_path"]["rotation"], 2);
    EXPECT_NEAR(rigged["animations"][0]["duration"].get<double>(), 2.083333, 1e-5);

    const json interp = info_json(data("interpolation_test.gltf"));
    ASSERT_EQ(interp["animations"].size(), 9u);
    EXPECT_EQ(interp["animations"][2]["samplers_by_interpolation"]["CUBICSPLINE"], 1);
    EXPECT_EQ(interp["animations"][2]["keyframes"], 5);

    const json sphere = info_json(sherpa::test::gltf_asset("AnimatedMorphSphere"));
    const json& morph = sphere["primitives_detail"][0]["morph_targets"];
    EXPECT_EQ(morph["count"], 2);
    EXPECT_EQ(morph["default_weights"].size(), 2u);
    EXPECT_NE(std::find(morph["attributes"].begin(), morph["attributes"].end(), "NORMAL"),
              morph["attributes"].end());
    // Static files get empty lists and no morph_targets.
    const json box = info_json(sherpa::test::gltf_asset("Box"));
    EXPECT_TRUE(box["skins"].empty() && box["animations"].empty());
    EXPECT_FALSE(box["primitives_detail"][0].contains("morph_targets"));
}

TEST(CliMotion, TimeAddsPosedAndCullingBounds) {
    const json j = info_json(sherpa::test::gltf_asset("RiggedSimple"), "--time 1.0");
    EXPECT_EQ(j["pose"]["animation"], 0) << "the first animation by default";
    EXPECT_EQ(j["pose"]["culling_contains_posed"], true);
    for (int c = 0; c < 3; ++c) {
        EXPECT_LE(j["culling_bounds"]["min"][c].get<double>(),
                  j["posed_bounds"]["min"][c].get<double>());
        EXPECT_GE(j["culling_bounds"]["max"][c].get<double>(),
                  j["posed_bounds"]["max"][c].get<double>());
    }
    // The bent rig leaves its bind-pose bounds (z reaches -1.67 at t = 0.5, see the oracle).
    EXPECT_NE(j["posed_bounds"], j["bounds"]);
    // Without animations: the default pose, which is the static scene.
    const json box = info_json(sherpa::test::gltf_asset("Box"), "--time 3");
    EXPECT_TRUE(box["pose"]["animation"].is_null());
    EXPECT_EQ(box["posed_bounds"], box["bounds"]);
    // --pose bind (as render and cull take it): the file's default pose, no animation.
    const json bind = info_json(sherpa::test::gltf_asset("RiggedSimple"), "--pose bind");
    EXPECT_TRUE(bind["pose"]["animation"].is_null());
    EXPECT_EQ(bind["pose"]["culling_contains_posed"], true);
    const CliRun text =
        run_cli("info '" + sherpa::test::gltf_asset("RiggedSimple") + "' --time 0.5");
    EXPECT_NE(text.out.find("posed bounds"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("skin 0"), std::string::npos) << text.out;
}

TEST(CliMotion, BadAnimationOrTimeIsAUsageError) {
    const std::string f = "info '" + sherpa::test::gltf_asset("RiggedSimple") + "' ";
    for (const char* args :
         {"--time nan", "--time inf", "--time x", "--animation 1 --time 0", "--animation 0",
          "--animation -1 --time 0", "--pose bind --time 0", "--pose rest", "--scene x"}) {
        const CliRun r = run_cli(f + args);
        EXPECT_EQ(r.exit_code, 2) << args << ": " << r.out;
        EXPECT_NE(r.out.find("error: "), std::string::npos) << args;
    }
}

std::vector<std::uint8_t> render_rgba(const std::string& file, const std::string& extra) {
    // One file per process: ctest runs these tests in parallel processes.
    const std::string png = (std::filesystem::temp_directory_path() /
                             ("sherpa_cli_motion_render_" + std::to_string(::getpid()) + ".png"))
                                .string();
    const CliRun r = run_cli("render '" + file + "' -o " + png +
                             " --width 64 --height 64 --validation --cache-dir '" +
                             SHERPA_TEST_TEXTURE_CACHE + "' " + extra);
    EXPECT_EQ(r.exit_code, 0) << extra << ": " << r.out;
    std::uint32_t w = 0, h = 0;
    std::vector<std::uint8_t> rgba;
    std::string error;
    if (r.exit_code == 0) {
        EXPECT_TRUE(sherpa::tex::read_png_rgba8(png, w, h, rgba, error)) << error;
    }
    std::filesystem::remove(png);
    return rgba;
}

TEST(CliMotion, RenderDrawsThePoseAskedFor) {
    const std::string rig = sherpa::test::gltf_asset("RiggedSimple");
    const auto posed = render_rgba(rig, "--animation 0 --time 0.5 --camera auto");
    const auto bind = render_rgba(rig, "--pose bind --camera auto");
    const auto plain = render_rgba(rig, "--camera auto");
    ASSERT_FALSE(posed.empty());
    // Without a pose option the default pose is drawn. Auto framing fits the drawn
    // vertices, and the skinned bind pose differs from the node pose by rounding, so the
    // camera may move by a hair: a handful of edge pixels, not a pose.
    ASSERT_EQ(bind.size(), plain.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < bind.size(); i += 4)
        differ +=
            !std::equal(bind.begin() + std::ptrdiff_t(i), bind.begin() + std::ptrdiff_t(i + 3),
                        plain.begin() + std::ptrdiff_t(i));
    EXPECT_LE(differ, bind.size() / 4 / 200) << "without a pose option the default pose is drawn";
    EXPECT_NE(posed, bind) << "the rig bends at t = 0.5";
    // A morph target's default weights are drawn: not the base shape.
    EXPECT_FALSE(render_rgba(sherpa::test::gltf_asset("SimpleMorph"), "--time 0").empty());
}

TEST(CliMotion, CullTestsTheInstancesWhereThePosePutsThem) {
    // BoxAnimated's inner box rises to y = 3.1 at t = 1.5 (its bounds as loaded end at
    // y = 0.5): a narrow camera on the top of the posed bounds sees it only posed.
    const std::string box = sherpa::test::gltf_asset("BoxAnimated");
    const json at = info_json(box, "--time 1.5");
    const float top = at["posed_bounds"]["max"][1].get<float>();
    ASSERT_GT(top, 2.0f);
    const std::string y = std::to_string(top - 0.3f);
    const std::string camera = "--camera eye=0," + y + ",6:target=0," + y + ",0:fov=10";
    for (const char* method : {"pvertex", "gpu"}) {
        const CliRun posed =
            run_cli("cull '" + box + "' --json " + camera + " --method " + method + " --time 1.5");
        ASSERT_EQ(posed.exit_code, 0) << posed.out;
        EXPECT_FALSE(json::parse(posed.out)["passes"][0]["visible"].empty()) << method;
        const CliRun bind =
            run_cli("cull '" + box + "' --json " + camera + " --method " + method + " --pose bind");
        ASSERT_EQ(bind.exit_code, 0) << bind.out;
        EXPECT_TRUE(json::parse(bind.out)["passes"][0]["visible"].empty()) << method;
    }
}

TEST(CliMotion, BadPoseOptionsAreUsageErrors) {
    const std::string rig = sherpa::test::gltf_asset("RiggedSimple");
    for (const char* args : {"--pose rest", "--pose bind --time 1", "--time nan",
                             "--animation 3 --time 0", "--animation 0"}) {
        for (const std::string& cmd : {"render '" + rig + "' -o /dev/null ",
                                       "cull '" + rig + "' --camera eye=0,0,5:target=0,0,0 "}) {
            const CliRun r = run_cli(cmd + args);
            EXPECT_EQ(r.exit_code, 2) << cmd << args << ": " << r.out;
            EXPECT_NE(r.out.find("error: "), std::string::npos) << args;
        }
    }
}

// An animated scale or inverse bind matrix of 3e38: `info` printed
// [-inf -nan -inf] .. [inf -nan inf] (JSON null) without a word. Now the node is named
// in a warning and left out, and the posed bounds are the still triangle's.
TEST(CliMotion, PosedBoundsPastTheFloatRangeAreWarnedAndLeftOut) {
    for (const char* name : {"pose_overflow_scale.gltf", "pose_overflow_ibm.gltf"}) {
        SCOPED_TRACE(name);
        const json j = info_json(data(name), "--animation 0 --time 1.3");
        EXPECT_EQ(j["posed_bounds"], json::parse(R"({"min": [3, 0, 0], "max": [4, 1, 0]})"));
        EXPECT_FALSE(j["culling_bounds"].is_null());
        EXPECT_EQ(j["posed_bounds_overflow"], json({0}));
        ASSERT_EQ(j["pose"]["warnings"].size(), 1u);
        const std::string w = j["pose"]["warnings"][0];
        EXPECT_NE(w.find("nodes[0]: posed bounds of its mesh overflow the float range"),
                  std::string::npos)
            << w;
        EXPECT_EQ(j["pose"]["culling_contains_posed"], true);
        const CliRun text = run_cli("info '" + data(name) + "' --animation 0 --time 1.3");
        EXPECT_EQ(text.exit_code, 0);
        EXPECT_NE(text.out.find("posed bounds [3 0 0] .. [4 1 0]"), std::string::npos) << text.out;
        EXPECT_NE(text.out.find("warning: nodes[0]: posed bounds"), std::string::npos) << text.out;
        // No non-finite number printed ("infos" in the validation line is a word).
        EXPECT_FALSE(std::regex_search(text.out, std::regex(R"((^|[^a-z])-?(nan|inf)([^a-z]|$))")))
            << text.out;
        // render draws what it can (the still triangle, lit: shadows are not NaN) and says why
        // the rest is missing.
        const std::string png =
            (std::filesystem::temp_directory_path() / "sherpa_cli_pose_overflow.png").string();
        const CliRun render =
            run_cli("render '" + data(name) + "' -o " + png +
                    " --width 32 --height 32 --validation --animation 0 " + "--time 1.3");
        EXPECT_EQ(render.exit_code, 0) << render.out;
        EXPECT_NE(render.out.find("overflow the float range"), std::string::npos) << render.out;
        const auto posed = render_rgba(data(name), "--animation 0 --time 1.3 --camera auto");
        ASSERT_FALSE(posed.empty());
        std::size_t differ = 0; // pixels unlike the corner's background
        for (std::size_t i = 0; i < posed.size(); i += 4)
            differ += !std::equal(posed.begin() + std::ptrdiff_t(i),
                                  posed.begin() + std::ptrdiff_t(i + 3), posed.begin());
        EXPECT_GT(differ, 20u) << "the still triangle is drawn";
    }
    // Before the huge key: no warning, the whole rig in the bounds.
    const json early = info_json(data("pose_overflow_scale.gltf"), "--animation 0 --time 0.5");
    EXPECT_TRUE(early["pose"]["warnings"].empty());
    EXPECT_TRUE(early["posed_bounds_overflow"].empty());
    EXPECT_LT(early["posed_bounds"]["min"][0].get<double>(), 3.0);
}

} // namespace
