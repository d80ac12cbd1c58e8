// sherpa-cli render: PNG output, report JSON schema, error exits. Runs the CLI
// with --validation so any Vulkan validation message fails the command.
#include "cli/cli_run.h"
#include "test_support.h"

#include <sherpa/texture/image.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <sys/wait.h>

#include <gtest/gtest.h>

namespace {

// A file of this suite in the process's temporary files (test_support.h).
std::string render_temp(const std::string& name) {
    return sherpa::test::temp_path("sherpa_cli_render", name);
}

using sherpa::test::CliRun;
using sherpa::test::run_cli;

TEST(CliRender, WritesPngAndReportWithEveryCategory) {
    const std::string png = render_temp("helmet.png"), report = render_temp("helmet.json");
    const CliRun r =
        run_cli("render '" + sherpa::test::gltf_asset("DamagedHelmet") + "' -o " + png +
                " --width 96 --height 64 --frames 3 --view lit --overlay wireframe aabb"
                " --camera eye=0,0,3:target=0,0,0 --report " +
                report + " --validation --cache-dir '" + SHERPA_TEST_TEXTURE_CACHE + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    std::uint32_t w = 0, h = 0;
    std::vector<std::uint8_t> rgba;
    std::string error;
    ASSERT_TRUE(sherpa::tex::read_png_rgba8(png, w, h, rgba, error)) << error;
    EXPECT_EQ(w, 96u);
    EXPECT_EQ(h, 64u);

    const auto j = sherpa::test::read_json(report);
    EXPECT_FALSE(j["device"]["name"].get<std::string>().empty());
    EXPECT_TRUE(j["device"]["ray_tracing"].is_boolean());
    for (const char* key :
         {"vertex_streams", "indices", "textures", "materials", "instances", "total"})
        EXPECT_GT(j["gpu_memory_bytes"][key].get<std::uint64_t>(), 0u) << key;
    // A static scene carries no skinning or morph bytes.
    EXPECT_EQ(j["gpu_memory_bytes"]["motion"].get<std::uint64_t>(), 0u);
    EXPECT_GT(j["vertex_layout"]["unified_56_byte_bytes"].get<std::uint64_t>(),
              j["vertex_layout"]["used_streams_bytes"].get<std::uint64_t>());
    for (const char* pass :
         {"shadows", "depth_prepass", "opaque", "alpha_mask", "alpha_blend", "overlays"})
        EXPECT_TRUE(j["gpu_time_ms"]["passes_median"][pass].is_number()) << pass;
    for (const char* stat : {"vertex_shader_invocations", "fragment_shader_invocations",
                             "clipping_primitives", "input_assembly_primitives"})
        EXPECT_GT(j["pipeline_statistics"][stat].get<std::uint64_t>(), 0u) << stat;
    EXPECT_EQ(j["frames"], 3);
    EXPECT_EQ(j["validation_messages"], 0);
    std::filesystem::remove(png);
    std::filesystem::remove(report);
}

TEST(CliRender, GltfCameraAndDebugViewsWork) {
    const std::string png = render_temp("cameras.png");
    const CliRun r = run_cli(
        "render '" + sherpa::test::gltf_asset("Cameras") + "' -o " + png +
        " --width 32 --height 32 --camera gltf:0 --view uv0-checker --validation --no-cache");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    std::filesystem::remove(png);
}

TEST(CliRender, ErrorsExitOneWithErrorPrefix) {
    const std::string png = render_temp("bad.png");
    const std::vector<std::string> failing{
        "render /nonexistent.gltf --no-cache -o " + png,
        "render builtin:default --no-cache -o " + png + " --camera gltf:7",
        "render builtin:default --no-cache -o /nonexistent-dir/x.png --width 8 --height 8"};
    for (const std::string& args : failing) {
        const CliRun r = run_cli(args);
        EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.out;
        EXPECT_EQ(r.out.rfind("error:", 0), 0u) << args << "\n" << r.out;
    }
    // Usage mistakes exit 2, as for every subcommand.
    for (const std::string args :
         {"render builtin:default --no-cache", "render builtin:default -o x.png --view nope",
          "render builtin:default -o x.png --camera eye=1,2"}) {
        const CliRun r = run_cli(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out;
        EXPECT_NE(r.out.find("error:"), std::string::npos) << args;
    }
}

// True when a "warning: " line of `out` contains `fragment`.
bool warned(const std::string& out, const std::string& fragment) {
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("warning: ", 0) == 0 && line.find(fragment) != std::string::npos)
            return true;
    return false;
}

// Render says what it leaves out, as info does: animations drawn in their default
// pose without --time, and unused attributes (skins and morph targets are drawn).
TEST(CliRender, NamesWhatItDoesNotDraw) {
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
        {"RiggedSimple", {"animation(s)", "draw the default pose unless given `--animation N"}},
        {"AnimatedMorphSphere", {"animation(s) (\"Globe\")", "`--animation N --time T`"}}};
    for (const auto& [model, fragments] : cases) {
        const std::string png = render_temp(model + ".png");
        const CliRun r = run_cli("render '" + sherpa::test::gltf_asset(model) + "' -o " + png +
                                 " --width 32 --height 32 --validation --cache-dir '" +
                                 SHERPA_TEST_TEXTURE_CACHE + "'");
        ASSERT_EQ(r.exit_code, 0) << r.out;
        for (const auto& f : fragments)
            EXPECT_TRUE(warned(r.out, f)) << model << ": " << f << "\n" << r.out;
        std::filesystem::remove(png);
    }
}

} // namespace

// --hide-node: the caster of tests/data/double_sided_shadow.gltf (node 1) hidden, the
// uv0 view with its wireframe loses the caster's edges and texels (69 of 64 x 64 pixels
// change on lavapipe; tests/gpu/visibility_test.cpp checks its shadow against the
// outline), every cull path draws the same image, and the report counts it as hidden.
TEST(CliRender, HideNodeRemovesItsPixelsOnEveryCullPath) {
    const std::string scene = std::string(SHERPA_TEST_DATA_DIR) + "/double_sided_shadow.gltf";
    auto read = [](const std::string& png) {
        std::uint32_t w = 0, h = 0;
        std::vector<std::uint8_t> rgba;
        std::string error;
        EXPECT_TRUE(sherpa::tex::read_png_rgba8(png, w, h, rgba, error)) << error;
        return rgba;
    };
    auto differing = [](const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
        std::size_t n = 0;
        for (std::size_t p = 0; p + 3 < std::min(a.size(), b.size()); p += 4)
            n += std::memcmp(&a[p], &b[p], 4) != 0;
        return n;
    };
    const std::string common =
        " --width 64 --height 64 --view uv0 --overlay wireframe --no-cache --validation"
        " --camera eye=0,0,-3:target=0,0,0:fov=50";
    std::vector<std::uint8_t> first_hidden;
    for (const char* cull : {"none", "cpu", "gpu"}) {
        SCOPED_TRACE(cull);
        const std::string shown = render_temp("shown.png"), hidden = render_temp("hidden.png"),
                          report = render_temp("hidden.json");
        CliRun r = run_cli("render '" + scene + "' -o " + shown + common + " --cull " + cull);
        ASSERT_EQ(r.exit_code, 0) << r.out;
        r = run_cli("render '" + scene + "' -o " + hidden + common + " --cull " + cull +
                    " --hide-node 1 --report " + report);
        ASSERT_EQ(r.exit_code, 0) << r.out;
        const auto a = read(shown), b = read(hidden);
        const std::size_t changed = differing(a, b);
        EXPECT_GT(changed, 40u) << "the caster's pixels are gone";
        EXPECT_LT(changed, 400u) << "and little else";
        if (first_hidden.empty())
            first_hidden = b;
        else
            EXPECT_EQ(b, first_hidden) << "every cull path draws the same";
        const auto j = sherpa::test::read_json(report);
        ASSERT_FALSE(j["culling"].empty());
        EXPECT_EQ(j["culling"][0]["hidden"], 1);
        EXPECT_EQ(j["culling"][0]["visible"], 1);
        for (const std::string& f : {shown, hidden, report}) std::filesystem::remove(f);
    }
    const CliRun bad = run_cli("render '" + scene + "' -o x.png --no-cache --hide-node 2");
    EXPECT_EQ(bad.exit_code, 2) << bad.out;
    EXPECT_NE(bad.out.find("--hide-node 2"), std::string::npos) << bad.out;
    EXPECT_NE(bad.out.find("has 2 nodes"), std::string::npos) << bad.out;
}
