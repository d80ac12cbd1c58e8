// sherpa-cli textures: JSON schema, miss then hit through the cache, --no-cache,
// usage errors.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sys/wait.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_run.h"
#include "texture/test_images.h"

namespace {

// stderr carries warnings; the JSON on stdout must parse on its own.
sherpa::test::CliRun run_quiet(const std::string& args) {
    return sherpa::test::run_cli(args, "2>/dev/null");
}
using sherpa::test::CliRun;

std::string helmet() {
    return (sherpa::test::assets_dir() / "gltf/DamagedHelmet/glTF/DamagedHelmet.gltf").string();
}

} // namespace

TEST(CliTextures, HelmetMissThenHitWithEveryField) {
    const auto dir = sherpa::test::fresh_temp_dir("cli-textures");
    const std::string args =
        "textures '" + helmet() + "' --cache-dir '" + dir.string() + "' --quality 0 --json";
    const CliRun first = run_quiet(args);
    ASSERT_EQ(first.exit_code, 0) << first.out;
    const auto j = nlohmann::json::parse(first.out);
    const auto& list = j.at("textures");
    ASSERT_EQ(list.size(), 5u); // albedo, emissive, metal-roughness, occlusion, normal
    std::map<std::string, int> roles;
    for (const auto& t : list) {
        for (const char* key : {"image", "width", "height", "mips"})
            EXPECT_TRUE(t.at(key).is_number_integer()) << key;
        for (const char* key : {"decode_ms", "encode_ms", "psnr"})
            EXPECT_TRUE(t.at(key).is_number()) << key;
        for (const char* key : {"source", "role", "format", "state", "cache_file", "hash"})
            EXPECT_TRUE(t.at(key).is_string()) << key;
        EXPECT_EQ(t["state"], "miss");
        EXPECT_EQ(t["width"], 2048);
        EXPECT_EQ(t["mips"], 12);
        EXPECT_EQ(t["hash"].get<std::string>().size(), 32u);
        EXPECT_TRUE(std::filesystem::path(t["cache_file"].get<std::string>()).is_absolute());
        EXPECT_TRUE(std::filesystem::exists(t["cache_file"].get<std::string>()));
        EXPECT_GT(t["psnr"].get<double>(), 30.0);
        ++roles[t["role"]];
        const std::string role = t["role"];
        EXPECT_EQ(t["format"], role == "color"    ? "VK_FORMAT_BC7_SRGB_BLOCK"
                               : role == "normal" ? "VK_FORMAT_BC5_UNORM_BLOCK"
                                                  : "VK_FORMAT_BC7_UNORM_BLOCK");
    }
    EXPECT_EQ(roles["color"], 2);
    EXPECT_EQ(roles["linear"], 2);
    EXPECT_EQ(roles["normal"], 1);

    const CliRun second = run_quiet(args);
    ASSERT_EQ(second.exit_code, 0) << second.out;
    for (const auto& t : nlohmann::json::parse(second.out)["textures"]) {
        EXPECT_EQ(t["state"], "hit");
        EXPECT_EQ(t["decode_ms"], 0.0);
    }
    std::filesystem::remove_all(dir);
}

TEST(CliTextures, NoCacheAndUsageErrors) {
    const std::string box =
        (sherpa::test::assets_dir() / "gltf/BoxTextured/glTF/BoxTextured.gltf").string();
    const CliRun r = run_quiet("textures '" + box + "' --no-cache --json");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["textures"].size(), 1u);
    EXPECT_EQ(j["textures"][0]["state"], "miss");
    EXPECT_TRUE(j["textures"][0]["cache_file"].is_null());
    EXPECT_EQ(run_quiet("textures").exit_code, 2);
    EXPECT_EQ(run_quiet("textures '" + box + "' --quality 9").exit_code, 2);
    EXPECT_EQ(run_quiet("textures /nonexistent.gltf --no-cache").exit_code, 1);
}

TEST(CliTextures, TwoProcessesWritingTheSameCacheAtOnce) {
    const auto dir = sherpa::test::fresh_temp_dir("cli-textures-concurrent");
    const std::string box =
        (sherpa::test::assets_dir() / "gltf/BoxTextured/glTF/BoxTextured.gltf").string();
    const std::string cli = std::string(SHERPA_CLI_PATH) + " textures '" + box + "' --cache-dir '" +
                            dir.string() + "' --json";
    // Both processes miss and write the same key; each renames a complete file.
    const std::string both = "(" + cli + " >" + (dir / "a.json").string() + " & " + cli + " >" +
                             (dir / "b.json").string() + " & wait) 2>/dev/null";
    ASSERT_EQ(std::system(both.c_str()), 0);
    for (const char* name : {"a.json", "b.json"}) {
        std::ifstream f(dir / name);
        const auto j = nlohmann::json::parse(f);
        // Usually both miss; a late starter may already find the other's file.
        const std::string state = j["textures"][0]["state"];
        EXPECT_TRUE(state == "miss" || state == "hit") << name << ": " << state;
    }
    const CliRun after =
        run_quiet("textures '" + box + "' --cache-dir '" + dir.string() + "' --json");
    ASSERT_EQ(after.exit_code, 0);
    EXPECT_EQ(nlohmann::json::parse(after.out)["textures"][0]["state"], "hit");
    std::size_t leftovers = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        leftovers += e.path().filename().string().find(".tmp.") != std::string::npos;
    EXPECT_EQ(leftovers, 0u);
    std::filesystem::remove_all(dir);
}
