#include "view_legend.h"

#include <sherpa/render/frame_request.h>
#include <sherpa/texture/image_text.h>

#include <algorithm>
#include <cmath>

namespace sherpa::cli {
namespace {

const char* colour_word(const std::array<std::uint8_t, 3>& c) {
    if (c[0] > 200 && c[1] > 150 && c[2] < 100) return "yellow";
    if (c[0] > 150 && c[1] < 100 && c[2] < 100) return "red";
    if (c[1] > 150 && c[0] < 100) return "green";
    if (c[2] > 150 && c[0] < 100) return "blue";
    return c[0] > 128 ? "light grey" : "dark grey";
}

} // namespace

std::vector<LegendEntry> view_legend(render::DebugView view) {
    std::vector<LegendEntry> out;
    if (view == render::DebugView::Provenance) {
        for (std::size_t i = 0; i < render::kProvenanceColors.size(); ++i)
            out.push_back({render::stored_bytes(render::kProvenanceColors[i]),
                           std::string("tangents ") + render::kProvenanceNames[i]});
    } else if (view == render::DebugView::ShadowError) {
        out.push_back({render::stored_bytes(render::kShadowAgreeLitColor), "both lit"});
        out.push_back({render::stored_bytes(render::kShadowAgreeShadowedColor), "both shadowed"});
        out.push_back(
            {render::stored_bytes(render::kShadowFalseShadowColor), "false shadow (maps)"});
        out.push_back({render::stored_bytes(render::kShadowFalseLightColor), "false light (maps)"});
    }
    return out;
}

bool draw_view_legend(std::vector<std::uint8_t>& rgba, std::uint32_t width, std::uint32_t height,
                      render::DebugView view) {
    const std::vector<LegendEntry> entries = view_legend(view);
    if (entries.empty() || rgba.size() < std::size_t(width) * height * 4) return false;
    constexpr std::uint32_t kRow = tex::kGlyphHeight + 5, kSwatch = tex::kGlyphHeight + 1;
    std::uint32_t text = 0;
    for (const LegendEntry& e : entries) text = std::max(text, tex::text_width(e.name));
    const std::uint32_t box_w = 4 + kSwatch + 4 + text + 4;
    const std::uint32_t box_h = 2 + std::uint32_t(entries.size()) * kRow + 1;
    if (2 * box_w > width || 3 * box_h > height) return false;
    tex::RgbaImage image;
    image.width = width, image.height = height;
    image.pixels = std::move(rgba);
    const int top = int(height - box_h);
    tex::fill_rect(image, 0, top, int(box_w), int(box_h), {24, 24, 24});
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const int y = top + 3 + int(i * kRow);
        tex::fill_rect(image, 4, y, int(kSwatch), int(kSwatch), entries[i].colour);
        tex::draw_text(image, int(4 + kSwatch + 4), y + 1, entries[i].name, {255, 255, 255});
    }
    rgba = std::move(image.pixels);
    return true;
}

std::string view_legend_line(render::DebugView view) {
    std::string line;
    for (const LegendEntry& e : view_legend(view))
        line += std::string(line.empty() ? "" : ", ") + colour_word(e.colour) + " " + e.name;
    return line.empty() ? line : "view " + std::string(to_string(view)) + ": " + line;
}

} // namespace sherpa::cli
