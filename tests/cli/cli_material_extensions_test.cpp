// sherpa-cli render with material extensions (KHR_materials_ior, _specular): their
// bytes in the report (none for a scene without them), their debug views, and the
// bad-input file rendered without a validation message. Runs with --validation.
#include "cli/cli_run.h"
#include "cli/sweep_images.h"
#include "test_support.h"

#include <sherpa/texture/image.h>

#include <cmath>
#include <filesystem>
#include <tuple>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

using sherpa::test::CliRun;
using sherpa::test::run_cli;

std::string temp_path(const std::string& name) {
    return sherpa::test::temp_path("sherpa_cli_matext", name);
}

using sherpa::test::kSweepCamera;
using sherpa::test::Png;
using sherpa::test::read_png;
using sherpa::test::sphere_centre;
using sherpa::test::sweep;

std::uint64_t extension_bytes(const std::string& model, const std::string& name) {
    const std::string png = temp_path(name + ".png"), report = temp_path(name + ".json");
    const CliRun r =
        run_cli("render '" + model + "' -o " + png +
                " --width 64 --height 48 --frames 1 --environment none --report " + report +
                " --validation --cache-dir '" + SHERPA_TEST_TEXTURE_CACHE + "'");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    const auto j = sherpa::test::read_json(report);
    std::filesystem::remove(png);
    std::filesystem::remove(report);
    return j["gpu_memory_bytes"]["material_extensions"].get<std::uint64_t>();
}

TEST(CliMaterialExtensions, OnlyMaterialsThatUseThemPay) {
    EXPECT_EQ(extension_bytes(sherpa::test::gltf_asset("DamagedHelmet"), "helmet"), 0u);
    // Ten materials with KHR_materials_ior only: a 32-byte index and one block of 16
    // bytes each.
    EXPECT_EQ(extension_bytes(sweep("ior_sweep"), "ior"), 480u);
    // Ten with KHR_materials_specular only: an index and a 96-byte block each.
    EXPECT_EQ(extension_bytes(sweep("specular_sweep"), "specular"), 1280u);
}

TEST(CliMaterialExtensions, IorViewShowsEachSpheresIor) {
    const std::string png = temp_path("ior_view.png");
    const CliRun r =
        run_cli("render '" + sweep("ior_sweep") + "' -o " + png +
                " --width 160 --height 120 --view ior" + kSweepCamera + " --validation --no-cache");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const Png p = read_png(png);
    const double iors[] = {1.0, 1.2, 1.5, 1.8, 2.33};
    for (int row = 0; row < 2; ++row)
        for (int c = 0; c < 5; ++c) {
            const double expected = std::clamp((iors[c] - 1.0) * 0.5, 0.0, 1.0) * 255.0;
            EXPECT_NEAR(sphere_centre(p, row, c)[0], expected, 1.0) << row << "," << c;
        }
    std::filesystem::remove(png);
}

TEST(CliMaterialExtensions, SpecularViewsShowWeightAndColour) {
    const std::string weight = temp_path("weight.png"), colour = temp_path("colour.png");
    for (const auto& [view, png] :
         {std::pair{"specular-weight", weight}, {"specular-color", colour}}) {
        const CliRun r = run_cli("render '" + sweep("specular_sweep") + "' -o " + png +
                                 " --width 160 --height 120 --view " + view + kSweepCamera +
                                 " --validation --no-cache");
        ASSERT_EQ(r.exit_code, 0) << r.out;
    }
    const Png w = read_png(weight), c = read_png(colour);
    const double weights[] = {0.0, 0.25, 0.5, 0.75, 1.0};
    for (int i = 0; i < 5; ++i) {
        EXPECT_NEAR(sphere_centre(w, 0, i)[0], weights[i] * 255.0, 1.0) << i;
        EXPECT_NEAR(sphere_centre(w, 1, i)[0], 255.0, 1.0) << i; // row 2: default weight
    }
    // Row 2's colour factors (0 .. 25, 0, 0) are radiance: red saturates past 1.
    EXPECT_EQ(sphere_centre(c, 1, 0)[0], 0);
    EXPECT_EQ(sphere_centre(c, 1, 4)[0], 255);
    EXPECT_EQ(sphere_centre(c, 1, 4)[1], 0);
    std::filesystem::remove(weight);
    std::filesystem::remove(colour);
}

// specular_textures.gltf: both textures read one 2x1 image (left texel red, alpha 0;
// right green, alpha 1) through KHR_texture_transform offset (0.5, 0); the sphere's
// front has u = 0.75, which the offset moves to the red texel. Without the transform
// (or without the TEXCOORD_0 stream the slots need) it would read green and 1.
TEST(CliMaterialExtensions, SpecularTexturesAreSampledThroughTheirTransform) {
    const std::string model = sweep("specular_textures");
    for (const auto& [view, r, g] :
         {std::tuple{"specular-color", 255, 0}, std::tuple{"specular-weight", 0, 0}}) {
        const std::string png = temp_path(std::string(view) + "_tex.png");
        const CliRun run =
            run_cli("render '" + model + "' -o " + png + " --width 160 --height 120 --view " +
                    view + " --camera eye=0,0,1.5:target=0,0,0:fov=45 --validation --no-cache");
        ASSERT_EQ(run.exit_code, 0) << run.out;
        const Png p = read_png(png);
        EXPECT_NEAR(p.at(80, 60)[0], r, 2) << view;
        EXPECT_NEAR(p.at(80, 60)[1], g, 2) << view;
        std::filesystem::remove(png);
    }
}

TEST(CliMaterialExtensions, BadValuesAreWarnedOnStderrAndTheFileStillRenders) {
    const std::string png = temp_path("bad.png");
    const CliRun r =
        run_cli("render '" + (sherpa::test::data_dir() / "material_extensions_bad.gltf").string() +
                "' -o " + png + " --width 64 --height 48 --validation --no-cache");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("KHR_materials_ior.ior: -1 is not an index of refraction"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("specularFactor: 2 is outside 0..1"), std::string::npos) << r.out;
    // The missing image, named with the slot that reads it.
    EXPECT_NE(r.out.find("missing_specular_color.png (used by material 'missing specular "
                         "texture' KHR_materials_specular.specularColorTexture)"),
              std::string::npos)
        << r.out;
    std::filesystem::remove(png);
}

} // namespace
