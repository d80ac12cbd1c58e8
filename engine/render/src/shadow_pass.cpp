// Shadow cascades (3, 2048², depth only) of the main directional light, one layer
// of the map each, fitted by the scene layer (sherpa/scene/shadow_cascades.h).
#include "draw.h"
#include "passes.h"

#include <cstring>

namespace sherpa::render {

ShadowPass::ShadowPass(gpu::Context& context, gpu::ResourceManager& resources,
                       std::uint32_t resolution)
    : context_(context), resources_(resources), resolution_(resolution) {
    gpu::ImageDesc d;
    d.format = kDepthFormat;
    d.width = d.height = resolution_;
    d.layers = kMaxCascades;
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
              VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    d.view_type = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    d.layer_views = true;
    d.name = "shadow cascades";
    map_ = resources_.images().create(d);

    auto si = gpu::vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    si.magFilter = si.minFilter = VK_FILTER_LINEAR; // 2x2 percentage-closer filtering per tap
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    si.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE; // outside every cascade: lit
    si.compareEnable = VK_TRUE;
    si.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    sampler_ = resources_.images().create_sampler(si);
    const gpu::Image& img = resources_.images().get(map_);

    // The descriptor names a read-only layout from the start, so the map is cleared
    // (fully lit) and put in that layout before any frame can sample it.
    gpu::CommandRecorder rec(context_);
    VkCommandBuffer cmd = rec.begin();
    gpu::transition(cmd, {img.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                          VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkClearDepthStencilValue one{1.0f, 0};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, kMaxCascades};
    vkCmdClearDepthStencilImage(cmd, img.image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &one, 1,
                                &range);
    gpu::transition(
        cmd, {img.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
              VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
              VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
              VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    resources_.timeline().wait_for(rec.submit(resources_));
}

ShadowPass::~ShadowPass() {
    resources_.images().destroy(map_);
    resources_.images().destroy(sampler_);
}

bool ShadowPass::needs_render(const scene::ShadowCascades& c, std::uint64_t scene_generation,
                              bool cache) {
    // The cascades depend only on these inputs: unchanged means the map is reusable.
    const std::uint32_t count = c.count;
    std::vector<std::uint8_t> key(sizeof(c.view_proj) + sizeof(scene_generation) + sizeof(count));
    std::memcpy(key.data(), c.view_proj.data(), sizeof(c.view_proj));
    std::memcpy(key.data() + sizeof(c.view_proj), &scene_generation, sizeof(scene_generation));
    std::memcpy(key.data() + sizeof(c.view_proj) + sizeof(scene_generation), &count, sizeof(count));
    const bool render = count > 0 && (!cache || !valid_ || key != key_);
    if (render) key_ = std::move(key);
    return render;
}

VkDescriptorImageInfo ShadowPass::descriptor() const {
    return {resources_.images().get(sampler_), resources_.images().get(map_).view.get(),
            VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
}

std::uint64_t ShadowPass::bytes() const {
    return resources_.images().get(map_).allocation_size;
}

void ShadowPass::record(FrameContext& f) {
    if (f.cascades == 0) return; // no shadows, or the cached map is still valid
    VkCommandBuffer cmd = f.cmd;
    const gpu::Image& map = resources_.images().get(map_);
    const std::uint32_t res = resolution_;
    gpu::transition(
        cmd,
        {map.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT,
         VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
         VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});
    for (std::uint32_t c = 0; c < f.cascades; ++c) {
        auto depth =
            gpu::vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
        depth.imageView = map.layer_views[c].get();
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {1.0f, 0};
        auto ri = gpu::vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
        ri.renderArea = {{0, 0}, {res, res}};
        ri.layerCount = 1;
        ri.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &ri);
        set_viewport(cmd, res, res);
        // Standard Z for the light; slope-scaled bias against acne on grazing faces.
        set_depth(cmd, VK_COMPARE_OP_LESS, true, 1.0f, 1.5f);
        scene::CullStats& tally = f.slot.culling.cascade_stats(c);
        // Casters cull as the camera does: a single-sided surface that the camera
        // cannot see from its back blocks no light arriving at its back either (else
        // TextureSettingsTest's hidden wrong-way polygon shadows the test behind it);
        // double-sided surfaces cast from both sides. The light's viewport is flipped
        // like the camera's, so front faces wind the same way.
        const DrawView view = cascade_view(f, c);
        draw_groups(f, DrawPipeline{PipelineId::ShadowOpaque}, scene::AlphaMode::Opaque, view,
                    tally);
        draw_groups(f, DrawPipeline{PipelineId::ShadowMask}, scene::AlphaMode::Mask, view, tally);
        vkCmdEndRendering(cmd);
    }
    gpu::transition(
        cmd, {map.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
              VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
              VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    valid_ = true;
}

} // namespace sherpa::render
