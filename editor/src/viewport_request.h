#pragma once
// What the window asks the viewport to draw (ViewportRequest) and what one present
// did (PresentOutcome): plain data between the window's controllers, the render thread
// and the engine behind the viewport (GpuViewport).
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

#include <sherpa/render/environment.h>
#include <sherpa/render/frame_request.h>
#include <sherpa/scene/culling_passes.h>

#include "scene_session.h"
#include "viewport_mode.h"

namespace sherpa::editor {

// How the lit view is lit and shown (the Environment menu, View > Tone mapping, the
// command line); the environment itself is the viewport's (ViewportScene::setEnvironment).
struct ViewportDisplay {
    float environmentRotation = 0.0f; // degrees about +Y
    float environmentIntensity = 1.0f;
    render::Background background = render::Background::Environment;
    glm::vec3 backgroundColor{0.18f, 0.19f, 0.21f}; // linear; Background::Color
    render::ToneMap toneMap = render::ToneMap::Neutral;
    float exposure = 0.0f; // stops
    bool sun = true;       // the default sun (scenes without lights)
    bool energyCompensation = true;
};

// The display's fields of `settings` (render::copy_lighting's): what every view of the
// window lit alike reads (the viewport, a comparison's side B, the Lab).
void apply_display(const ViewportDisplay& display, render::FrameRequest& settings);

// What the window wants drawn: the engine's FrameRequest as the window's controllers
// fill it (full size; ViewportPresenter::present() drops shadows from reduced frames,
// and overlays and highlight where rays draw), and what the viewport draws around it.
struct ViewportRequest {
    render::FrameRequest request;
    // Nodes unchecked in the scene tree (NodeVisibility::hidden()), given to the
    // renderer; null: all shown.
    std::shared_ptr<const std::vector<bool>> hiddenNodes;
    ViewportComparison compare;   // raster, ray traced, split or difference
    SharedSession compareSession; // SideB::OtherFile: the other file
};

// What one present() did, and what the renderer measured by then.
struct PresentOutcome {
    bool shown = false;       // false: skipped (swapchain recreated) or refused
    double gpu_ms = -1.0;     // timestamps of the latest completed frame
    bool cull_passes = false; // the renderer's culling passes are known
    // The last presented frame's culling passes from the renderer's history (camera,
    // then each cascade); `cached_shadows`: the cascades were reused, not drawn.
    std::vector<scene::CullStats> passes;
    bool cached_shadows = false;
    // Not drawn: what the ray tracer refused (a view without a ray formula, a posed
    // frame...); empty when it drew.
    QString refused;
    DifferenceNumbers difference; // comparison frames: the latest completed difference
    // Path traced (ray-traced mode, lit view): samples per pixel accumulated as of the
    // latest completed frame (kFramesInFlight behind) and the estimated relative error,
    // measured at 4, 8, 16, ... samples (-1 before the first measurement).
    bool path_traced = false;
    std::uint32_t path_samples = 0;
    double path_error = -1.0;
};

} // namespace sherpa::editor
