// The viewport's A/B comparison (issue 18 item 3): side A is the viewport's own
// raster frame, side B the same camera with one thing changed (the ray tracer,
// another debug view, another file), drawn by a second Renderer on the same
// context that exists only while comparing (ViewportPresenter::present frees it after).
// The engine's ComparisonFrame draws both and composites them into the swapchain.
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/presenter.h>
#include <sherpa/render/comparison.h>
#include <sherpa/render/presented_frame.h>
#include <sherpa/render/renderer.h>

#include "viewport_presenter.h"
#include "viewport_scene.h"

#include <cmath>

namespace sherpa::editor {

namespace {

render::FrameRequest side_b_settings(const ViewportRequest& frame, const render::FrameRequest& a) {
    render::FrameRequest b = a;
    switch (frame.compare.side) {
    case SideB::RayTraced:
        b.renderer = render::RendererKind::RayTraced;
        break;
    case SideB::OtherView:
        b.view = static_cast<render::DebugView>(frame.compare.view);
        break;
    case SideB::OtherFile:
        // The pose, joint and hidden nodes are the first scene's nodes: the other file
        // as loaded (its hidden nodes: presentComparison()).
        b.pose = nullptr;
        b.selected_joint.reset();
        b.freeze_cull.reset();
        break;
    }
    return b;
}

DifferenceNumbers numbers(const render::ComparisonStats& s, float heat_max) {
    DifferenceNumbers out;
    out.valid = s.valid;
    out.pixels = s.pixels;
    out.mean = s.mean;
    out.max = s.max;
    out.psnr_db = s.psnr_db;
    out.over_threshold_percent = s.over_threshold_percent;
    out.heat_max = heat_max > 0.0f ? double(heat_max) : s.percentile_999();
    return out;
}

} // namespace

bool ViewportPresenter::presentComparison(const ViewportRequest& frame,
                                          const render::FrameRequest& a_in, float scale) {
    const ViewportComparison& c = frame.compare;
    render::FrameRequest a = a_in;
    // Rays have no derivatives: against the ray tracer both sides sample mip 0, so the
    // difference shows the data paths, not two LOD choices (the engine's exactness check).
    if (c.side == SideB::RayTraced) a.texture_lod = 0.0f;
    const render::FrameRequest b = side_b_settings(frame, a);
    const SharedSession session =
        c.side == SideB::OtherFile ? frame.compareSession : scene_.session();
    if (!session) {
        refusal_ = QStringLiteral("side B has no scene (choose the other file first)");
        return false;
    }
    // Side B's renderer, loaded as this frame needs it (another scene, more streams,
    // acceleration structures for rays); reloaded only when one of those changes.
    const bool all = scene_.allStreams() || render::needs_all_streams(b);
    const bool rays = b.renderer == render::RendererKind::RayTraced;
    if (!b_.renderer || b_.session != session || b_.all_streams != all || b_.ray_tracing != rays) {
        b_ = {};
        render::RendererOptions options;
        options.ray_tracing = rays && context_.info().ray_tracing_enabled;
        b_.renderer = std::make_unique<render::Renderer>(context_, options);
        // Lit as side A is: the same environment (frame_request() gives both sides the
        // same display settings).
        b_.environment = scene_.environment();
        b_.renderer->set_environment(b_.environment.get());
        load_session(*b_.renderer, *session, all, scene_.missingTextures());
        b_.session = session;
        b_.all_streams = all;
        b_.ray_tracing = rays;
    }
    // Side A's environment changed while comparing: side B's is made again from it.
    if (b_.environment != scene_.environment()) {
        b_.environment = scene_.environment();
        b_.renderer->set_environment(b_.environment.get());
    }
    b_.renderer->set_hidden_nodes(c.side == SideB::OtherFile ? nullptr : frame.hiddenNodes);
    render::ComparisonSettings compare;
    compare.mode = c.mode == ViewportMode::Split ? render::CompareMode::Split
                                                 : render::CompareMode::Difference;
    compare.divider = c.divider;
    compare.threshold = c.threshold;
    compare.heat_max = c.heat_max;
    std::optional<render::ComparisonFrame> pair;
    try {
        pair.emplace(renderer_, a, *b_.renderer, b, compare, scale);
    } catch (const gpu::GpuError& e) { // refused before anything was recorded
        refusal_ = QString::fromUtf8(e.what());
        return false;
    }
    const bool shown = presenter_->present_frame(*pair);
    completed_ = pair->completed_stats_a();
    difference_ = numbers(pair->completed_comparison(), compare.heat_max);
    return shown;
}

} // namespace sherpa::editor
