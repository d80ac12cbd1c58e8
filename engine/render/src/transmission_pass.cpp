#include "transmission_pass.h"

#include "draw.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/material_extensions.h>

#include <algorithm>
#include <bit>

namespace sherpa::render {
namespace {

constexpr VkFormat kRadianceFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

} // namespace

TransmissionPass::TransmissionPass(gpu::Context& context, gpu::ResourceManager& resources,
                                   VkDescriptorSetLayout textures_layout,
                                   VkDescriptorSetLayout frame_layout)
    : context_(context), resources_(resources), textures_layout_(textures_layout),
      frame_layout_(frame_layout) {}

TransmissionPass::~TransmissionPass() {
    release();
}

void TransmissionPass::release() {
    if (level0_) {
        context_.wait_idle();
        level0_.reset();
    }
    resources_.images().destroy(color_);
    resources_.images().destroy(depth_);
    resources_.images().destroy(sampler_);
    width_ = height_ = levels_ = 0;
}

bool TransmissionPass::active(const FrameContext& f) {
    return f.scene && !f.settings.floor_only && f.settings.view == DebugView::Lit &&
           f.scene->materials().extensions().transmissive_materials > 0;
}

std::uint64_t TransmissionPass::bytes() const {
    std::uint64_t b = 0;
    for (gpu::ImageHandle h : {color_, depth_})
        if (h.valid()) b += resources_.images().get(h).allocation_size;
    return b;
}

void TransmissionPass::ensure_target(FrameContext& f) {
    if (color_.valid() && width_ == f.target.width && height_ == f.target.height) return;
    release();
    width_ = f.target.width;
    height_ = f.target.height;
    levels_ = std::bit_width(std::max(width_, height_));
    gpu::ImageDesc c;
    c.format = kRadianceFormat;
    c.width = width_;
    c.height = height_;
    c.mip_levels = levels_;
    c.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
              VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    c.name = "transmission background";
    color_ = resources_.images().create(c);
    depth_ = resources_.images().create(
        depth_attachment_desc(width_, height_, "transmission background depth"));
    auto vi = gpu::vk_init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    vi.image = resources_.images().get(color_).image.get();
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = kRadianceFormat;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    gpu::vk_check(vkCreateImageView(context_.device(), &vi, nullptr, &view),
                  "vkCreateImageView(transmission)");
    level0_ = gpu::UniqueImageView(context_.device(), view);
    if (!sampler_.valid()) {
        auto si = gpu::vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
        si.magFilter = si.minFilter = VK_FILTER_LINEAR;
        si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
        si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        si.maxLod = VK_LOD_CLAMP_NONE;
        sampler_ = resources_.images().create_sampler(si);
    }
}

void TransmissionPass::prepare(FrameContext& f) {
    if (!active(f)) {
        // A scene without transmission holds nothing (another view of the same scene
        // keeps the target for when the lit view comes back).
        if (!f.scene || f.scene->materials().extensions().transmissive_materials == 0) release();
        return;
    }
    ensure_target(f);
    const VkDescriptorImageInfo info{resources_.images().get(sampler_),
                                     resources_.images().get(color_).view.get(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    auto write = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstSet = f.slot.set;
    write.dstBinding = 9;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &info;
    vkUpdateDescriptorSets(context_.device(), 1, &write, 0, nullptr);
}

void TransmissionPass::record(FrameContext& f) {
    if (!active(f)) return;
    if (!pipelines_)
        pipelines_ = std::make_unique<Pipelines>(context_, textures_layout_, frame_layout_,
                                                 kRadianceFormat, true);
    const gpu::Image& color = resources_.images().get(color_);
    const gpu::Image& depth = resources_.images().get(depth_);
    VkImage image = color.image.get();
    // Level 0 becomes the attachment (an earlier frame's fragment shaders read it).
    gpu::transition(f.cmd, {image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
                            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, 0, 1});
    gpu::transition(
        f.cmd,
        {depth.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
         VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
         VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});
    auto ca = gpu::vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    ca.imageView = level0_.get();
    ca.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    ca.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    ca.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    // Alpha 0 where no surface is: refraction.glsl adds the environment there; with a
    // solid background its colour (as radiance, as three.js clears its target).
    const bool environment_background = f.environment && f.settings.background != Background::Color;
    const glm::vec3 cc =
        environment_background ? glm::vec3(0.0f) : glm::vec3(f.settings.clear_color);
    ca.clearValue.color = {{cc.r, cc.g, cc.b, 0.0f}};
    auto da = gpu::vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    da.imageView = depth.view.get();
    da.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    da.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    da.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    da.clearValue.depthStencil = {0.0f, 0}; // reverse-Z
    auto ri = gpu::vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    ri.renderArea = {{0, 0}, {width_, height_}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &ca;
    ri.pDepthAttachment = &da;
    vkCmdBeginRendering(f.cmd, &ri);
    set_viewport(f.cmd, width_, height_);
    // The frame's passes with this pass's pipelines and target; its draws are tallied
    // apart (the camera's statistics count the shading draws once).
    gpu::RenderTarget target{image, color.view.get(), kRadianceFormat, width_, height_};
    FrameContext g{f.cmd,     f.slot,      f.slot_index, *pipelines_, f.settings, target,
                   f.context, f.resources, f.scene,      f.culling,   f.lighting};
    g.environment = f.environment;
    g.cascades = f.cascades;
    scene::CullStats tally;
    set_depth(f.cmd, VK_COMPARE_OP_GREATER, true);
    const auto view = static_cast<std::uint32_t>(DebugView::Lit);
    draw_groups(g, DrawPipeline{PipelineId::Count, view, false}, scene::AlphaMode::Opaque,
                camera_view(g), tally);
    draw_groups(g, DrawPipeline{PipelineId::Count, view, false}, scene::AlphaMode::Mask,
                camera_view(g), tally);
    vkCmdEndRendering(f.cmd);

    // The mip chain by successive linear blits, each level from the one above.
    gpu::transition(f.cmd,
                    {image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT, 0, 1});
    std::int32_t w = static_cast<std::int32_t>(width_), h = static_cast<std::int32_t>(height_);
    for (std::uint32_t level = 1; level < levels_; ++level) {
        gpu::transition(f.cmd,
                        {image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
                         VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, level, 1});
        const std::int32_t nw = std::max(w / 2, 1), nh = std::max(h / 2, 1);
        VkImageBlit blit{};
        blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
        blit.srcOffsets[1] = {w, h, 1};
        blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
        blit.dstOffsets[1] = {nw, nh, 1};
        vkCmdBlitImage(f.cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
        gpu::transition(f.cmd,
                        {image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                         VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                         VK_ACCESS_2_TRANSFER_READ_BIT, level, 1});
        w = nw;
        h = nh;
    }
    gpu::transition(f.cmd,
                    {image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_TRANSFER_READ_BIT,
                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
}

} // namespace sherpa::render
