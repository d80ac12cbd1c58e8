// The environment behind the scene (FrameRequest::background environment or
// blurred): one full-screen triangle at the far plane, depth-tested EQUAL against the
// cleared far depth, so only pixels no surface covers are shaded. Nothing is drawn
// (and nothing built) for a solid-colour background or without an environment.
#include "draw.h"
#include "passes.h"

#include <sherpa/gpu/vk_helpers.h>

#include "background_frag.h"
#include "background_vert.h"

namespace sherpa::gpu {

BackgroundPass::BackgroundPass() = default;
BackgroundPass::~BackgroundPass() = default;

bool BackgroundPass::active(const FrameContext& f) {
    return f.environment && !f.settings.floor_only && f.settings.view == DebugView::Lit &&
           f.settings.background != Background::Color;
}

void BackgroundPass::record(FrameContext& f) {
    if (!active(f)) return;
    VkDevice device = f.context.device();
    if (!vert_) {
        vert_ = create_shader_module(device, spirv_background_vert, "background.vert");
        frag_ = create_shader_module(device, spirv_background_frag, "background.frag");
    }
    UniquePipeline& p = pipelines_[f.pipelines.color_format()];
    if (!p) {
        PipelineDesc d{vert_.get(), frag_.get()};
        p = make_graphics_pipeline(device, f.pipelines.layout(), f.pipelines.color_format(), d,
                                   "vkCreateGraphicsPipelines(background)");
    }
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.get());
    vkCmdSetCullMode(f.cmd, VK_CULL_MODE_NONE);
    vkCmdSetFrontFace(f.cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
    set_depth(f.cmd, VK_COMPARE_OP_EQUAL, false); // reverse-Z: 0 is the cleared far plane
    vkCmdDraw(f.cmd, 3, 1, 0, 0);
}

} // namespace sherpa::gpu
