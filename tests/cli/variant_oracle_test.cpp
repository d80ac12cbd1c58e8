// KHR_materials_variants against three.js: `render --variant NAME` and three.js with the
// variant applied as its own example does (tools/render_oracle/three_render.mjs
// --variant). tests/data/material_sweeps/variants.gltf (make_sweeps.py): three unlit
// spheres, so that both renderers draw the factors as they are; each sphere's mean
// colour must agree between them, and match what the file's mapping names.
#include "cli/cli_run.h"
#include "cli/oracle_image.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace sherpa::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCamera = "eye=0,0,5:target=0,0,0:fov=45:near=0.1:far=100";

// Mean 8-bit colour (/255) of a disk inside sphere `column` (x = -1, 0, 1; y = 0).
glm::dvec3 sphere_mean(const Image& img, int column) {
    const double half_height = 5.0 * std::tan(22.5 * 3.14159265358979 / 180.0);
    const double x = column - 1.0;
    const double cx = img.width * 0.5 * (1.0 + x / (half_height * img.width / img.height));
    const double cy = img.height * 0.5;
    const double r = 0.6 * 0.4 / half_height * img.height * 0.5;
    return disk_mean(img, cx, cy, r);
}

// Both renderers' images of the file with `variant` ("" for the defaults).
std::pair<Image, Image> render_both(const std::string& variant) {
    const std::string file = std::string(SHERPA_TEST_DATA_DIR) + "/material_sweeps/variants.gltf";
    const fs::path out = fs::path(SHERPA_ORACLE_OUT);
    fs::create_directories(out);
    const std::string tag = "variant_" + (variant.empty() ? std::string("default") : variant);
    const fs::path ours = out / (tag + "_sherpa.png"), theirs = out / (tag + "_three.png");
    const std::string common = " --width 320 --height 240 --camera " + quoted(kCamera) +
                               " --background 1,0,1 --tone-map linear" +
                               (variant.empty() ? "" : " --variant " + quoted(variant));
    const CliRun r = run_cli("render " + quoted(file) + " -o " + quoted(ours.string()) + common +
                             " --environment none --sun off");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    const std::string node = std::string(SHERPA_NODE) + " " + SHERPA_RENDER_ORACLE_SCRIPT +
                             " --cache " + quoted(SHERPA_RENDER_ORACLE_CACHE) + " --gltf " +
                             quoted(file) + " --out " + quoted(theirs.string()) + common + " 2>&1";
    std::string log;
    if (FILE* p = popen(node.c_str(), "r")) {
        char buf[4096];
        for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) log.append(buf, n);
        EXPECT_EQ(pclose(p), 0) << log;
    } else {
        ADD_FAILURE() << "cannot run " << node;
    }
    return {read(ours), read(theirs)};
}

// linear 0..1 -> 8-bit sRGB / 255
double srgb(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

TEST(VariantOracle, SherpaAndThreeJsShowTheSameMaterialsPerVariant) {
    const glm::dvec3 grey(srgb(0.5)), red(1, 0, 0), green(0, 1, 0), magenta(1, 0, 1);
    struct Expect {
        const char* variant;
        glm::dvec3 spheres[3]; // from the file; negative: compared between renderers only
    };
    const glm::dvec3 any(-1.0);
    const Expect cases[] = {{"", {grey, grey, grey}},
                            {"Warm", {red, grey, any}},        // sphere 2: the checker texture
                            {"Cool", {grey, magenta, green}}}; // sphere 1 masked away
    for (const Expect& e : cases) {
        const auto [a, b] = render_both(e.variant);
        ASSERT_FALSE(a.rgba.empty());
        ASSERT_FALSE(b.rgba.empty());
        for (int s = 0; s < 3; ++s) {
            const glm::dvec3 ma = sphere_mean(a, s), mb = sphere_mean(b, s);
            const glm::dvec3 d = glm::abs(ma - mb);
            std::printf("variant oracle '%s' sphere %d: sherpa %.3f %.3f %.3f, three %.3f %.3f "
                        "%.3f\n",
                        e.variant, s, ma.x, ma.y, ma.z, mb.x, mb.y, mb.z);
            EXPECT_LE(std::max({d.x, d.y, d.z}), 0.02) << e.variant << " sphere " << s;
            if (e.spheres[s].x < 0.0) {
                // The checker (yellow and blue texels): not the grey it replaces.
                const glm::dvec3 g = glm::abs(ma - grey);
                EXPECT_GT(std::max({g.x, g.y, g.z}), 0.1) << e.variant << " sphere " << s;
                continue;
            }
            const glm::dvec3 f = glm::abs(ma - e.spheres[s]);
            EXPECT_LE(std::max({f.x, f.y, f.z}), 0.01) << e.variant << " sphere " << s;
        }
    }
}

} // namespace
} // namespace sherpa::test
