// POINTS, LINES, LINE_STRIP and LINE_LOOP primitives: imported with their topology,
// counted (segments/points, not triangles), in the scene bounds, culled, and drawn
// unlit by sherpa-cli render with validation on. The point test checks pixels at
// positions computed here from the camera's pinhole model (glTF's perspective
// projection), not from the renderer's matrices.
#include "cli/cli_run.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/image.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

std::string base64(const std::vector<std::uint8_t>& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const std::uint32_t n = std::uint32_t(in[i]) << 16 |
                                (i + 1 < in.size() ? std::uint32_t(in[i + 1]) << 8 : 0) |
                                (i + 2 < in.size() ? in[i + 2] : 0);
        out += t[n >> 18 & 63];
        out += t[n >> 12 & 63];
        out += i + 1 < in.size() ? t[n >> 6 & 63] : '=';
        out += i + 2 < in.size() ? t[n & 63] : '=';
    }
    return out;
}

// One primitive of `mode` over `positions` (no indices), red unlit-by-topology
// base colour; written to a temp file.
std::string write_gltf(const std::string& name, int mode, const std::vector<float>& positions) {
    std::vector<std::uint8_t> bytes(positions.size() * 4);
    std::memcpy(bytes.data(), positions.data(), bytes.size());
    std::vector<float> lo(3, 1e30f), hi(3, -1e30f);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], positions[i]);
        hi[i % 3] = std::max(hi[i % 3], positions[i]);
    }
    const nlohmann::json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes",
         {{{"primitives",
            {{{"attributes", {{"POSITION", 0}}}, {"mode", mode}, {"material", 0}}}}}}},
        {"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 0.0, 0.0, 1.0}}}}}}},
        {"buffers",
         {{{"uri", "data:application/octet-stream;base64," + base64(bytes)},
           {"byteLength", bytes.size()}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", bytes.size()}}}},
        {"accessors",
         {{{"bufferView", 0},
           {"componentType", 5126},
           {"count", positions.size() / 3},
           {"type", "VEC3"},
           {"min", lo},
           {"max", hi}}}}};
    const fs::path out =
        fs::temp_directory_path() / ("sherpa_pl_" + std::to_string(getpid()) + "_" + name);
    std::ofstream(out) << doc.dump();
    return out.string();
}

struct RenderedImage {
    std::uint32_t w = 0, h = 0;
    std::vector<std::uint8_t> rgba;
    bool red(int x, int y) const {
        const std::uint8_t* p = &rgba[(std::size_t(y) * w + std::size_t(x)) * 4];
        return p[0] > 200 && p[1] < 60 && p[2] < 60;
    }
};

RenderedImage render_rgba(const std::string& scene, const std::string& extra = "") {
    const std::string png = scene + ".png";
    const test::CliRun r = test::run_cli("render '" + scene + "' -o '" + png +
                                         "' --width 64 --height 64 --validation --no-shadows"
                                         " --camera eye=0,0,5:target=0,0,0:fov=60 " +
                                         extra);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    RenderedImage img;
    std::string error;
    EXPECT_TRUE(sherpa::tex::read_png_rgba8(png, img.w, img.h, img.rgba, error)) << error;
    return img;
}

TEST(PointsAndLines, ImportedWithTopologyCountsAndBounds) {
    const std::vector<float> square = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    struct Case {
        int mode;
        sherpa::scene::Topology topology;
        std::uint32_t elements;
    };
    for (const Case c :
         {Case{0, sherpa::scene::Topology::Points, 4}, Case{1, sherpa::scene::Topology::Lines, 2},
          Case{2, sherpa::scene::Topology::Lines, 4}, Case{3, sherpa::scene::Topology::Lines, 3}}) {
        const std::string path =
            write_gltf("mode" + std::to_string(c.mode) + ".gltf", c.mode, square);
        const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
        ASSERT_TRUE(r) << r.error;
        ASSERT_EQ(r.scene->meshes.size(), 1u) << "mode " << c.mode;
        EXPECT_EQ(r.scene->meshes[0].topology(), c.topology);
        EXPECT_EQ(r.scene->meshes[0].element_count(), c.elements) << "mode " << c.mode;
        EXPECT_EQ(r.scene->counts.triangles, 0u);
        ASSERT_TRUE(r.scene->bounds.valid()) << "mode " << c.mode;
        EXPECT_EQ(r.scene->bounds.min, glm::vec3(-1, -1, 0));
        EXPECT_EQ(r.scene->bounds.max, glm::vec3(1, 1, 0));
        const test::CliRun info = test::run_cli("info '" + path + "' --json", "2>/dev/null");
        ASSERT_EQ(info.exit_code, 0) << info.out;
        const auto p = nlohmann::json::parse(info.out).at("primitives_detail").at(0);
        EXPECT_EQ(p.at(c.topology == sherpa::scene::Topology::Points ? "points" : "segments"),
                  c.elements);
        EXPECT_EQ(p.at("triangles"), 0);
        EXPECT_FALSE(p.contains("skipped"));
    }
}

TEST(PointsAndLines, CulledLikeAnyInstance) {
    const std::string path = write_gltf("cull.gltf", 3, {-1, 0, 0, 1, 0, 0});
    for (const char* method : {"pvertex", "gpu"}) {
        const test::CliRun in = test::run_cli("cull '" + path + "' --json --method " + method +
                                                  " --camera eye=0,0,5:target=0,0,0",
                                              "2>/dev/null");
        ASSERT_EQ(in.exit_code, 0) << in.out;
        const auto camera = nlohmann::json::parse(in.out).at("passes").at(0);
        EXPECT_EQ(camera.at("visible").size(), 1u) << method << " " << in.out;
        const test::CliRun away = test::run_cli("cull '" + path + "' --json --method " + method +
                                                    " --camera eye=0,0,5:target=0,0,10",
                                                "2>/dev/null");
        ASSERT_EQ(away.exit_code, 0) << away.out;
        EXPECT_EQ(nlohmann::json::parse(away.out).at("passes").at(0).at("visible").size(), 0u)
            << method;
    }
}

// Pinhole projection of a point on the z = 0 plane seen from (0,0,5) towards the
// origin with a 60 degree vertical field of view, into 64x64 pixel coordinates
// (x right, y down; pixel centres at .5).
glm::vec2 pixel_of(glm::vec2 p) {
    const double f = 1.0 / std::tan(30.0 * M_PI / 180.0);
    const double nx = p.x / 5.0 * f, ny = p.y / 5.0 * f;
    return {float((nx + 1.0) / 2.0 * 64.0), float((1.0 - ny) / 2.0 * 64.0)};
}

TEST(PointsAndLines, PointsAreDrawnAtTheirProjectedPixelsWithAVisibleSize) {
    const std::vector<glm::vec2> points = {{1, 0}, {0, 1}, {-1.5f, -1}};
    std::vector<float> positions;
    for (glm::vec2 p : points) positions.insert(positions.end(), {p.x, p.y, 0.0f});
    for (const char* cull : {"none", "cpu", "gpu"}) {
        const RenderedImage img =
            render_rgba(write_gltf(std::string("points_") + cull + ".gltf", 0, positions),
                        std::string("--cull ") + cull);
        ASSERT_EQ(img.w, 64u);
        int red = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) red += img.red(x, y);
        // Each point covers the pixels whose centres lie in a 4x4 px square around
        // its projection (Vulkan point rasterization): 16 each.
        EXPECT_EQ(red, 16 * int(points.size())) << "cull " << cull;
        for (glm::vec2 p : points) {
            const glm::vec2 c = pixel_of(p);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    EXPECT_TRUE(img.red(int(std::floor(c.x)) + dx, int(std::floor(c.y)) + dy))
                        << "point (" << p.x << "," << p.y << ") at pixel " << c.x << "," << c.y;
            EXPECT_FALSE(img.red(int(c.x) + 4, int(c.y)));
            EXPECT_FALSE(img.red(int(c.x) - 4, int(c.y)));
        }
    }
}

TEST(PointsAndLines, LineOnlyFileRendersItsLinesValidationClean) {
    // A LINE_LOOP square: its four sides cross the pixel rows and columns they project
    // to, kLineWidthPixels (2) wide on a device with wideLines (lavapipe has them).
    const std::string path = write_gltf("loop.gltf", 2, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});
    const RenderedImage img = render_rgba(path);
    ASSERT_EQ(img.w, 64u);
    const glm::vec2 lo = pixel_of({-1, -1}), hi = pixel_of({1, 1});
    int red = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) red += img.red(x, y);
    const float side = lo.y - hi.y; // pixels
    EXPECT_GE(red, int(2 * 4 * side) - 16) << "four 2-pixel sides";
    EXPECT_LE(red, int(2 * 4 * side) + 16);
    // Every red pixel lies on the square's outline (its centre within the line's
    // half width of 1 px, plus a pixel of rasterization slack).
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            if (!img.red(x, y)) continue;
            const float px = float(x) + 0.5f, py = float(y) + 0.5f;
            const bool on = std::abs(px - lo.x) <= 1.5f || std::abs(px - hi.x) <= 1.5f ||
                            std::abs(py - lo.y) <= 1.5f || std::abs(py - hi.y) <= 1.5f;
            EXPECT_TRUE(on) << x << "," << y;
        }
    // Across the middle of each vertical side, exactly two red pixels: the width.
    const int mid = int((lo.y + hi.y) / 2);
    for (const float side_x : {lo.x, hi.x}) {
        int across = 0;
        for (int x = int(side_x) - 3; x <= int(side_x) + 3; ++x) across += img.red(x, mid);
        EXPECT_EQ(across, 2) << "line width at x " << side_x;
    }
}

} // namespace
