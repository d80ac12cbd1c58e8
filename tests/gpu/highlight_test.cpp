// The selection highlight is an outline: the highlighted instance keeps every pixel of
// its interior as the plain render drew it (its material can still be judged, and the
// missing-texture checker is not turned pink and olive by a tint), while an orange
// ring appears just outside its silhouette; single-sided (back-face edges) and
// double-sided (biased edges) meshes alike. A highlighted triangle and vertex draw
// magenta; more instances can be outlined (a node's subtree); an instance that is not
// drawn changes nothing. The highlighted render is written to highlight_box.png next
// to the test binary for inspection.
#include "gpu_test_support.h"

#include <sherpa/texture/image.h>

#include <algorithm>
#include <cstdlib>

namespace sherpa::test {
namespace {

constexpr int kHighlightImageSize = 160;

struct Counts {
    std::size_t orange = 0, magenta = 0;
};

bool is_orange(const std::uint8_t* p) { // sRGB of kHighlightColor: (255, 180, 0)
    return p[0] > 235 && p[1] > 160 && p[1] < 200 && p[2] < 30;
}

Counts count_highlight(const std::vector<std::uint8_t>& rgba) {
    Counts c;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        const int r = rgba[i], g = rgba[i + 1], b = rgba[i + 2];
        if (is_orange(&rgba[i])) ++c.orange;
        if (r > 235 && g < 30 && b > 235) ++c.magenta;
    }
    return c;
}

// The plain render's object mask: pixels unlike the background (the corner's).
std::vector<bool> object_mask(const std::vector<std::uint8_t>& rgba) {
    std::vector<bool> mask(kHighlightImageSize * kHighlightImageSize);
    for (int i = 0; i < kHighlightImageSize * kHighlightImageSize; ++i) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(rgba[4 * i + c] - rgba[c]));
        mask[std::size_t(i)] = d > 3;
    }
    return mask;
}

// Distance (Chebyshev, capped at `cap`) of each pixel to the nearest pixel whose mask
// differs from its own.
std::vector<int> edge_distance(const std::vector<bool>& mask, int cap) {
    std::vector<int> dist(mask.size(), cap);
    for (int y = 0; y < kHighlightImageSize; ++y)
        for (int x = 0; x < kHighlightImageSize; ++x) {
            const bool self = mask[std::size_t(y * kHighlightImageSize + x)];
            for (int r = 1; r < cap; ++r) {
                bool found = false;
                for (int dy = -r; dy <= r && !found; ++dy)
                    for (int dx = -r; dx <= r && !found; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= kHighlightImageSize ||
                            ny >= kHighlightImageSize)
                            continue;
                        found = mask[std::size_t(ny * kHighlightImageSize + nx)] != self;
                    }
                if (found) {
                    dist[std::size_t(y * kHighlightImageSize + x)] = r;
                    break;
                }
            }
        }
    return dist;
}

struct Outline {
    std::size_t interior = 0, interior_changed = 0; // object pixels 4+ px inside
    std::size_t ring = 0, ring_orange = 0;          // background pixels 1-2 px outside
};

Outline classify_outline(const std::vector<std::uint8_t>& plain,
                         const std::vector<std::uint8_t>& lit) {
    const std::vector<bool> mask = object_mask(plain);
    const std::vector<int> dist = edge_distance(mask, 5);
    Outline o;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (mask[i] && dist[i] >= 4) {
            ++o.interior;
            for (std::size_t c = 0; c < 3; ++c)
                if (std::abs(int(plain[4 * i + c]) - int(lit[4 * i + c])) > 2) {
                    ++o.interior_changed;
                    break;
                }
        }
        if (!mask[i] && dist[i] <= 1) {
            ++o.ring;
            o.ring_orange += is_orange(&lit[4 * i]) ? 1 : 0;
        }
    }
    return o;
}

class HighlightTest : public GpuTest {
protected:
    render::FrameRequest settings() {
        render::FrameRequest s;
        s.width = s.height = kHighlightImageSize;
        std::string error;
        EXPECT_TRUE(render::parse_camera_spec("eye=1.5,1.2,2:target=0,0,0", s.camera, error))
            << error;
        return s;
    }
};

TEST_F(HighlightTest, SelectedInstanceIsOutlinedNotTinted) {
    auto scene = load(gltf_asset("BoxTextured"));
    ASSERT_TRUE(scene);
    ASSERT_EQ(scene->instances.size(), 1u);
    renderer().load(*scene);
    render::FrameRequest s = settings();
    const std::vector<std::uint8_t> plain_rgba = draw(s);
    const Counts plain = count_highlight(plain_rgba);

    s.highlight_instance = 0;
    const std::vector<std::uint8_t> lit_rgba = draw(s);
    const Outline o = classify_outline(plain_rgba, lit_rgba);
    // The box covers about a quarter of the 160² image.
    EXPECT_GT(o.interior, std::size_t(kHighlightImageSize * kHighlightImageSize / 8));
    EXPECT_EQ(o.interior_changed, 0u) << "the surface keeps its colours (no tint)";
    EXPECT_GT(o.ring_orange, o.ring * 3 / 4) << "an orange ring around the silhouette";
    EXPECT_EQ(count_highlight(lit_rgba).magenta, plain.magenta);

    s.highlight_triangle = 0;
    s.highlight_vertex = 0;
    const std::vector<std::uint8_t> detailed = draw(s);
    const Counts detail = count_highlight(detailed);
    EXPECT_GT(detail.magenta, plain.magenta + 100) << "filled triangle and vertex tripod";
    std::string error;
    EXPECT_TRUE(tex::write_png("highlight_box.png", kHighlightImageSize, kHighlightImageSize,
                               detailed, error))
        << error;

    // Out of range: no instance, so nothing is highlighted (and nothing breaks).
    s.highlight_instance = 7;
    const Counts none = count_highlight(draw(s));
    EXPECT_EQ(none.orange, plain.orange);
    EXPECT_EQ(none.magenta, plain.magenta);
    renderer().unload();
}

TEST_F(HighlightTest, DoubleSidedPlaneIsOutlinedToo) {
    // No back faces to draw: every edge, pushed behind the surface by depth bias.
    auto scene = load(gltf_asset("TwoSidedPlane"));
    ASSERT_TRUE(scene);
    ASSERT_FALSE(scene->instances.empty());
    renderer().load(*scene);
    render::FrameRequest s = settings();
    std::string error;
    ASSERT_TRUE(render::parse_camera_spec("eye=0.4,2.5,1.2:target=0,0,0", s.camera, error))
        << error;
    const std::vector<std::uint8_t> plain = draw(s);
    s.highlight_instance = 0;
    const std::vector<std::uint8_t> lit = draw(s);
    const Outline o = classify_outline(plain, lit);
    EXPECT_GT(o.interior, std::size_t(kHighlightImageSize * kHighlightImageSize / 10));
    EXPECT_EQ(o.interior_changed, 0u) << "the surface keeps its colours";
    EXPECT_GT(o.ring_orange, o.ring / 2) << "an orange ring around the plane";
    renderer().unload();
}

TEST_F(HighlightTest, SubtreeOutlineAlongsideOtherLineOverlays) {
    // The box overlay, the cull overlay and the outlines share the frame.
    auto scene = load("builtin:default");
    ASSERT_TRUE(scene);
    renderer().load(*scene);
    render::FrameRequest s = settings();
    s.camera = {};
    s.overlays = render::kOverlayBounds | render::kOverlayCullBoxes;
    const Counts plain = count_highlight(draw(s));
    s.highlight_instance = static_cast<std::uint32_t>(scene->instances.size() / 2);
    const Counts one = count_highlight(draw(s));
    EXPECT_GT(one.orange, plain.orange);
    // A node without a mesh: the editor outlines its subtree's instances.
    s.highlight_instance.reset();
    for (std::uint32_t i = 0; i < scene->instances.size(); ++i) s.highlight_outline.push_back(i);
    const Counts all = count_highlight(draw(s));
    EXPECT_GT(all.orange, one.orange);
    renderer().unload();
}

} // namespace
} // namespace sherpa::test
