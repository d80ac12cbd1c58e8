// The camera's surface passes, inside the frame's dynamic-rendering pass: the
// benchmark floor, the depth prepass and forward shading per alpha mode.
#include "draw.h"
#include "passes.h"

namespace sherpa::render {

void FloorPass::record(FrameContext& f) {
    if (!f.settings.floor_only) return;
    // Same triangles, one constant colour: what the rasterizer costs by itself.
    set_depth(f.cmd, VK_COMPARE_OP_GREATER, true);
    const DrawPipeline floor{PipelineId::Floor};
    for (scene::AlphaMode a :
         {scene::AlphaMode::Opaque, scene::AlphaMode::Mask, scene::AlphaMode::Blend})
        draw_groups(f, floor, a, camera_view(f), f.slot.culling.camera_stats());
}

void DepthPrepass::record(FrameContext& f) {
    if (f.settings.floor_only || !f.prepass) return;
    set_depth(f.cmd, VK_COMPARE_OP_GREATER, true);
    draw_groups(f, DrawPipeline{PipelineId::PrepassOpaque}, scene::AlphaMode::Opaque,
                camera_view(f), f.slot.prepass);
    draw_groups(f, DrawPipeline{PipelineId::PrepassMask}, scene::AlphaMode::Mask, camera_view(f),
                f.slot.prepass);
}

void ForwardPass::record(FrameContext& f) {
    if (f.settings.floor_only) return;
    const auto view = static_cast<std::uint32_t>(f.settings.view);
    scene::CullStats& tally = f.slot.culling.camera_stats();
    if (alpha_ == scene::AlphaMode::Blend) {
        // One rule for blended surfaces in both renderers (docs/raytracing/README.md): the
        // lit view blends them over what is behind, back to front; every data view shows
        // the nearest surface as the ray tracer's primary rays do, so blended surfaces
        // write depth there and each pixel keeps the nearest one's values.
        set_depth(f.cmd, VK_COMPARE_OP_GREATER, f.settings.view != DebugView::Lit);
        draw_blended(f, DrawPipeline{PipelineId::Count, view, true}, tally);
        return;
    }
    // After the prepass only the visible surface passes: shade each pixel once.
    set_depth(f.cmd, f.prepass ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_GREATER,
              !f.prepass);
    draw_groups(f, DrawPipeline{PipelineId::Count, view, false}, alpha_, camera_view(f), tally);
}

} // namespace sherpa::render
