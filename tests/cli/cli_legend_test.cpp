// The numbers and classes a CLI image stands for are in the image: `compare --image`
// draws the heat over a dimmed side A, both sides and a legend with its numbers;
// render's provenance view carries its legend. Text is found by matching the built-in
// font's glyphs pixel for pixel (white on the legend's dark box) in the PNG as read by
// libpng, and the numbers searched for are the ones --json reports.
#include "cli/cli_run.h"
#include "reference/reference_images.h"
#include "test_support.h"

#include <sherpa/texture/image_text.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

bool white(const std::uint8_t* p) {
    return p[0] == 255 && p[1] == 255 && p[2] == 255;
}

// Whether `text` is drawn at scale 1 in white anywhere in `img` (glyph pixels white,
// the cells' other pixels not).
bool has_text(const test::ReferenceImage& img, const std::string& text) {
    const std::uint32_t w = sherpa::tex::text_width(text), h = sherpa::tex::kGlyphHeight;
    if (w == 0 || w > img.width || h > img.height) return false;
    for (std::uint32_t y = 0; y + h <= img.height; ++y)
        for (std::uint32_t x = 0; x + w <= img.width; ++x) {
            bool match = true;
            for (std::size_t i = 0; i < text.size() && match; ++i) {
                const auto rows = sherpa::tex::glyph_rows(text[i]);
                for (std::uint32_t r = 0; r < h && match; ++r)
                    for (std::uint32_t c = 0; c < sherpa::tex::kGlyphWidth && match; ++c) {
                        const bool set = rows[r] & (0x10u >> c);
                        match = set ==
                                white(img.texel(
                                    x + std::uint32_t(i) * sherpa::tex::kGlyphAdvance + c, y + r));
                    }
            }
            if (match) return true;
        }
    return false;
}

std::string format(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

// Box.gltf with its one material turned from red to blue, beside its buffer.
fs::path blue_box(const fs::path& dir) {
    const fs::path box = fs::path(test::gltf_asset("Box"));
    nlohmann::json j = nlohmann::json::parse(std::ifstream(box));
    j["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.0, 0.1, 0.8, 1.0};
    fs::copy_file(box.parent_path() / "Box0.bin", dir / "Box0.bin",
                  fs::copy_options::overwrite_existing);
    const fs::path out = dir / "BlueBox.gltf";
    std::ofstream(out) << j.dump();
    return out;
}

struct PanelCounts {
    std::size_t red = 0, blue = 0, grey = 0, black = 0, pixels = 0;
};

PanelCounts count(const test::ReferenceImage& img, std::uint32_t x0, std::uint32_t y0,
                  std::uint32_t x1, std::uint32_t y1) {
    PanelCounts n;
    for (std::uint32_t y = y0; y < y1; ++y)
        for (std::uint32_t x = x0; x < x1; ++x) {
            const std::uint8_t* p = img.texel(x, y);
            ++n.pixels;
            n.red += p[0] > p[2] + 40 && p[0] > p[1] + 40;
            n.blue += p[2] > p[0] + 40;
            n.grey += p[0] == p[1] && p[1] == p[2] && p[0] > 0;
            n.black += p[0] == 0 && p[1] == 0 && p[2] == 0;
        }
    return n;
}

TEST(CliLegend, CompareImageShowsTheDifferenceOverSideABothSidesAndItsNumbers) {
    const fs::path dir = fs::temp_directory_path() / ("sherpa_legend_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const fs::path png = dir / "difference.png";
    const test::CliRun r =
        test::run_cli("compare '" + test::gltf_asset("Box") + "' '" + blue_box(dir).string() +
                          "' --json --image '" + png.string() + "'",
                      "2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out)["image"];
    test::ReferenceImage img;
    std::string error;
    ASSERT_TRUE(test::read_png_reference(png, img, error)) << error;
    ASSERT_EQ(img.width, j["size"][0].get<std::uint32_t>());
    ASSERT_EQ(img.height, j["size"][1].get<std::uint32_t>());
    const std::uint32_t w = 640, h = 360; // the difference panel, then the sides at half size
    ASSERT_GE(img.height, h + h / 2 + 40);

    // The difference panel: the box's pixels differ (heat), the rest is side A in grey,
    // not black: the render says where the difference is.
    const PanelCounts diff = count(img, 0, 12, w, h);
    EXPECT_GT(diff.grey, diff.pixels / 2) << "side A dimmed under the heat";
    EXPECT_LT(diff.black, diff.pixels / 20);
    EXPECT_GT(diff.pixels - diff.grey - diff.black, diff.pixels / 50) << "heat where the box is";
    // Both sides of the material difference: red A on the left, blue B on the right.
    const PanelCounts a = count(img, 0, h + 12, w / 2, h + h / 2);
    const PanelCounts b = count(img, w / 2, h + 12, w, h + h / 2);
    EXPECT_GT(a.red, a.pixels / 50);
    EXPECT_EQ(a.blue, 0u);
    EXPECT_GT(b.blue, b.pixels / 50);
    EXPECT_EQ(b.red, 0u);
    EXPECT_TRUE(has_text(img, "A: Box.gltf"));
    EXPECT_TRUE(has_text(img, "B: BlueBox.gltf"));

    // The legend's numbers are the ones --json reports.
    const double psnr = j["psnr_db"].get<double>();
    EXPECT_TRUE(has_text(img, "PSNR " + format("%.2f", psnr) + " dB")) << psnr;
    EXPECT_TRUE(has_text(img, "mean " + format("%.3g", j["mean"].get<double>())));
    EXPECT_TRUE(has_text(img, ">= " + format("%.3g", j["scale"].get<double>())));
    EXPECT_TRUE(has_text(img, format("%.2f", j["over_threshold_percent"].get<double>()) +
                                  "% of pixels over " + std::to_string(j["threshold"].get<int>())));
    // And the material's field, both values, under the legend.
    EXPECT_TRUE(has_text(img, "material 0 ")) << "the material difference is named";
    fs::remove_all(dir);
}

TEST(CliLegend, ProvenanceViewCarriesItsLegend) {
    const fs::path png =
        fs::temp_directory_path() / ("sherpa_provenance_" + std::to_string(getpid()) + ".png");
    // DamagedHelmet gives no tangents: they are generated (yellow).
    const test::CliRun r =
        test::run_cli("render '" + test::gltf_asset("DamagedHelmet") + "' -o '" + png.string() +
                      "' --view provenance --width 320 --height 240 "
                      "--cache-dir '" SHERPA_TEST_TEXTURE_CACHE "'");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("view provenance: green tangents authored, yellow tangents generated, "
                         "red tangents defaulted (legend drawn bottom left)"),
              std::string::npos)
        << r.out;
    test::ReferenceImage img;
    std::string error;
    ASSERT_TRUE(test::read_png_reference(png, img, error)) << error;
    for (const char* name : {"tangents authored", "tangents generated", "tangents defaulted"})
        EXPECT_TRUE(has_text(img, name)) << name;
    // The swatch's colour is the colour the helmet is drawn in: the legend tells the
    // truth about the picture. The swatch sits left of its label.
    std::uint32_t sx = 0, sy = 0;
    bool found = false;
    for (std::uint32_t y = img.height / 2; y < img.height && !found; ++y)
        for (std::uint32_t x = 0; x < 12 && !found; ++x) {
            const std::uint8_t* p = img.texel(x, y);
            if (p[0] > 200 && p[1] > 150 && p[2] < 80) sx = x, sy = y, found = true;
        }
    ASSERT_TRUE(found) << "a yellow swatch";
    const std::uint8_t* swatch = img.texel(sx, sy);
    std::size_t same = 0;
    for (std::uint32_t y = 0; y < img.height / 2; ++y)
        for (std::uint32_t x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.texel(x, y);
            same += std::abs(p[0] - swatch[0]) <= 1 && std::abs(p[1] - swatch[1]) <= 1 &&
                    std::abs(p[2] - swatch[2]) <= 1;
        }
    EXPECT_GT(same, std::size_t(img.width) * img.height / 40) << "helmet pixels in the colour";
    fs::remove(png);
}

} // namespace
