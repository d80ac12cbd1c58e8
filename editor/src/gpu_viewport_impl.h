#pragma once
// GpuViewport's engine state (private to gpu_viewport*.cpp, which include the
// engine's headers before Qt's).
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/presenter.h>
#include <sherpa/render/cull_check.h>
#include <sherpa/render/renderer.h>

#include <QString>

#include "gpu_viewport.h"

namespace sherpa::editor {

struct GpuViewport::Impl {
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<gpu::Renderer> renderer;
    std::unique_ptr<gpu::Presenter> presenter;
    gpu::FrameStats completed; // of the latest frame known complete (status bar, pass table)
    std::uint64_t surface = 0;
    std::uint32_t width = 0, height = 0;
    SharedSession session; // on the GPU: its scene and prepared textures
    bool all_streams = false;
    gpu::MissingTextures missing = gpu::MissingTextures::Checker; // load()
    bool reduced_prepass = false;                                 // setReducedFramePrepass()
    std::unique_ptr<gpu::GpuCullChecker> culler; // CPU/GPU agreement checks, built per scene
    // The environment lighting side A (setEnvironment), kept to light side B alike.
    std::shared_ptr<const gpu::EnvironmentImage> environment;

    // Side B of a comparison (gpu_viewport_compare.cpp): a second renderer on the same
    // context, with what it was loaded with; made while comparing, freed after.
    struct SideB {
        std::unique_ptr<gpu::Renderer> renderer;
        SharedSession session;
        bool all_streams = false, ray_tracing = false;
    } b;
    DifferenceNumbers difference; // of the latest completed comparison frame
    QString refusal;              // why the last frame was not drawn (the ray tracer refused)
    // The path tracer's accumulation as of the last present(): samples per pixel, the
    // estimated relative error when last measured (-1: not yet) and at which count.
    bool path_traced = false; // the last present() drew the path tracer
    std::uint32_t path_samples = 0, path_error_samples = 0;
    double path_error = -1.0;
};

// Loads `session` into `renderer` (side A's upload and side B's): every stream with
// `all_streams`, else those its materials use; missing textures drawn as `missing`.
void load_session(gpu::Renderer& renderer, const SceneSession& session, bool all_streams,
                  gpu::MissingTextures missing);

// The request of side A as drawn at `scale`: without shadows (and the prepass unless
// `reduced_prepass`) when reduced, without overlays and highlight where rays draw or
// two sides are compared, through the path tracer in the ray-traced mode.
gpu::FrameRequest drawn_request(const ViewportRequest& frame, float scale, bool reduced_prepass);

} // namespace sherpa::editor
