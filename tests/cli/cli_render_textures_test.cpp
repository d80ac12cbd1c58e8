// sherpa-cli render and the texture cache: BC7/BC5 on the GPU, the report's
// textures section, cache hits on the second run, --no-cache, and the forced
// RGBA8 fallback. Every run uses --validation (any message fails it) and a
// temporary cache directory or none, never the user's cache.
#include "cli/cli_run.h"
#include "test_support.h"

#include <sherpa/texture/image.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

using sherpa::test::CliRun;
using sherpa::test::run_cli;

class CliRenderTextures : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("sherpa_render_textures_" + std::to_string(::getpid()) + "_" + info->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    // Renders the helmet at a small size; `options` adds texture options.
    nlohmann::json render(const std::string& options, const std::string& name,
                          std::vector<std::uint8_t>* rgba = nullptr, std::string* out = nullptr) {
        const std::string png = (dir_ / (name + ".png")).string();
        const std::string report = (dir_ / (name + ".json")).string();
        const CliRun r = run_cli("render '" + sherpa::test::gltf_asset("DamagedHelmet") + "' -o " +
                                 png + " --width 96 --height 96" +
                                 " --camera eye=1.6,0.5,2.6:target=0,0,0 --validation --report " +
                                 report + " " + options);
        EXPECT_EQ(r.exit_code, 0) << r.out;
        if (out) *out = r.out;
        if (r.exit_code != 0) return {};
        if (rgba) {
            std::uint32_t w = 0, h = 0;
            std::string error;
            EXPECT_TRUE(sherpa::tex::read_png_rgba8(png, w, h, *rgba, error)) << error;
        }
        return sherpa::test::read_json(report);
    }

    static std::map<std::string, int> counts(const nlohmann::json& section) {
        return section.get<std::map<std::string, int>>();
    }

    std::filesystem::path dir_;
};

TEST_F(CliRenderTextures, HelmetUploadsBc7AndBc5ThenHitsTheCache) {
    // --keep-bc7: on a CPU device (lavapipe, here) BC7 is otherwise decoded at upload.
    const std::string cache = "--keep-bc7 --cache-dir '" + (dir_ / "cache").string() + "'";
    std::vector<std::uint8_t> first_rgba, second_rgba;
    const nlohmann::json first = render(cache, "first", &first_rgba);
    ASSERT_FALSE(first.is_null());
    EXPECT_EQ(first["validation_messages"], 0);
    const nlohmann::json& t = first["textures"];
    EXPECT_EQ(t["count"], 5);
    EXPECT_EQ(counts(t["by_format"]),
              (std::map<std::string, int>{{"VK_FORMAT_BC7_SRGB_BLOCK", 2},
                                          {"VK_FORMAT_BC7_UNORM_BLOCK", 2},
                                          {"VK_FORMAT_BC5_UNORM_BLOCK", 1}}));
    EXPECT_EQ(counts(t["by_state"]), (std::map<std::string, int>{{"miss", 5}}));
    std::uint64_t bytes = 0;
    for (const auto& tex : t["textures"]) {
        EXPECT_EQ(tex["mips"], 12) << tex["source"];
        EXPECT_TRUE(tex["psnr"].is_number()) << tex["source"];
        EXPECT_GT(tex["psnr"].get<double>(), 38.0) << tex["source"];
        EXPECT_TRUE(tex["bindless_slot"].is_number()) << tex["source"];
        EXPECT_TRUE(std::filesystem::exists(tex["cache_file"].get<std::string>()));
        bytes += tex["bytes"].get<std::uint64_t>();
    }
    // The memory report's textures are the blocks: about 1 byte per texel, not 4.
    EXPECT_EQ(first["gpu_memory_bytes"]["textures"].get<std::uint64_t>(), bytes);
    EXPECT_LT(bytes, 5ull * 2048 * 2048 * 4 / 3 + (1 << 20));

    const nlohmann::json second = render(cache, "second", &second_rgba);
    ASSERT_FALSE(second.is_null());
    EXPECT_EQ(counts(second["textures"]["by_state"]), (std::map<std::string, int>{{"hit", 5}}));
    EXPECT_EQ(second["validation_messages"], 0);
    EXPECT_EQ(second["gpu_memory_bytes"]["textures"], first["gpu_memory_bytes"]["textures"]);
    EXPECT_EQ(second_rgba, first_rgba); // the cached blocks are the blocks just made

    // The CPU-device default: the same cached BC7 blocks, decoded to RGBA8 at upload,
    // look the same as sampling the blocks; BC5 stays compressed.
    std::vector<std::uint8_t> decoded_rgba;
    std::string decoded_out;
    const nlohmann::json decoded = render("--cache-dir '" + (dir_ / "cache").string() + "'",
                                          "decoded", &decoded_rgba, &decoded_out);
    ASSERT_FALSE(decoded.is_null());
    if (decoded["device"]["type"] != "cpu") GTEST_SKIP() << "BC7 is decoded on CPU devices only";
    // Same pixels, nothing to act on: in the report's notices, not on stderr, and no
    // CLI message names an engine struct.
    // (The importer's own warnings about the file, e.g. fallback tangents, still print.)
    EXPECT_EQ(decoded_out.find("RGBA8"), std::string::npos) << decoded_out;
    EXPECT_EQ(decoded_out.find("BC7"), std::string::npos) << decoded_out;
    EXPECT_EQ(decoded_out.find("::"), std::string::npos) << decoded_out;
    ASSERT_FALSE(decoded["notices"].empty());
    EXPECT_NE(decoded["notices"][0].get<std::string>().find("decoded to RGBA8"), std::string::npos);
    EXPECT_EQ(counts(decoded["textures"]["by_state"]), (std::map<std::string, int>{{"hit", 5}}));
    EXPECT_EQ(counts(decoded["textures"]["by_format"]),
              (std::map<std::string, int>{{"VK_FORMAT_R8G8B8A8_SRGB", 2},
                                          {"VK_FORMAT_R8G8B8A8_UNORM", 2},
                                          {"VK_FORMAT_BC5_UNORM_BLOCK", 1}}));
    // Braces: EXPECT_* expands to an if/else of its own, which an unbraced if would capture.
    for (const auto& tex : decoded["textures"]["textures"]) {
        if (tex["format"] != "VK_FORMAT_BC5_UNORM_BLOCK") {
            EXPECT_NE(tex["note"].get<std::string>().find("decoded to RGBA8"), std::string::npos);
        }
    }
    EXPECT_EQ(decoded["validation_messages"], 0);
    ASSERT_EQ(decoded_rgba.size(), first_rgba.size());
    std::size_t off = 0;
    int worst = 0;
    for (std::size_t i = 0; i < first_rgba.size(); ++i) {
        const int d = std::abs(int(decoded_rgba[i]) - int(first_rgba[i]));
        worst = std::max(worst, d);
        off += d > 2;
    }
    EXPECT_EQ(off, 0u) << "largest channel difference " << worst;
}

TEST_F(CliRenderTextures, NoCacheRenderUsesNoDirectory) {
    // --quality 0 (the fastest level) keeps this run short; it compresses all five.
    const nlohmann::json j = render("--no-cache --quality 0", "nocache");
    ASSERT_FALSE(j.is_null());
    EXPECT_TRUE(j["textures"]["cache_dir"].is_null());
    EXPECT_EQ(counts(j["textures"]["by_state"]), (std::map<std::string, int>{{"miss", 5}}));
    for (const auto& tex : j["textures"]["textures"]) EXPECT_TRUE(tex["cache_file"].is_null());
    EXPECT_EQ(j["validation_messages"], 0);
}

TEST_F(CliRenderTextures, ForcedRgba8FallbackRendersAndReportsFallback) {
    std::string out;
    const nlohmann::json j =
        render("--no-bc --cache-dir '" + (dir_ / "cache").string() + "'", "rgba8", nullptr, &out);
    ASSERT_FALSE(j.is_null());
    EXPECT_EQ(counts(j["textures"]["by_state"]), (std::map<std::string, int>{{"fallback", 5}}));
    EXPECT_EQ(counts(j["textures"]["by_format"]),
              (std::map<std::string, int>{{"VK_FORMAT_R8G8B8A8_SRGB", 2},
                                          {"VK_FORMAT_R8G8B8A8_UNORM", 3}}));
    // Asked for: reported, not warned about.
    EXPECT_EQ(out.find("warning: RGBA8 forced"), std::string::npos) << out;
    ASSERT_FALSE(j["notices"].empty());
    EXPECT_NE(j["notices"][0].get<std::string>().find("RGBA8 forced (--no-bc)"), std::string::npos);
    EXPECT_EQ(j["validation_messages"], 0);
    EXPECT_GT(j["gpu_memory_bytes"]["textures"].get<std::uint64_t>(), 5ull * 2048 * 2048 * 4);
}

TEST_F(CliRenderTextures, TextureOptionMistakesAreUsageErrors) {
    for (const std::string args : {"--quality 9", "--quality", "--cache-dir", "--cache-cap-mb 0"}) {
        const CliRun r = run_cli("render builtin:default -o x.png --no-cache " + args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out;
        EXPECT_NE(r.out.find("error: --"), std::string::npos) << args << "\n" << r.out;
    }
}

} // namespace
