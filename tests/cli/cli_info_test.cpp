// sherpa-cli info: exit codes, error format, JSON schema.
#include "cli/cli_json.h"
#include "cli/cli_run.h"
#include "test_support.h"

#include <array>
#include <cstdio>
#include <sys/wait.h>

#include <gtest/gtest.h>

namespace {

using sherpa::test::CliRun;
using sherpa::test::info_json;
using sherpa::test::run_cli;

TEST(CliInfo, JsonHasEveryRequiredKey) {
    const auto j = info_json(sherpa::test::gltf_asset("DamagedHelmet"));
    ASSERT_FALSE(j.empty());
    for (const char* key :
         {"scenes", "nodes", "meshes", "primitives", "materials", "textures", "images", "samplers",
          "lights", "cameras", "instances", "vertices", "triangles"})
        EXPECT_TRUE(j.at(key).is_number_integer()) << key;
    EXPECT_EQ(j["vertices"], 14556);
    EXPECT_EQ(j["triangles"], 15452);
    EXPECT_EQ(j["bounds"]["min"].size(), 3u);
    EXPECT_EQ(j["bounds"]["max"].size(), 3u);
    const auto& p = j["primitives_detail"].at(0);
    for (const char* key :
         {"mesh", "primitive", "mode", "vertices", "indices", "material", "attributes"})
        EXPECT_TRUE(p.contains(key)) << key;
    EXPECT_EQ(p["attributes"]["TANGENT"], "generated") << "normal map without TANGENT: MikkTSpace";
    EXPECT_EQ(p["attributes"]["NORMAL"], "authored");
    EXPECT_TRUE(j["usage"].contains("primitives"));
    EXPECT_TRUE(j["warnings"].is_array());
    EXPECT_TRUE(j["timings_ms"]["parse"].is_number());
    EXPECT_TRUE(j["timings_ms"]["process"].is_number());
}

// Every extension the file names is listed with whether Sherpa reads it; an
// unsupported one that is only used (not required) does not stop the file opening.
TEST(CliInfo, JsonListsExtensionsUsedAndRequiredWithSupport) {
    const auto j =
        info_json((sherpa::test::data_dir() / "unsupported_used_extension.gltf").string());
    ASSERT_FALSE(j.empty());
    const nlohmann::json used = {{{"name", "EXT_made_up_extras"}, {"supported", false}},
                                 {{"name", "KHR_texture_transform"}, {"supported", true}}};
    const nlohmann::json required = {{{"name", "KHR_texture_transform"}, {"supported", true}}};
    EXPECT_EQ(j.at("extensions_used"), used);
    EXPECT_EQ(j.at("extensions_required"), required);
}

TEST(CliInfo, BuiltinDefaultWorks) {
    const CliRun r = run_cli("info builtin:default");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("instances"), std::string::npos);
}

TEST(CliInfo, LoadErrorExitsOneWithErrorPrefix) {
    const CliRun r =
        run_cli("info '" + (sherpa::test::data_dir() / "node_cycle.gltf").string() + "'");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.out.rfind("error: ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("node_cycle.gltf"), std::string::npos);
}

TEST(CliInfo, BadUsageExitsTwo) {
    EXPECT_EQ(run_cli("").exit_code, 2);
    EXPECT_EQ(run_cli("info").exit_code, 2);
    EXPECT_EQ(run_cli("info builtin:default --bogus").exit_code, 2);
    EXPECT_EQ(run_cli("frobnicate").exit_code, 2);
    EXPECT_EQ(run_cli("info builtin:default --scene x").exit_code, 2);
}

} // namespace
