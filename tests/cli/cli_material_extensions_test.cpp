// sherpa-cli render with material extensions (ior, specular, clearcoat, sheen): their
// bytes in the report (none for a scene without them), their debug views, and the
// bad-input file rendered without a validation message. Runs with --validation.
#include "cli/cli_run.h"
#include "cli/sweep_furnace.h"
#include "cli/sweep_images.h"
#include "test_support.h"

#include <sherpa/texture/image.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <tuple>
#include <unistd.h>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace {

// A file of this suite in the process's temporary files (test_support.h).
std::string matext_temp(const std::string& name) {
    return sherpa::test::temp_path("sherpa_cli_matext", name);
}

using sherpa::test::CliRun;
using sherpa::test::run_cli;

using sherpa::test::furnace_front;
using sherpa::test::kSweepCamera;
using sherpa::test::Png;
using sherpa::test::read_png;
using sherpa::test::sphere_centre;
using sherpa::test::sweep;

// The colour `view` draws at the front of a one-sphere file (its centre pixel, 160x120,
// seen from 1.5 in front): the texture-transform checks read it.
std::array<int, 3> front_pixel(const std::string& model, const std::string& view) {
    const std::string png = matext_temp(view + "_front.png");
    const CliRun run =
        run_cli("render '" + model + "' -o " + png + " --width 160 --height 120 --view " + view +
                " --camera eye=0,0,1.5:target=0,0,0:fov=45 --validation --no-cache");
    EXPECT_EQ(run.exit_code, 0) << run.out;
    const Png p = read_png(png);
    std::filesystem::remove(png);
    if (p.rgba.empty()) return {-1, -1, -1};
    return {p.at(80, 60)[0], p.at(80, 60)[1], p.at(80, 60)[2]};
}

std::uint64_t extension_bytes(const std::string& model, const std::string& name) {
    const std::string png = matext_temp(name + ".png"), report = matext_temp(name + ".json");
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
    // Ten materials with KHR_materials_ior only: a 48-byte index and one block of 16
    // bytes each.
    EXPECT_EQ(extension_bytes(sweep("ior_sweep"), "ior"), 640u);
    // Ten with KHR_materials_specular only: an index and a 96-byte block each.
    EXPECT_EQ(extension_bytes(sweep("specular_sweep"), "specular"), 1440u);
    // Ten with KHR_materials_clearcoat only: an index and a 128-byte block each.
    EXPECT_EQ(extension_bytes(sweep("clearcoat_sweep"), "clearcoat"), 1760u);
    // Ten with KHR_materials_sheen only: an index and a 96-byte block each.
    EXPECT_EQ(extension_bytes(sweep("sheen_sweep"), "sheen"), 1440u);
    // Ten with KHR_materials_anisotropy only: an index and a 64-byte block each.
    EXPECT_EQ(extension_bytes(sweep("anisotropy_sweep"), "anisotropy"), 1120u);
    // Ten with KHR_materials_iridescence only: an index and a 96-byte block each.
    EXPECT_EQ(extension_bytes(sweep("iridescence_sweep"), "iridescence"), 1440u);
}

TEST(CliMaterialExtensions, IorViewShowsEachSpheresIor) {
    const std::string png = matext_temp("ior_view.png");
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
    const std::string weight = matext_temp("weight.png"), colour = matext_temp("colour.png");
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
    for (const auto& [view, r, g] :
         {std::tuple{"specular-color", 255, 0}, std::tuple{"specular-weight", 0, 0}}) {
        const std::array<int, 3> c = front_pixel(sweep("specular_textures"), view);
        EXPECT_NEAR(c[0], r, 2) << view;
        EXPECT_NEAR(c[1], g, 2) << view;
    }
}

TEST(CliMaterialExtensions, ClearcoatViewsShowFactorAndRoughness) {
    const std::string factor = matext_temp("cc.png"), rough = matext_temp("ccr.png");
    for (const auto& [view, png] :
         {std::pair{"clearcoat", factor}, {"clearcoat-roughness", rough}}) {
        const CliRun r = run_cli("render '" + sweep("clearcoat_sweep") + "' -o " + png +
                                 " --width 160 --height 120 --view " + view + kSweepCamera +
                                 " --validation --no-cache");
        ASSERT_EQ(r.exit_code, 0) << r.out;
    }
    const Png f = read_png(factor), r = read_png(rough);
    const double steps[] = {0.0, 0.25, 0.5, 0.75, 1.0};
    for (int i = 0; i < 5; ++i) {
        EXPECT_NEAR(sphere_centre(f, 0, i)[0], steps[i] * 255.0, 1.0) << i;
        EXPECT_NEAR(sphere_centre(f, 1, i)[0], 255.0, 1.0) << i; // row 2: a full coat
        EXPECT_NEAR(sphere_centre(r, 0, i)[0], 0.0, 1.0) << i;   // row 1: smooth
        EXPECT_NEAR(sphere_centre(r, 1, i)[0], steps[i] * 255.0, 1.0) << i;
    }
    std::filesystem::remove(factor);
    std::filesystem::remove(rough);
}

// clearcoat_textures.gltf: clearcoatTexture (R) and clearcoatRoughnessTexture (G) read
// a 2x1 image (left R 1 G 0, right R 0 G 1) through KHR_texture_transform offset
// (0.5, 0): the front (u = 0.75) reads the left texel, coat 1 and roughness 0 (1 and
// 0 untransformed); the 1x1 clearcoatNormalTexture tilts the coat's normal onto the
// tangent, away from the geometry's normal (which faces the camera, encoded blue 255).
TEST(CliMaterialExtensions, ClearcoatTexturesAreSampledThroughTheirTransform) {
    for (const auto& [view, channel, lo, hi] :
         {std::tuple{"clearcoat", 0, 253, 255}, std::tuple{"clearcoat-roughness", 0, 0, 2},
          std::tuple{"clearcoat-normal", 2, 100, 160}}) {
        const std::array<int, 3> c = front_pixel(sweep("clearcoat_textures"), view);
        EXPECT_GE(c[channel], lo) << view;
        EXPECT_LE(c[channel], hi) << view;
    }
}

TEST(CliMaterialExtensions, SheenViewsShowColourAndRoughness) {
    const std::string colour = matext_temp("sheen.png"), rough = matext_temp("sheenr.png");
    for (const auto& [view, png] : {std::pair{"sheen-color", colour}, {"sheen-roughness", rough}}) {
        const CliRun r = run_cli("render '" + sweep("sheen_sweep") + "' -o " + png +
                                 " --width 160 --height 120 --view " + view + kSweepCamera +
                                 " --validation --no-cache");
        ASSERT_EQ(r.exit_code, 0) << r.out;
    }
    const Png c = read_png(colour), r = read_png(rough);
    const double steps[] = {0.0, 0.25, 0.5, 0.75, 1.0};
    for (int i = 0; i < 5; ++i) {
        // The colour is linear radiance, written sRGB-encoded like the base colour view.
        const double srgb =
            steps[i] <= 0.0031308 ? steps[i] * 12.92 : 1.055 * std::pow(steps[i], 1 / 2.4) - 0.055;
        EXPECT_NEAR(sphere_centre(c, 0, i)[1], srgb * 255.0, 1.5) << i;
        EXPECT_NEAR(sphere_centre(c, 1, i)[1], 255.0, 1.0) << i;
        EXPECT_NEAR(sphere_centre(r, 0, i)[0], 0.5 * 255.0, 1.0) << i;
        EXPECT_NEAR(sphere_centre(r, 1, i)[0], steps[i] * 255.0, 1.0) << i;
    }
    std::filesystem::remove(colour);
    std::filesystem::remove(rough);
}

// sheen_textures.gltf: sheenColorTexture and sheenRoughnessTexture read a 2x1 image
// (left red, alpha 0; right green, alpha 1) through KHR_texture_transform offset
// (0.5, 0): the front reads red and roughness 0 (green and 1 untransformed).
TEST(CliMaterialExtensions, SheenTexturesAreSampledThroughTheirTransform) {
    for (const auto& [view, r, g] :
         {std::tuple{"sheen-color", 255, 0}, std::tuple{"sheen-roughness", 0, 0}}) {
        const std::array<int, 3> c = front_pixel(sweep("sheen_textures"), view);
        EXPECT_NEAR(c[0], r, 2) << view;
        EXPECT_NEAR(c[1], g, 2) << view;
    }
}

// The direction view's expected colour at a sweep sphere's centre pixel: the point
// that faces the eye (0, 0, 5), its authored tangent (along u, around the sphere) and
// bitangent cross(n, t) (up at the front), the tangent rotated toward the bitangent
// by `degrees`, encoded as the normal view.
glm::dvec3 expected_direction(int row, int column, double degrees) {
    const glm::dvec3 centre(column - 2.0, 0.5 - row, 0.0);
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.0, 0.0, 5.0) - centre);
    const double phi = std::atan2(-n.z, n.x); // n = (sin t cos phi, cos t, -sin t sin phi)
    const glm::dvec3 t(-std::sin(phi), 0.0, -std::cos(phi));
    const glm::dvec3 b = glm::cross(n, t);
    const double a = degrees * 3.14159265358979 / 180.0;
    glm::dvec3 d = std::cos(a) * t + std::sin(a) * b;
    d = glm::normalize(d - n * glm::dot(n, d));
    return (d * 0.5 + 0.5) * 255.0;
}

// anisotropy_sweep.gltf: the strength view shows each sphere's strength (row 1 0 .. 1,
// row 2 0.8); the direction view, at each sphere's centre, the tangent (row 1) rotated
// counter-clockwise toward the bitangent by row 2's angles.
TEST(CliMaterialExtensions, AnisotropyViewsShowStrengthAndDirection) {
    const std::string strength = matext_temp("as.png"), direction = matext_temp("ad.png");
    for (const auto& [view, png] :
         {std::pair{"anisotropy-strength", strength}, {"anisotropy-direction", direction}}) {
        const CliRun r = run_cli("render '" + sweep("anisotropy_sweep") + "' -o " + png +
                                 " --width 160 --height 120 --view " + view + kSweepCamera +
                                 " --validation --no-cache");
        ASSERT_EQ(r.exit_code, 0) << r.out;
    }
    const Png s = read_png(strength), d = read_png(direction);
    const double steps[] = {0.0, 0.25, 0.5, 0.75, 1.0};
    const double degrees[] = {0.0, 30.0, 60.0, 90.0, 135.0};
    for (int i = 0; i < 5; ++i) {
        EXPECT_NEAR(sphere_centre(s, 0, i)[0], steps[i] * 255.0, 1.0) << i;
        EXPECT_NEAR(sphere_centre(s, 1, i)[0], 0.8 * 255.0, 1.0) << i;
        for (int row = 0; row < 2; ++row) {
            const glm::dvec3 want = expected_direction(row, i, row == 0 ? 0.0 : degrees[i]);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(sphere_centre(d, row, i)[c], want[c], 8.0)
                    << row << " " << i << " " << c;
        }
    }
    std::filesystem::remove(strength);
    std::filesystem::remove(direction);
}

// The film's Fresnel is one function for both renderers: in a uniform environment, the
// front of iridescence_textures.gltf (factor 1, 400 nm on a black dielectric, roughness
// 0.2) reflects the same coloured light rasterized (the split-sum with the film's F0)
// and path traced (the film's Fresnel at n . v in the BRDF), per channel.
TEST(CliMaterialExtensions, IridescenceRasterAndPathTracerAgreeInAFurnace) {
    const glm::dvec3 raster = furnace_front(sweep("iridescence_textures"), "");
    const glm::dvec3 traced =
        furnace_front(sweep("iridescence_textures"), " --renderer rt --spp 64");
    std::printf("iridescence furnace: raster %.4f %.4f %.4f, path traced %.4f %.4f %.4f\n",
                raster.r, raster.g, raster.b, traced.r, traced.g, traced.b);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(raster[c], traced[c], 0.004) << c;
    // Coloured: the film at 400 nm reflects green and blue over red (a grey F0 would not).
    EXPECT_GT(raster.g, raster.r + 0.02);
}

// anisotropy_textures.gltf: anisotropyTexture reads a 2x1 image (left: direction +y,
// strength 1; right: +x, strength 0) through KHR_texture_transform offset (0.5, 0):
// the front reads strength 1 along the bitangent (+Y there, green 255); untransformed
// it would read strength 0 along +X.
TEST(CliMaterialExtensions, AnisotropyTextureIsSampledThroughItsTransform) {
    const std::array<int, 3> s = front_pixel(sweep("anisotropy_textures"), "anisotropy-strength");
    EXPECT_NEAR(s[0], 255, 2);
    const std::array<int, 3> d = front_pixel(sweep("anisotropy_textures"), "anisotropy-direction");
    EXPECT_NEAR(d[0], 128, 4);
    EXPECT_NEAR(d[1], 255, 4);
}

// iridescence_sweep.gltf: the factor view shows row 1's factor 0 .. 1 and row 2's full
// films; the thickness view 0.4 um (the default 400 nm) along row 1 and 0.1 .. 0.7 um
// along row 2.
TEST(CliMaterialExtensions, IridescenceViewsShowFactorAndThickness) {
    const std::string factor = matext_temp("ir.png"), thickness = matext_temp("irt.png");
    for (const auto& [view, png] :
         {std::pair{"iridescence", factor}, {"iridescence-thickness", thickness}}) {
        const CliRun r = run_cli("render '" + sweep("iridescence_sweep") + "' -o " + png +
                                 " --width 160 --height 120 --view " + view + kSweepCamera +
                                 " --validation --no-cache");
        ASSERT_EQ(r.exit_code, 0) << r.out;
    }
    const Png f = read_png(factor), t = read_png(thickness);
    const double steps[] = {0.0, 0.25, 0.5, 0.75, 1.0};
    const double nm[] = {100.0, 250.0, 400.0, 550.0, 700.0};
    for (int i = 0; i < 5; ++i) {
        EXPECT_NEAR(sphere_centre(f, 0, i)[0], steps[i] * 255.0, 1.0) << i;
        EXPECT_NEAR(sphere_centre(f, 1, i)[0], 255.0, 1.0) << i;
        EXPECT_NEAR(sphere_centre(t, 0, i)[0], 0.4 * 255.0, 1.0) << i;
        EXPECT_NEAR(sphere_centre(t, 1, i)[0], nm[i] / 1000.0 * 255.0, 1.0) << i;
    }
    std::filesystem::remove(factor);
    std::filesystem::remove(thickness);
}

// iridescence_textures.gltf: iridescenceTexture (R) and iridescenceThicknessTexture (G)
// read a 2x1 image (left R 1 G 0.5, right R 0 G 1) through KHR_texture_transform offset
// (0.5, 0): the front reads factor 1 and mix(200, 600, 0.5) = 400 nm (factor 0 and
// 600 nm untransformed).
TEST(CliMaterialExtensions, IridescenceTexturesAreSampledThroughTheirTransform) {
    EXPECT_NEAR(front_pixel(sweep("iridescence_textures"), "iridescence")[0], 255, 2);
    EXPECT_NEAR(front_pixel(sweep("iridescence_textures"), "iridescence-thickness")[0], 102, 2);
}

TEST(CliMaterialExtensions, BadValuesAreWarnedOnStderrAndTheFileStillRenders) {
    const std::string png = matext_temp("bad.png");
    const CliRun r =
        run_cli("render '" + (sherpa::test::data_dir() / "material_extensions_bad.gltf").string() +
                "' -o " + png + " --width 64 --height 48 --validation --no-cache");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("KHR_materials_ior.ior: -1 is not an index of refraction"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("specularFactor: 2 is outside 0..1"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("clearcoatFactor: -0.5 is outside 0..1; clamped to 0"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("anisotropyStrength: 1.5 is outside 0..1; clamped to 1"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("anisotropyRotation: not a finite number; the default 0 is used"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("iridescenceIor: 0.5 is below 1; the default 1.3 is used"),
              std::string::npos)
        << r.out;
    // The missing image, named with the slot that reads it.
    EXPECT_NE(r.out.find("missing_specular_color.png (used by material 'missing specular "
                         "texture' KHR_materials_specular.specularColorTexture; material "
                         "'anisotropy not finite' KHR_materials_anisotropy.anisotropyTexture)"),
              std::string::npos)
        << r.out;
    std::filesystem::remove(png);
}

} // namespace
