// The engine's headers come first (see gpu_viewport.cpp).
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/presenter.h>
#include <sherpa/render/presented_frame.h>
#include <sherpa/render/renderer.h>

#include "viewport_presenter.h"
#include "viewport_scene.h"

#include <optional>

namespace sherpa::editor {

ViewportPresenter::ViewportPresenter(gpu::Context& context, render::Renderer& renderer,
                                     const ViewportScene& scene)
    : context_(context), renderer_(renderer), scene_(scene) {}

ViewportPresenter::~ViewportPresenter() {
    presenter_.reset();
    b_ = {};
}

void ViewportPresenter::releaseSurface() {
    presenter_.reset();
    completed_ = {};
    surface_ = 0;
}

void apply_display(const ViewportDisplay& d, render::FrameRequest& settings) {
    settings.environment_rotation = d.environmentRotation;
    settings.environment_intensity = d.environmentIntensity;
    settings.background = d.background;
    if (d.background == render::Background::Color)
        settings.clear_color = glm::vec4(d.backgroundColor, 1.0f);
    settings.tone_map = d.toneMap;
    settings.exposure = d.exposure;
    settings.sun = d.sun;
    settings.energy_compensation = d.energyCompensation;
}

render::FrameRequest drawn_request(const ViewportRequest& frame, float scale,
                                   bool reduced_prepass) {
    render::FrameRequest settings = frame.request;
    // A reduced frame means a slow device while the camera moves: the shadow cascades
    // follow the camera and cost the same at any resolution (DamagedHelmet on lavapipe:
    // 165 of 245 ms), so moving frames go without them; the still frame has them.
    // So does the depth prepass, unless asked for (setReducedFramePrepass).
    if (scale < 1.0f) settings.shadows = false;
    if (scale < 1.0f && !reduced_prepass) settings.depth_prepass = render::PrepassMode::Off;
    // Rays draw the surface only: overlays and the selection are the rasterizer's,
    // and a comparison shows the two sides' surfaces, nothing drawn over one of them.
    if (frame.compare.rays() || frame.compare.comparing()) {
        settings.overlays = 0;
        settings.highlight_instance.reset();
        settings.highlight_triangle.reset();
        settings.highlight_vertex.reset();
        settings.highlight_outline.clear();
    }
    if (frame.compare.mode == ViewportMode::RayTraced) {
        settings.renderer = render::RendererKind::RayTraced;
        // The lit view is path traced: one sample per frame, accumulated while
        // nothing changes (the render thread keeps drawing until kPathSamples).
        settings.path.samples = 1;
        settings.path.max_samples = ViewportPresenter::kPathSamples;
    }
    return settings;
}

void ViewportPresenter::preparePresenter(std::uint64_t surface, const render::FrameRequest& frame) {
    if (!presenter_ || surface_ != surface) {
        presenter_.reset();
        // Not FIFO: the render thread must not block on the display's refresh, and
        // Mesa's X11 path then puts the image to the server within the present call,
        // so a screenshot taken after it sees this frame, not an earlier one.
        gpu::PresenterOptions options;
        options.vsync = false;
        presenter_ = std::make_unique<gpu::Presenter>(context_, renderer_.resources(),
                                                      reinterpret_cast<VkSurfaceKHR>(surface),
                                                      frame.width, frame.height, options);
        surface_ = surface;
        width_ = frame.width;
        height_ = frame.height;
    } else if (frame.width != width_ || frame.height != height_) {
        presenter_->resize(frame.width, frame.height);
        width_ = frame.width;
        height_ = frame.height;
    }
}

PresentOutcome ViewportPresenter::present(std::uint64_t surface, const ViewportRequest& frame,
                                          float scale) {
    return outcome(draw(surface, frame, scale));
}

PresentOutcome ViewportPresenter::outcome(bool shown) const {
    PresentOutcome out;
    out.shown = shown;
    out.refused = refusal_;
    out.difference = difference_;
    out.path_traced = path_traced_;
    out.path_samples = path_samples_;
    out.path_error = path_error_;
    // GPU time (timestamps, first to last pass) of the latest completed frame.
    if (presenter_ && !completed_.passes.empty()) out.gpu_ms = completed_.gpu_ms;
    const auto& h = renderer_.cull_history();
    if (h.size() > 0) {
        const render::CullFrame& f = h[h.size() - 1];
        out.cull_passes = true;
        out.passes = f.passes;
        out.cached_shadows = !f.shadows_rendered;
    }
    return out;
}

bool ViewportPresenter::draw(std::uint64_t surface, const ViewportRequest& frame, float scale) {
    refusal_.clear();
    if (!surface || frame.request.width == 0 || frame.request.height == 0) return false;
    const render::FrameRequest settings = drawn_request(frame, scale, reduced_prepass_);
    preparePresenter(surface, frame.request);
    renderer_.set_hidden_nodes(frame.hiddenNodes); // unchanged: one comparison
    if (frame.compare.comparing()) return presentComparison(frame, settings, scale);
    b_ = {}; // side B lives only while comparing
    difference_ = {};
    std::optional<render::PresentedFrame> presented;
    try {
        presented.emplace(renderer_, settings, scale);
    } catch (const gpu::GpuError& e) { // refused before anything was recorded
        if (settings.renderer != render::RendererKind::RayTraced) throw;
        refusal_ = QString::fromUtf8(e.what());
        return false;
    }
    const bool shown = presenter_->present_frame(*presented);
    completed_ = presented->completed_stats(); // garbage: the presenter collects it
    notePathSamples(settings);
    return shown;
}

// The accumulation after this frame (the renderer counts it when it records), and its
// error read back at each power of two from 4 samples (the sums are read back: a cost
// that halves in frequency as the image converges).
void ViewportPresenter::notePathSamples(const render::FrameRequest& settings) {
    if (settings.renderer != render::RendererKind::RayTraced ||
        settings.view != render::DebugView::Lit) {
        path_traced_ = false;
        path_samples_ = path_error_samples_ = 0;
        path_error_ = -1.0;
        return;
    }
    path_traced_ = true;
    // The completed frame's count (kFramesInFlight behind): no readback for it.
    const std::uint32_t n = completed_.path.samples;
    if (n < path_samples_) path_error_ = -1.0; // started over
    path_samples_ = n;
    if (n >= 4 && (n & (n - 1)) == 0 && n != path_error_samples_) {
        path_error_ = render::path_trace_error(renderer_).relative_error;
        path_error_samples_ = n;
    }
}

} // namespace sherpa::editor
