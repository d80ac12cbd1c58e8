// One cascade fit for everybody: `sherpa-cli cull --json` culls exactly the shadow
// cascades the renderer draws for the same camera and aspect (same volumes, same
// casters visible), on the CPU and the GPU-driven paths.
#include "cli/cli_run.h"
#include "test_support.h"

#include <filesystem>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

using sherpa::test::CliRun;
using sherpa::test::run_cli;

void expect_same_passes(const std::string& scene, const std::string& camera,
                        const std::string& path) {
    SCOPED_TRACE(scene + " --cull " + path);
    const std::string png = sherpa::test::temp_path("sherpa_cli_cascades", "r.png"),
                      report = sherpa::test::temp_path("sherpa_cli_cascades", "r.json");
    // 16:9, the camera string's default aspect, as `cull` assumes.
    const CliRun r =
        run_cli("render '" + scene + "' -o " + png + " --width 320 --height 180 --camera " +
                camera + " --cull " + path + " --report " + report + " --validation");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const CliRun c = run_cli("cull '" + scene + "' --camera " + camera + " --json", "2>/dev/null");
    ASSERT_EQ(c.exit_code, 0) << c.out;
    const auto rendered = sherpa::test::read_json(report)["culling"];
    const auto culled = nlohmann::json::parse(c.out)["passes"];
    ASSERT_EQ(rendered.size(), 4u);
    ASSERT_EQ(culled.size(), rendered.size());
    for (std::size_t p = 0; p < culled.size(); ++p) {
        const auto &a = rendered[p], &b = culled[p];
        SCOPED_TRACE(b["name"].get<std::string>());
        EXPECT_EQ(a["name"], b["name"]);
        for (int k = 0; k < 16; ++k) {
            const float x = a["cull_view_projection"][k], y = b["cull_view_projection"][k];
            EXPECT_NEAR(x, y, 1e-5f * std::max(1.0f, std::abs(y))) << "element " << k;
        }
        for (const char* key : {"total", "visible", "triangles"})
            EXPECT_EQ(a[key], b["stats"][key]) << key;
    }
    std::filesystem::remove(png);
    std::filesystem::remove(report);
}

TEST(CliCullCascades, RendererCascadesEqualCullCommandCascades) {
    for (const char* path : {"cpu", "gpu"}) {
        expect_same_passes("builtin:grid?n=2000", "eye=2,3,6:target=0,0,0", path);
        expect_same_passes("builtin:default", "eye=0,1.5,4:target=0,0.5,0", path);
    }
}

} // namespace
