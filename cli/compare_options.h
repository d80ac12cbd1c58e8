#pragma once
// `sherpa-cli render SCENE -o OUT.png --compare split|difference ...`: the render
// command's frame (side A) against side B, which is the same frame with the
// --compare-* overrides (another file, renderer, view, texture LOD or texture
// compression), drawn by a second renderer on the same device and composited on
// the GPU (render::render_comparison): the PNG is the split or difference image, the
// statistics go to stdout (JSON with --json).
#include "cli_common.h"
#include "texture_cli.h" // OptionMatch, TextureCliOptions

#include <optional>
#include <string>

#include <sherpa/render/comparison.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/render/scene_setup.h>

namespace sherpa::cli {

inline constexpr const char* kCompareOptionsSynopsis =
    "[--compare split|difference [--compare-with FILE] [--compare-renderer raster|rt]\n"
    "     [--compare-view NAME] [--compare-texture-lod N|auto] [--compare-no-bc] "
    "[--compare-quality N]\n"
    "     [--divider F] [--threshold T] [--heat-max D|auto] [--json]]";
inline constexpr const char* kCompareOptionsHelp =
    "  --compare split|difference\n"
    "                     draw side A (this command's frame) against side B (the same\n"
    "                     frame with the --compare-* changes below): split shows A left\n"
    "                     of a divider line and B right of it; difference a heat map of\n"
    "                     the largest R, G, B difference (black, blue, red, yellow, white)\n"
    "  --compare-with FILE  side B renders FILE (same camera: 'auto' frames SCENE)\n"
    "  --compare-renderer raster|rt, --compare-view NAME, --compare-texture-lod N|auto\n"
    "                     side B's renderer, debug view, texture mip level\n"
    "  --compare-no-bc, --compare-quality N\n"
    "                     side B's textures uncompressed (RGBA8), or at BC7 level N\n"
    "  --divider F        split: the divider at fraction F of the width (default 0.5)\n"
    "  --threshold T      a pixel differs when a channel differs by more than T 8-bit\n"
    "                     steps (default 2)\n"
    "  --heat-max D|auto  difference: D steps (and more) are white (default 16); auto:\n"
    "                     the 99.9th percentile of the pixels that differ\n"
    "  --json             the statistics as JSON on stdout\n";

struct CompareCliOptions {
    std::optional<render::CompareMode> mode; // --compare: unset, no comparison
    std::string with;                        // another file for side B; empty: SCENE
    std::optional<render::RendererKind> renderer;
    std::optional<render::DebugView> view;
    std::optional<float> texture_lod;
    bool no_bc = false;
    std::optional<int> quality;
    render::ComparisonSettings compare;
    bool json = false;
    bool side_b_changed() const {
        return !with.empty() || renderer || view || texture_lod || no_bc || quality;
    }
};

// If args[i] is a comparison option, consumes it and its value (advancing i).
OptionMatch parse_compare_option(Args args, std::size_t& i, CompareCliOptions& out,
                                 std::string& error);

// Everything the comparison needs from the render command.
struct CompareRun {
    const scene::Scene* scene = nullptr; // side A's, loaded
    std::string scene_name;
    render::FrameRequest settings; // side A's
    render::SceneSetup setup;      // side A's (streams: each side's own)
    TextureCliOptions textures;
    bool validation = false, ray_tracing = true;
    std::string output;                    // the PNG
    std::uint32_t frames = 1;              // --frames: comparisons drawn (pass times: their median)
    render::EnvironmentChoice environment; // both sides' (the lit view's), as render's own
};

// Renders, writes the PNG and prints the statistics; returns the exit code.
int run_comparison(const CompareRun& run, const CompareCliOptions& options);

} // namespace sherpa::cli
