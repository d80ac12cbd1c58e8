#pragma once
// The legends of render's views whose colours are classes (provenance, shadow-error):
// drawn into the image's bottom-left corner with the engine's colours and the built-in
// font, and printed, so that a picture passed on still says what its colours mean.
#include <sherpa/render/debug_views.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sherpa::cli {

struct LegendEntry {
    std::array<std::uint8_t, 3> colour; // the stored bytes of the class colour
    std::string name;
};

// Empty for views without classes.
std::vector<LegendEntry> view_legend(render::DebugView view);

// Draws view_legend(view) into the bottom-left corner of `rgba` (width x height, RGBA8
// rows) when the box takes at most half the width and a third of the height; returns
// whether it drew. "view NAME: colour name, ..." for stdout either way (empty: none).
bool draw_view_legend(std::vector<std::uint8_t>& rgba, std::uint32_t width, std::uint32_t height,
                      render::DebugView view);
std::string view_legend_line(render::DebugView view);

} // namespace sherpa::cli
