// sherpa-cli info on skins, morph targets and animations (issue #16): the JSON keys,
// --time/--animation, and usage errors. The posed bounds are checked against three.js
// in motion_oracle_test.cpp.
#include "cli/cli_run.h"
#include "test_support.h"

#include <gtest/gtest.h>

namespace {

using nlohmann::json;
using sherpa::test::CliRun;
using sherpa::test::run_cli;

json info_json(const std::string& file, const std::string& extra = "") {
    const CliRun r = run_cli("info '" + file + "' --json " + extra);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return r.exit_code == 0 ? json::parse(r.out) : json::object();
}

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
    const CliRun text =
        run_cli("info '" + sherpa::test::gltf_asset("RiggedSimple") + "' --time 0.5");
    EXPECT_NE(text.out.find("posed bounds"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("skin 0"), std::string::npos) << text.out;
}

TEST(CliMotion, BadAnimationOrTimeIsAUsageError) {
    const std::string f = "info '" + sherpa::test::gltf_asset("RiggedSimple") + "' ";
    for (const char* args : {"--time nan", "--time inf", "--time x", "--animation 1 --time 0",
                             "--animation 0", "--animation -1 --time 0"}) {
        const CliRun r = run_cli(f + args);
        EXPECT_EQ(r.exit_code, 2) << args << ": " << r.out;
        EXPECT_NE(r.out.find("error: "), std::string::npos) << args;
    }
}

} // namespace
