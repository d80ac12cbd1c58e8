#pragma once
// The viewport's presentation: the engine's Presenter (swapchain) on the surface Qt
// made for the viewport window, each frame drawn as the window asked (raster, ray
// traced or path traced, or two sides compared), and what the renderer measured by
// then. Side B of a comparison is a second renderer on the same context, loaded and
// lit as the viewport's scene is (ViewportScene), made while comparing, freed after.
#include <QString>

#include <cstddef>
#include <cstdint>
#include <memory>

#include <sherpa/render/renderer.h>

#include "viewport_request.h"

namespace sherpa::gpu {
class Context;
class Presenter;
} // namespace sherpa::gpu

namespace sherpa::editor {

class ViewportScene;

class ViewportPresenter {
public:
    // Draws with `renderer` (side A) on `context`; `scene` is what it holds.
    ViewportPresenter(gpu::Context& context, render::Renderer& renderer,
                      const ViewportScene& scene);
    ~ViewportPresenter();
    ViewportPresenter(const ViewportPresenter&) = delete;
    ViewportPresenter& operator=(const ViewportPresenter&) = delete;

    // Presents one frame on `surface` (the swapchain is created on first use and
    // recreated when the size changes), each side drawn at `scale` of the frame's
    // size and scaled up, without shadows (interaction on slow devices).
    PresentOutcome present(std::uint64_t surface, const ViewportRequest& frame, float scale = 1.0f);
    // Drops the swapchain (before the window's surface goes away).
    void releaseSurface();
    // Whether frames drawn reduced (scale < 1, moving on a slow device) keep the
    // depth prepass the renderer would choose. Off by default: at a third of each
    // side DamagedHelmet's prepass saves about as much shading as it costs on
    // lavapipe (sherpa-bench-orbit: 1.00-1.22x the frame rate without it, four runs).
    void setReducedFramePrepass(bool prepass) { reduced_prepass_ = prepass; }
    // What the GPU measured of the latest completed frame (timestamps pass by pass);
    // empty before one and after releaseSurface().
    const render::FrameStats& completed() const { return completed_; }

    // Accumulation of the path-traced lit view (ray-traced mode) stops at this many
    // samples per pixel; every change starts it over.
    static constexpr std::uint32_t kPathSamples = 1024;
    static constexpr std::size_t kFramesInFlight = 2; // render::Renderer::kFramesInFlight

private:
    // present()'s frame; false when it was skipped or refused.
    bool draw(std::uint64_t surface, const ViewportRequest& frame, float scale);
    // What the renderer measured as of the frame just presented.
    PresentOutcome outcome(bool shown) const;
    void notePathSamples(const render::FrameRequest& settings);
    void preparePresenter(std::uint64_t surface, const render::FrameRequest& frame);
    // viewport_presenter_compare.cpp: side B loaded as `frame` asks, both drawn and
    // composited.
    bool presentComparison(const ViewportRequest& frame, const render::FrameRequest& a,
                           float scale);

    gpu::Context& context_;
    render::Renderer& renderer_;
    const ViewportScene& scene_;
    std::unique_ptr<gpu::Presenter> presenter_;
    render::FrameStats completed_; // of the latest frame known complete (status bar, pass table)
    std::uint64_t surface_ = 0;
    std::uint32_t width_ = 0, height_ = 0;
    bool reduced_prepass_ = false; // setReducedFramePrepass()
    // Side B of a comparison: a second renderer on the same context, with what it was
    // loaded and lit with; made while comparing, freed after.
    struct ComparisonSide {
        std::unique_ptr<render::Renderer> renderer;
        SharedSession session;
        bool all_streams = false, ray_tracing = false;
        std::shared_ptr<const render::EnvironmentImage> environment;
    } b_;
    DifferenceNumbers difference_; // of the latest completed comparison frame
    QString refusal_;              // why the last frame was not drawn (the ray tracer refused)
    // The path tracer's accumulation as of the last present(): samples per pixel, the
    // estimated relative error when last measured (-1: not yet) and at which count.
    bool path_traced_ = false; // the last present() drew the path tracer
    std::uint32_t path_samples_ = 0, path_error_samples_ = 0;
    double path_error_ = -1.0;
};

// The request of side A as drawn at `scale`: without shadows (and the prepass unless
// `reduced_prepass`) when reduced, without overlays and highlight where rays draw or
// two sides are compared, through the path tracer in the ray-traced mode.
render::FrameRequest drawn_request(const ViewportRequest& frame, float scale, bool reduced_prepass);

} // namespace sherpa::editor
