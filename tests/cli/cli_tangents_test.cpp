// sherpa-cli tangents: the per-corner dump and the authored-vs-regenerated comparison.
#include "test_support.h"

#include <cstdlib>
#include <sstream>
#include <sys/wait.h>

#include <gtest/gtest.h>

namespace {

// Runs sherpa-cli with `args`, stdout to `out_path`; returns the exit code.
int cli(const std::string& args, const std::string& out_path = "/dev/null") {
    const std::string cmd =
        std::string(SHERPA_CLI_PATH) + " tangents " + args + " > " + out_path + " 2>/dev/null";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> lines_of(const std::string& path) {
    std::ifstream f(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(f, line);) lines.push_back(line);
    return lines;
}

TEST(CliTangents, DumpHasOneRowPerCornerInTriangleOrder) {
    const std::string csv = "cli_tangents_dump.csv";
    ASSERT_EQ(cli(sherpa::test::gltf_asset("NormalTangentMirrorTest") + " --dump " + csv), 0);
    const auto lines = lines_of(csv);
    ASSERT_EQ(lines.size(), 1u + 15720u); // header + corners (5240 triangles)
    EXPECT_EQ(lines[0], "mesh,primitive,triangle,corner,tx,ty,tz,tw");
    EXPECT_EQ(lines[1].rfind("0,0,0,0,", 0), 0u);
    EXPECT_EQ(lines[5].rfind("0,0,1,1,", 0), 0u);
    // --regenerate replaces the authored tangents by MikkTSpace's, within 0.01 degrees.
    const std::string regenerated = "cli_tangents_regenerated.csv";
    ASSERT_EQ(cli(sherpa::test::gltf_asset("NormalTangentMirrorTest") + " --regenerate --dump " +
                  regenerated),
              0);
    const auto again = lines_of(regenerated);
    ASSERT_EQ(again.size(), lines.size());
    EXPECT_NE(again, lines);
    std::remove(csv.c_str());
    std::remove(regenerated.c_str());
}

TEST(CliTangents, CompareJsonReportsAuthoredPrimitives) {
    const std::string out = "cli_tangents_compare.json";
    ASSERT_EQ(cli(sherpa::test::gltf_asset("NormalTangentMirrorTest") + " --compare --json", out),
              0);
    const auto j = sherpa::test::read_json(out);
    ASSERT_EQ(j["primitives"].size(), 1u);
    const auto& p = j["primitives"][0];
    EXPECT_TRUE(p["authored"].get<bool>());
    EXPECT_EQ(p["corners"].get<int>(), 15720);
    EXPECT_EQ(p["handedness_flips"].get<int>(), 0);
    EXPECT_LT(p["p99_deg"].get<double>(), 0.005);
    ASSERT_EQ(cli(sherpa::test::gltf_asset("NormalTangentMirrorTest") +
                      " --compare --json --method lengyel",
                  out),
              0);
    EXPECT_GT(sherpa::test::read_json(out)["primitives"][0]["max_deg"].get<double>(), 1.0);
    std::remove(out.c_str());
}

TEST(CliTangents, BadArgumentsAreUsageErrors) {
    const std::string scene = sherpa::test::gltf_asset("Box");
    EXPECT_EQ(cli(scene), 2);                              // neither --dump nor --compare
    EXPECT_EQ(cli(scene + " --compare --dump x.csv"), 2);  // both
    EXPECT_EQ(cli(scene + " --compare --method nope"), 2); // unknown method
    EXPECT_EQ(cli("--compare"), 2);                        // no scene
    EXPECT_EQ(cli("/no/such/file.gltf --compare"), 1);     // load error
}

} // namespace
