// sherpa-cli compare of a sample model against its gltfpack version (made by the
// gltf_compress_corpus fixture: 14-bit positions over the scene's extent, 8-bit
// octahedral normals, 12-bit UVs): every error is within the quantization step.
#include "cli/cli_run.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

class CompareGltfpack : public ::testing::TestWithParam<std::string> {};

TEST_P(CompareGltfpack, ErrorsStayWithinTheQuantizationStep) {
    const std::string model = GetParam();
    const fs::path packed =
        fs::path(SHERPA_GLTF_COMPRESS_CACHE) / "corpus" / (model + ".meshopt.glb");
    const test::CliRun r =
        test::run_cli("compare '" + test::gltf_asset(model) + "' '" + packed.string() + "' --json",
                      "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    const sherpa::scene::LoadResult source = sherpa::scene::load_scene(test::gltf_asset(model));
    ASSERT_TRUE(source) << source.error;
    const glm::vec3 e = source.scene->bounds.extent();
    glm::vec2 uv_lo(INFINITY), uv_hi(-INFINITY);
    for (const auto& m : source.scene->meshes)
        for (const auto& v : m.vertices)
            uv_lo = glm::min(uv_lo, v.uv0), uv_hi = glm::max(uv_hi, v.uv0);
    const double step = std::max({e.x, e.y, e.z}) / double((1 << 14) - 1);
    const double uv_step = std::max(1.0f, std::max(uv_hi.x - uv_lo.x, uv_hi.y - uv_lo.y)) / 4095.0;
    // One octahedral step of an 8-bit normal (2/127 in each of two components).
    const double normal_deg = glm::degrees(2.0 * std::asin(1.5 * 2.0 / 127.0 / 2.0));
    ASSERT_FALSE(j["primitives"].empty());
    for (const auto& p : j["primitives"]) {
        SCOPED_TRACE(p.dump());
        ASSERT_EQ(p["note"], "");
        EXPECT_LE(p["position_error"]["max"].get<double>(), step);
        EXPECT_LE(p["position_error"]["rms"].get<double>(),
                  p["position_error"]["max"].get<double>());
        EXPECT_LE(p["normal_error_deg"]["max"].get<double>(), normal_deg);
        EXPECT_LE(p["uv_error"]["max"].get<double>(), 1.5 * uv_step);
    }
    // -cc leaves the images as they are.
    for (const auto& t : j["textures"]) EXPECT_TRUE(t["identical"].get<bool>()) << t.dump();
    EXPECT_LT(j["bytes"]["total"][1].get<double>(), j["bytes"]["total"][0].get<double>())
        << "the packed file is smaller than the source with its buffers and images";
}

INSTANTIATE_TEST_SUITE_P(Models, CompareGltfpack,
                         ::testing::Values("Duck", "BoxTextured", "DamagedHelmet"));

TEST(CompareGltfpackImage, HeatMapOfTheDuckShowsOnlyQuantizationNoise) {
    const fs::path png =
        fs::temp_directory_path() / ("sherpa_compare_" + std::to_string(::getpid()) + ".png");
    const fs::path packed = fs::path(SHERPA_GLTF_COMPRESS_CACHE) / "corpus" / "Duck.meshopt.glb";
    const test::CliRun r =
        test::run_cli("compare '" + test::gltf_asset("Duck") + "' '" + packed.string() +
                          "' --json --image '" + png.string() + "'",
                      "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(fs::exists(png));
    EXPECT_GT(j["image"]["psnr_db"].get<double>(), 45.0);
    EXPECT_LT(j["image"]["over_threshold_percent"].get<double>(), 0.5);
    EXPECT_GT(j["image"]["max"].get<double>(), 0.0) << "quantized normals shade differently";
    fs::remove(png);
}

} // namespace
