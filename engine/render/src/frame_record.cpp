// Recording of one frame: shadow cascades, then in one dynamic-rendering pass the
// depth prepass, opaque, alpha-mask, sorted alpha-blend and the overlays, with a
// timestamp after each and pipeline statistics around the camera passes.
#include "frame_slot.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/gpu_structs.h>

#include <algorithm>

namespace sherpa::gpu {

namespace {

void set_viewport(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) {
    // Negative height flips Y so clip-space +Y is up (see camera.h).
    VkViewport vp{0.0f, float(height), float(width), -float(height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {width, height}};
    vkCmdSetViewport(cmd, 0, 1, &vp);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void set_depth(VkCommandBuffer cmd, VkCompareOp op, bool write, float bias_constant = 0.0f,
               float bias_slope = 0.0f) {
    vkCmdSetDepthCompareOp(cmd, op);
    vkCmdSetDepthWriteEnable(cmd, write ? VK_TRUE : VK_FALSE);
    const bool bias = bias_constant != 0.0f || bias_slope != 0.0f;
    vkCmdSetDepthBiasEnable(cmd, bias ? VK_TRUE : VK_FALSE);
    if (bias) vkCmdSetDepthBias(cmd, bias_constant, 0.0f, bias_slope);
}

void push(VkCommandBuffer cmd, VkPipelineLayout layout, const GPUPushConstants& pc) {
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(pc), &pc);
}

void set_mesh(GPUPushConstants& pc, const GpuMesh& mesh, std::uint32_t material) {
    pc.positions = mesh.stream[std::size_t(VertexAttribute::Position)];
    pc.normals = mesh.stream[std::size_t(VertexAttribute::Normal)];
    pc.tangents = mesh.stream[std::size_t(VertexAttribute::Tangent)];
    pc.uv0 = mesh.stream[std::size_t(VertexAttribute::TexCoord0)];
    pc.uv1 = mesh.stream[std::size_t(VertexAttribute::TexCoord1)];
    pc.colors = mesh.stream[std::size_t(VertexAttribute::Color0)];
    pc.material_id = material;
    pc.mesh_flags = mesh.flags;
}

} // namespace

void Renderer::record_frame(VkCommandBuffer cmd, std::uint32_t index, const RenderTarget& target,
                            const RenderSettings& settings) {
    FrameSlot& slot = *slots_.at(index);
    wait_slot(slot);
    // Frames nobody read the results of (the swapchain path) still reach the
    // culling history, before this slot's queries are reset.
    if (slot.has_results && !slot.history_pushed) {
        FrameStats unused;
        read_cull_stats(slot, unused);
    }
    vkResetQueryPool(context_.device(), slot.timestamps.get(), 0, kTimestampCount);
    if (slot.statistics) vkResetQueryPool(context_.device(), slot.statistics.get(), 0, 1);
    slot.has_results = false;
    slot.draw_calls = 0;
    record_passes(cmd, slot, target, settings);
}

void Renderer::draw_groups(VkCommandBuffer cmd, FrameSlot& slot, Pipelines& p,
                           DrawPipeline pipeline, AlphaMode alpha, std::uint32_t cascade, bool cull,
                           CullStats& tally) {
    if (!scene_) return;
    VkPipeline bound = VK_NULL_HANDLE;
    GPUPushConstants pc = slot.push_base;
    pc.cascade = cascade;
    const std::uint32_t pass = cascade == kNoCascade ? 0 : 1 + cascade;
    const bool culled = slot.cull != CullPath::None && pass < slot.pass_count;
    for (std::size_t gi = 0; gi < scene_->groups().size(); ++gi) {
        const DrawGroup& g = scene_->groups()[gi];
        if (g.alpha != alpha) continue;
        const GpuMesh& mesh = scene_->meshes()[g.mesh];
        // Groups are sorted by mesh: consecutive groups mostly share a pipeline.
        if (const VkPipeline want = p.resolve(pipeline, mesh.flags); want != bound) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, want);
            bound = want;
        }
        vkCmdSetCullMode(cmd, cull && !g.double_sided ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE);
        vkCmdSetFrontFace(cmd,
                          g.mirrored ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
        set_mesh(pc, mesh, g.material);
        if (culled) {
            if (draw_culled(cmd, slot, p.layout(), gi, pass, pc, tally)) ++slot.draw_calls;
            continue;
        }
        push(cmd, p.layout(), pc);
        vkCmdDrawIndexed(cmd, mesh.index_count, g.instance_count, mesh.first_index, 0,
                         g.first_instance);
        ++slot.draw_calls;
        ++tally.draw_calls;
        tally.triangles += std::uint64_t{g.instance_count} * (mesh.index_count / 3);
    }
}

void Renderer::draw_blended(VkCommandBuffer cmd, FrameSlot& slot, Pipelines& p,
                            DrawPipeline pipeline, CullStats& tally) {
    if (!scene_) return;
    // Back to front by the view depth of each instance's bounds centre.
    struct Item {
        float depth;
        std::uint32_t group, instance;
    };
    std::vector<Item> items;
    const auto& groups = scene_->groups();
    for (std::uint32_t gi = 0; gi < groups.size(); ++gi) {
        if (groups[gi].alpha != AlphaMode::Blend) continue;
        for (std::uint32_t k = 0; k < groups[gi].instance_count; ++k) {
            const std::uint32_t inst = groups[gi].first_instance + k;
            const glm::vec3 c = scene_->instance_bounds()[inst].center();
            items.push_back({(slot.camera.view * glm::vec4(c, 1.0f)).z, gi, inst});
        }
    }
    if (items.empty()) return;
    std::stable_sort(items.begin(), items.end(),
                     [](const Item& a, const Item& b) { return a.depth < b.depth; });
    VkPipeline bound = VK_NULL_HANDLE;
    GPUPushConstants pc = slot.push_base;
    pc.cascade = kNoCascade;
    for (const Item& it : items) {
        if (slot.cull != CullPath::None && !slot.passes[0].visible[it.instance]) continue;
        const DrawGroup& g = groups[it.group];
        const GpuMesh& mesh = scene_->meshes()[g.mesh];
        if (const VkPipeline want = p.resolve(pipeline, mesh.flags); want != bound) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, want);
            bound = want;
        }
        vkCmdSetCullMode(cmd, g.double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
        vkCmdSetFrontFace(cmd,
                          g.mirrored ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
        set_mesh(pc, mesh, g.material);
        push(cmd, p.layout(), pc);
        vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, 0, it.instance);
        ++slot.draw_calls;
        ++tally.draw_calls;
        tally.triangles += mesh.index_count / 3;
    }
}

void Renderer::record_shadows(VkCommandBuffer cmd, FrameSlot& slot, Pipelines& p,
                              std::uint32_t cascades) {
    const Image& map = resources_->get(shadow_map_);
    const std::uint32_t res = options_.shadow_resolution;
    transition(
        cmd,
        {map.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT,
         VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
         VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});
    for (std::uint32_t c = 0; c < cascades; ++c) {
        auto depth =
            vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
        depth.imageView = map.layer_views[c].get();
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {1.0f, 0};
        auto ri = vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
        ri.renderArea = {{0, 0}, {res, res}};
        ri.layerCount = 1;
        ri.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &ri);
        set_viewport(cmd, res, res);
        // Standard Z for the light; slope-scaled bias against acne on grazing faces.
        set_depth(cmd, VK_COMPARE_OP_LESS, true, 1.0f, 1.5f);
        CullStats& tally = slot.passes.at(1 + c).stats;
        // Casters cull as the camera does: a single-sided surface that the camera
        // cannot see from its back blocks no light arriving at its back either (else
        // TextureSettingsTest's hidden wrong-way polygon shadows the test behind it);
        // double-sided surfaces cast from both sides. The light's viewport is flipped
        // like the camera's, so front faces wind the same way.
        draw_groups(cmd, slot, p, DrawPipeline{p.get(PipelineId::ShadowOpaque)}, AlphaMode::Opaque,
                    c, true, tally);
        draw_groups(cmd, slot, p, DrawPipeline{p.get(PipelineId::ShadowMask)}, AlphaMode::Mask, c,
                    true, tally);
        vkCmdEndRendering(cmd);
    }
    transition(cmd, {map.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT,
                     VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                     VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                     VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    shadow_map_valid_ = true;
}

void Renderer::record_passes(VkCommandBuffer cmd, FrameSlot& slot, const RenderTarget& target,
                             const RenderSettings& settings) {
    Pipelines& p = pipelines_for(target.format);
    ensure_depth(target.width, target.height);
    bool shadows = false;
    std::uint32_t cascades = 0;
    fill_frame_data(slot, settings, float(target.width) / float(target.height), shadows, cascades);
    slot.shadows_rendered = shadows;
    slot.push_base = GPUPushConstants{};
    if (scene_) slot.push_base.instances = scene_->instances_address();
    bind_frame_set(slot);
    slot.push_base.cascade = kNoCascade;
    cull_frame(cmd, slot, settings, float(target.width) / float(target.height),
               shadows ? cascades : 0);
    CullStats unused;
    CullStats& shading = slot.pass_count ? slot.passes[0].stats : unused;

    const VkDescriptorSet sets[] = {bindless_->set(), slot.set};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout(), 0, 2, sets, 0,
                            nullptr);
    if (scene_ && scene_->index_buffer() != VK_NULL_HANDLE)
        vkCmdBindIndexBuffer(cmd, scene_->index_buffer(), 0, VK_INDEX_TYPE_UINT32);
    VkQueryPool ts = slot.timestamps.get();
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ts, 0);
    if (shadows) record_shadows(cmd, slot, p, cascades);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ts, 1);

    const Image& depth_image = resources_->get(depth_);
    // Both attachments are cleared: their previous contents do not matter.
    transition(
        cmd,
        {target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
         // Source stages include transfers: after an earlier frame's readback copy.
         VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
         VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT});
    transition(
        cmd,
        {depth_image.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
         VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});

    auto color = vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    color.imageView = target.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    const glm::vec4 cc = settings.clear_color;
    color.clearValue.color = {{cc.r, cc.g, cc.b, cc.a}};
    auto depth = vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    depth.imageView = depth_image.view.get();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {0.0f, 0}; // reverse-Z: 0 is infinitely far
    auto ri = vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    ri.renderArea = {{0, 0}, {target.width, target.height}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &color;
    ri.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &ri);
    set_viewport(cmd, target.width, target.height);
    if (slot.statistics) vkCmdBeginQuery(cmd, slot.statistics.get(), 0, 0);

    if (settings.floor_only) {
        // Same triangles, one constant colour: what the rasterizer costs by itself.
        set_depth(cmd, VK_COMPARE_OP_GREATER, true);
        for (AlphaMode a : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend})
            draw_groups(cmd, slot, p, DrawPipeline{p.get(PipelineId::Floor)}, a, kNoCascade, true,
                        shading);
        for (std::uint32_t i = 2; i < kTimestampCount - 1; ++i)
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ts, i);
    } else {
        const bool prepass = prepass_enabled(settings.depth_prepass, context_.info().is_cpu(),
                                             scene_ ? scene_->triangle_count() : 0,
                                             std::uint64_t{target.width} * target.height);
        if (prepass) {
            set_depth(cmd, VK_COMPARE_OP_GREATER, true);
            draw_groups(cmd, slot, p, DrawPipeline{p.get(PipelineId::PrepassOpaque)},
                        AlphaMode::Opaque, kNoCascade, true, slot.prepass);
            draw_groups(cmd, slot, p, DrawPipeline{p.get(PipelineId::PrepassMask)}, AlphaMode::Mask,
                        kNoCascade, true, slot.prepass);
        }
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ts, 2);
        const DrawPipeline forward{VK_NULL_HANDLE, static_cast<std::uint32_t>(settings.view),
                                   false};
        // After the prepass only the visible surface passes: shade each pixel once.
        set_depth(cmd, prepass ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_GREATER, !prepass);
        draw_groups(cmd, slot, p, forward, AlphaMode::Opaque, kNoCascade, true, shading);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ts, 3);
        draw_groups(cmd, slot, p, forward, AlphaMode::Mask, kNoCascade, true, shading);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ts, 4);
        set_depth(cmd, VK_COMPARE_OP_GREATER, false);
        draw_blended(cmd, slot, p,
                     DrawPipeline{VK_NULL_HANDLE, static_cast<std::uint32_t>(settings.view), true},
                     shading);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ts, 5);
    }
    draw_overlays(cmd, slot, p, settings);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, ts, 6);
    if (slot.statistics) vkCmdEndQuery(cmd, slot.statistics.get(), 0);
    vkCmdEndRendering(cmd);

    const bool to_transfer = target.final_layout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    transition(cmd,
               {target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                target.final_layout, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                to_transfer ? VK_PIPELINE_STAGE_2_COPY_BIT : VK_PIPELINE_STAGE_2_NONE,
                to_transfer ? VK_ACCESS_2_TRANSFER_READ_BIT : VK_ACCESS_2_NONE});
}

} // namespace sherpa::gpu
