// sherpa-cli render --compare: the composited PNG and the statistics against the
// two sides rendered alone by the same command (split: their pixels either side of
// the divider; difference: mean, max, PSNR and the count over the threshold
// computed here from the two PNGs), under the validation layer.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/sweep_images.h"
#include "cli_run.h"
#include "test_support.h"

#include <sherpa/texture/image.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace sherpa::test {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr std::uint32_t kW = 64, kH = 48;

using sherpa::test::Png;

class CliRenderCompare : public ::testing::Test {
protected:
    fs::path dir =
        fs::temp_directory_path() /
        ("sherpa_cli_compare_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    void SetUp() override { fs::create_directories(dir); }
    void TearDown() override { fs::remove_all(dir); }

    // One render with `extra` options; returns the PNG (and the JSON with --json).
    Png render(const std::string& scene, const std::string& name, const std::string& extra,
               json* out = nullptr) {
        const fs::path png = dir / name;
        const CliRun r = run_cli("render '" + scene + "' -o '" + png.string() + "' --width " +
                                     std::to_string(kW) + " --height " + std::to_string(kH) +
                                     " --validation --no-shadows --cache-dir '" +
                                     SHERPA_TEST_TEXTURE_CACHE + "' " + extra,
                                 out ? "2>/dev/null" : "2>&1");
        EXPECT_EQ(r.exit_code, 0) << r.out;
        if (out && r.exit_code == 0) *out = json::parse(r.out);
        return sherpa::test::read_png(png.string());
    }
};

TEST_F(CliRenderCompare, SplitShowsTheTwoSingleRendersEitherSideOfTheDivider) {
    const std::string box = gltf_asset("BoxTextured");
    const Png a = render(box, "a.png", "--view normal");
    const Png b = render(box, "b.png", "--view uv0");
    json j;
    const Png split =
        render(box, "split.png", "--view normal --compare split --compare-view uv0 --json", &j);
    ASSERT_EQ(split.rgba.size(), a.rgba.size());
    EXPECT_EQ(j["mode"], "split");
    EXPECT_EQ(j["a"]["view"], "normal");
    EXPECT_EQ(j["b"]["view"], "uv0");
    EXPECT_EQ(j["pixels"].get<std::uint64_t>(), std::uint64_t(kW) * kH);
    std::size_t wrong = 0;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x) {
            if (x == kW / 2 - 1 || x == kW / 2) continue; // the divider line
            const std::size_t p = 4 * (std::size_t(y) * kW + x);
            const Png& want = x < kW / 2 ? a : b;
            for (int k = 0; k < 3; ++k) wrong += split.rgba[p + k] != want.rgba[p + k];
        }
    EXPECT_EQ(wrong, 0u);
}

// Raster against rays (the rasterizer's derivative LOD against the rays' level 0):
// the printed statistics are the ones computed from the two single renders.
// Both sides of a lit comparison are lit as the single render is: by the room (the
// default), by nothing (--environment none), and with the display settings given.
TEST_F(CliRenderCompare, LitSidesAreLitAsTheSingleRender) {
    const std::string box = gltf_asset("BoxTextured");
    for (const std::string lighting :
         {"", "--environment none", "--environment-rotation 90 --tone-map aces --exposure 1"}) {
        const Png single =
            render(box, "single.png", "--camera eye=2,1.5,3:target=0,0,0 " + lighting);
        const Png split = render(box, "split.png",
                                 "--camera eye=2,1.5,3:target=0,0,0 " + lighting +
                                     " --compare split --compare-with '" + box + "'");
        ASSERT_EQ(split.rgba.size(), single.rgba.size());
        std::size_t wrong = 0;
        for (std::uint32_t y = 0; y < kH; ++y)
            for (std::uint32_t x = 0; x < kW; ++x) {
                if (x == kW / 2 - 1 || x == kW / 2) continue; // the divider line
                const std::size_t p = 4 * (std::size_t(y) * kW + x);
                for (int k = 0; k < 3; ++k) wrong += split.rgba[p + k] != single.rgba[p + k];
            }
        EXPECT_EQ(wrong, 0u) << lighting;
    }
}

// A file that is no image: render warns naming it, and draws with the room.
TEST_F(CliRenderCompare, ABadEnvironmentFileIsAWarningAndTheRoom) {
    const std::string box = gltf_asset("BoxTextured");
    const fs::path bad = dir / "bad.hdr";
    std::ofstream(bad) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 512 +X 1024\nxx";
    const Png room = render(box, "room.png", "");
    const CliRun r =
        run_cli("render '" + box + "' -o '" + (dir / "bad.png").string() + "' --width " +
                std::to_string(kW) + " --height " + std::to_string(kH) +
                " --validation --no-cache --no-shadows --environment '" + bad.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("warning: " + bad.string() + ": "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("using the built-in room environment instead"), std::string::npos)
        << r.out;
    EXPECT_EQ(sherpa::test::read_png((dir / "bad.png").string()).rgba, room.rgba);
}

// The report says how the environment is made: SH9 irradiance by default (no irradiance
// cube, no Lambert pass), its GPU bytes, and the build's passes (the lookup table made
// with this first environment).
TEST_F(CliRenderCompare, TheReportShowsTheEnvironmentsIrradianceBytesAndPasses) {
    const std::string box = gltf_asset("BoxTextured");
    const fs::path report = dir / "report.json";
    const CliRun r =
        run_cli("render '" + box + "' -o '" + (dir / "lit.png").string() + "' --width " +
                std::to_string(kW) + " --height " + std::to_string(kH) +
                " --validation --no-cache --frames 1 --report '" + report.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const json j = read_json(report.string());
    ASSERT_TRUE(j["environment"].is_object()) << j.dump();
    const json& env = j["environment"];
    EXPECT_EQ(env["name"], "room");
    EXPECT_EQ(env["irradiance"], "sh9");
    EXPECT_EQ(env["irradiance_size"], 0);
    EXPECT_EQ(env["lut_size"], 64);
    // The room (1024x512): specular 256 faces x 6 levels, sheen 64 x 4, the 64x64 table.
    EXPECT_EQ(env["bytes"], 4487168);
    for (const char* pass : {"radiance_cube", "specular", "irradiance", "sheen", "lut"})
        EXPECT_TRUE(env["pass_gpu_ms"][pass].is_number()) << pass;
}

TEST_F(CliRenderCompare, DifferenceStatisticsAreThoseOfTheSingleRenders) {
    const std::string box = gltf_asset("BoxTextured");
    const Png a = render(box, "raster.png", "--view base-color");
    const Png b = render(box, "rays.png", "--view base-color --renderer rt");
    json j;
    render(box, "difference.png",
           "--view base-color --compare difference --compare-renderer rt --threshold 3 --json", &j);
    double sum = 0, squared = 0, max = 0;
    std::size_t over = 0;
    for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
        int d = 0;
        for (int k = 0; k < 3; ++k) {
            const int c = std::abs(int(a.rgba[p + k]) - int(b.rgba[p + k]));
            d = std::max(d, c);
            squared += double(c) * c;
        }
        sum += d;
        max = std::max(max, double(d));
        over += d > 3;
    }
    const double n = double(kW) * kH;
    ASSERT_GT(max, 0.0) << "the test needs a difference";
    EXPECT_NEAR(j["mean"].get<double>(), sum / n, 1e-9);
    EXPECT_DOUBLE_EQ(j["max"].get<double>(), max);
    EXPECT_NEAR(j["psnr_db"].get<double>(), 10 * std::log10(255.0 * 255.0 * 3 * n / squared), 1e-9);
    EXPECT_NEAR(j["over_threshold_percent"].get<double>(), 100.0 * double(over) / n, 1e-9);
    EXPECT_EQ(j["b"]["renderer"], "rt");
}

TEST_F(CliRenderCompare, AFileAgainstItselfAndAnotherFile) {
    const std::string box = gltf_asset("Box");
    json self;
    const Png black = render(box, "self.png", "--compare difference --json", &self);
    EXPECT_EQ(self["mean"].get<double>(), 0.0);
    EXPECT_TRUE(self["psnr_db"].is_null()); // infinite
    for (std::size_t p = 0; p < black.rgba.size(); p += 4)
        ASSERT_EQ(black.rgba[p] | black.rgba[p + 1] | black.rgba[p + 2], 0) << p;
    json other;
    render(box, "other.png",
           "--compare difference --compare-with '" + gltf_asset("BoxTextured") + "' --json",
           &other);
    EXPECT_GT(other["mean"].get<double>(), 1.0); // lit textured box against a plain one
    EXPECT_EQ(other["b"]["file"], gltf_asset("BoxTextured"));
}

TEST_F(CliRenderCompare, BadOptionsAreUsageErrors) {
    const std::string box = gltf_asset("Box"), out = (dir / "x.png").string();
    for (const std::string bad :
         {"--compare-view normal", "--compare blend", "--compare split --divider 2",
          "--compare difference --threshold -1", "--compare split --compare-view nothing",
          "--compare difference --heat-max 0"}) {
        const CliRun r = run_cli("render '" + box + "' -o '" + out + "' " + bad);
        EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.out;
    }
    const CliRun missing = run_cli("render '" + box + "' -o '" + out +
                                   "' --compare split --compare-with /nonexistent.gltf");
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.out.find("/nonexistent.gltf"), std::string::npos) << missing.out;
}

} // namespace
} // namespace sherpa::test
