#pragma once
// What the viewport draws (issue 17 item 8, issue 18 item 3): the rasterizer, the ray
// tracer, or an A/B comparison of two sides drawn with one camera (locked by
// construction: both sides get the same CameraSpec) and composited by the engine's
// ComparisonFrame, side by side with a divider (Split) or as a heat map of |A - B|
// (Difference). Plain data, mapped to the engine's settings in viewport_presenter*.cpp.
#include <cstdint>

namespace sherpa::editor {

enum class ViewportMode : std::uint8_t { Raster, RayTraced, Split, Difference };

// Side A of a comparison is the viewport's own raster frame (its view, its scene);
// side B differs from it in one thing.
enum class SideB : std::uint8_t {
    RayTraced, // the same view of the same scene through the ray tracer
    OtherView, // another debug view of the same scene, rasterized
    OtherFile, // the same view of another file, loaded only while comparing
};

struct ViewportComparison {
    ViewportMode mode = ViewportMode::Raster;
    SideB side = SideB::RayTraced;
    std::uint32_t view = 0; // SideB::OtherView: a render::DebugView (ViewCatalog id)
    float divider = 0.5f;   // Split: fraction of the width, A left of it
    // A pixel differs when a channel differs by more than this (sRGB 0..1); a
    // difference of heat_max and above is drawn at full heat; 0: automatic (the 99.9th
    // percentile of the differing pixels of the latest completed frame).
    float threshold = 2.0f / 255.0f;
    float heat_max = 16.0f / 255.0f;
    bool comparing() const {
        return mode == ViewportMode::Split || mode == ViewportMode::Difference;
    }
    // The frame goes through the ray tracer on some side (no overlays, no highlight).
    bool rays() const {
        return mode == ViewportMode::RayTraced || (comparing() && side == SideB::RayTraced);
    }
};

// The difference of the latest completed comparison frame (the engine's
// ComparisonStats), over every pixel: sRGB-encoded values in 0..1, the largest of R, G, B.
struct DifferenceNumbers {
    bool valid = false;
    std::uint64_t pixels = 0;
    double mean = 0.0, max = 0.0;
    double psnr_db = 0.0; // infinity when identical
    double over_threshold_percent = 0.0;
    double heat_max = 0.0; // the scale drawn: the chosen one, or the automatic one
};

} // namespace sherpa::editor
