// The selection highlight draws: the highlighted instance's surface is tinted
// orange with its shading still showing (every tinted pixel a mix of the plain
// render and orange, never solid orange) and its box in orange; a highlighted
// triangle and vertex magenta pixels; an instance that is not drawn changes nothing. The
// highlighted render is written to highlight_box.png next to the test binary for inspection.
#include "gpu_test_support.h"

#include <sherpa/texture/image.h>

#include <algorithm>
#include <cstdlib>

namespace sherpa::test {
namespace {

constexpr std::uint32_t kSize = 160;

struct Counts {
    std::size_t orange = 0, magenta = 0;
};

Counts count_highlight(const std::vector<std::uint8_t>& rgba) {
    // sRGB encodings of kHighlightColor (255, 180, 0) and kHighlightDetailColor.
    Counts c;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        const int r = rgba[i], g = rgba[i + 1], b = rgba[i + 2];
        if (r > 235 && g > 160 && g < 200 && b < 30) ++c.orange;
        if (r > 235 && g < 30 && b > 235) ++c.magenta;
    }
    return c;
}

struct Tint {
    std::size_t tinted = 0; // changed pixels that lie between the plain pixel and orange
    std::size_t solid = 0;  // changed pixels that went (almost) solid orange
    std::size_t other = 0;  // changed any other way
};

// Compares a highlighted render with the plain one, pixel by pixel.
Tint classify_tint(const std::vector<std::uint8_t>& plain, const std::vector<std::uint8_t>& lit) {
    const int orange[3] = {255, 180, 0}; // kHighlightColor, sRGB-encoded
    Tint t;
    for (std::size_t i = 0; i < plain.size(); i += 4) {
        bool changed = false, between = true, near_orange = true;
        for (int c = 0; c < 3; ++c) {
            const int p = plain[i + std::size_t(c)], l = lit[i + std::size_t(c)];
            changed |= std::abs(l - p) > 2;
            between &= l >= std::min(p, orange[c]) - 3 && l <= std::max(p, orange[c]) + 3;
            near_orange &= std::abs(l - orange[c]) < 25;
        }
        if (!changed) continue;
        if (near_orange)
            ++t.solid;
        else if (between)
            ++t.tinted;
        else
            ++t.other;
    }
    return t;
}

class HighlightTest : public GpuTest {
protected:
    gpu::RenderSettings settings() {
        gpu::RenderSettings s;
        s.width = s.height = kSize;
        std::string error;
        EXPECT_TRUE(gpu::parse_camera_spec("eye=1.5,1.2,2:target=0,0,0", s.camera, error)) << error;
        return s;
    }
};

TEST_F(HighlightTest, SelectedInstanceTriangleAndVertexAreDrawn) {
    auto scene = load(gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    ASSERT_EQ(scene->instances.size(), 1u);
    renderer().load(*scene);
    gpu::RenderSettings s = settings();
    const std::vector<std::uint8_t> plain_rgba = draw(s);
    const Counts plain = count_highlight(plain_rgba);

    s.highlight_instance = 0;
    const std::vector<std::uint8_t> lit_rgba = draw(s);
    const Counts instance = count_highlight(lit_rgba);
    EXPECT_GT(instance.orange, plain.orange + 200) << "the box in orange";
    EXPECT_EQ(instance.magenta, plain.magenta);
    // The box covers about a quarter of the 160² image: its surface is tinted, and
    // the tint keeps the shading (a mix with the plain pixel), apart from the box
    // edges drawn in solid orange.
    const Tint tint = classify_tint(plain_rgba, lit_rgba);
    EXPECT_GT(tint.tinted, kSize * kSize / 8) << "the surface is tinted";
    EXPECT_LT(tint.solid, tint.tinted / 4) << "solid orange only on the box's edges";
    EXPECT_LT(tint.other, tint.tinted / 50) << "nothing but a mix towards orange";

    s.highlight_triangle = 0;
    s.highlight_vertex = 0;
    const std::vector<std::uint8_t> detailed = draw(s);
    const Counts detail = count_highlight(detailed);
    EXPECT_GT(detail.magenta, plain.magenta + 100) << "filled triangle and vertex tripod";
    std::string error;
    EXPECT_TRUE(tex::write_png("highlight_box.png", kSize, kSize, detailed, error)) << error;

    // Out of range: no instance, so nothing is highlighted (and nothing breaks).
    s.highlight_instance = 7;
    const Counts none = count_highlight(draw(s));
    EXPECT_EQ(none.orange, plain.orange);
    EXPECT_EQ(none.magenta, plain.magenta);
    renderer().unload();
}

TEST_F(HighlightTest, HighlightAlongsideOtherLineOverlays) {
    // The box overlay, the cull overlay and the highlight share the frame's line buffer.
    auto scene = load("builtin:default");
    ASSERT_TRUE(scene);
    renderer().load(*scene);
    gpu::RenderSettings s = settings();
    s.camera = {};
    s.overlays = gpu::kOverlayBounds | gpu::kOverlayCullBoxes;
    const Counts plain = count_highlight(draw(s));
    s.highlight_instance = static_cast<std::uint32_t>(scene->instances.size() / 2);
    const Counts lit = count_highlight(draw(s));
    EXPECT_GT(lit.orange, plain.orange);
    renderer().unload();
}

} // namespace
} // namespace sherpa::test
