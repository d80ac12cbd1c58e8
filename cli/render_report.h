#pragma once
// The JSON report of `sherpa-cli render --report`: device, GPU memory per
// category, per-pass GPU time, pipeline statistics, textures (format and cache
// state per prepared texture, counts by state and format) and load timings.
#include <filesystem>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include <sherpa/render/renderer.h>

namespace sherpa::cli {

// Wall-clock times of loading, measured once per run (reported, never asserted).
struct LoadTiming {
    double scene_load_ms = 0;           // glTF import (tangents included)
    double texture_prepare_ms = 0;      // cache lookups, decode, mips, compression
    double gpu_upload_ms = 0;           // GpuScene: buffers, images, bindless
    double load_and_first_frame_ms = 0; // the three above plus the first frame
};

struct RenderRun {
    std::string scene;
    render::FrameRequest settings;
    std::string camera_text;
    std::vector<render::FrameStats> frames; // every rendered frame, in order
    std::vector<double> cpu_frame_ms;       // wall time of each frame (submit to completion)
    LoadTiming timing;
    std::optional<std::filesystem::path> cache_dir; // texture cache used; nullopt: none
};

nlohmann::json render_report_json(render::Renderer& renderer, const RenderRun& run);

} // namespace sherpa::cli
