#pragma once
// The JSON report of `sherpa-cli render --report`: device, GPU memory per
// category, per-pass GPU time, pipeline statistics.
#include <vector>

#include <nlohmann/json.hpp>

#include <sherpa/gpu/renderer.h>

namespace sherpa::cli {

struct RenderRun {
    std::string scene;
    gpu::RenderSettings settings;
    std::string camera_text;
    std::vector<gpu::FrameStats> frames; // every rendered frame, in order
    std::vector<double> cpu_frame_ms;    // wall time of each frame (submit to completion)
};

nlohmann::json render_report_json(gpu::Renderer& renderer, const RenderRun& run);

} // namespace sherpa::cli
