// Hostile input (issue #12) through sherpa-cli: the cases of
// tests/scene/hostile_input_test.cpp that need a whole process (an address-space
// limit) or check what the CLI reports.
#include "cli/cli_run.h"
#include "test_support.h"

#include <cstdio>
#include <string>

#include <sys/wait.h>

#include <gtest/gtest.h>

namespace {

namespace test = sherpa::test;

// The 67M-vertex file once took 5.1 GB before its 36-byte bufferView was checked:
// under a 1.5 GB address-space limit its primitive must still be skipped with the
// range error before any allocation (the rest of the file loads).
TEST(HostileSizes, HugeCountIsRefusedBeforeAllocating) {
    const std::string cmd = "sh -c 'ulimit -v 1500000 && exec " + std::string(SHERPA_CLI_PATH) +
                            " info \"" + (test::data_dir() / "huge_count.gltf").string() +
                            "\"' 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string out;
    char buf[4096];
    for (std::size_t n; (n = fread(buf, 1, sizeof(buf), p)) > 0;) out.append(buf, n);
    const int status = pclose(p);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
    EXPECT_NE(out.find("past the end of bufferViews[0]"), std::string::npos) << out;
}

// glTF requires exact min/max: `info --json` lists the accessor whose data leaves them
// (the scene layer's half: HostileObjects.DataOutsideDeclaredMinMaxIsReported).
TEST(HostileObjects, DataOutsideDeclaredMinMaxIsReportedByInfoJson) {
    const test::CliRun cli = test::run_cli(
        "info --json '" + (test::data_dir() / "position_outside_minmax.gltf").string() + "'",
        "2>/dev/null");
    ASSERT_EQ(cli.exit_code, 0) << cli.out;
    const auto j = nlohmann::json::parse(cli.out);
    ASSERT_EQ(j.at("accessor_range_violations").size(), 1u);
    EXPECT_EQ(j["accessor_range_violations"][0]["elements_outside"], 1);
}

} // namespace
