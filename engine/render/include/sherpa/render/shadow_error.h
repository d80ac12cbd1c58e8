#pragma once
// Pixel counts of the shadow-error view (DebugView::ShadowError, drawn by the ray
// tracer): each covered pixel is in one of four classes, told apart by its colour,
// the kShadowError* constants of debug_views.h the shader's colours are generated from.
#include <cstdint>
#include <span>

namespace sherpa::render {

struct ShadowErrorCounts {
    std::uint64_t agree_lit = 0, agree_shadowed = 0;
    std::uint64_t false_shadow = 0; // the maps shadow a point the rays find lit
    std::uint64_t false_light = 0;  // the maps light a point the rays find shadowed
    std::uint64_t other = 0;        // background (no surface)

    // Pixels the reference (the rays) finds lit.
    std::uint64_t lit() const { return agree_lit + false_shadow; }
    std::uint64_t wrong() const { return false_shadow + false_light; }
    // The error the Lab charts: wrong pixels (either way) per 100 pixels the rays
    // find lit; 0 when no pixel is lit.
    double percent_of_lit_wrong() const {
        return lit() ? 100.0 * double(wrong()) / double(lit()) : 0.0;
    }
};

// `rgba`: the view's RGBA8 pixels as Renderer::render returns them (4 bytes each).
ShadowErrorCounts count_shadow_error(std::span<const std::uint8_t> rgba);

} // namespace sherpa::render
