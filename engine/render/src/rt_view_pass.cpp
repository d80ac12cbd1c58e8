#include "rt_view_pass.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>

#include <array>
#include <cstring>

#include "rt_rahit.h"
#include "rt_rchit.h"
#include "rt_rgen.h"
#include "rt_rmiss.h"

namespace sherpa::render {
namespace {

constexpr VkShaderStageFlags kHitStages =
    VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR;
constexpr VkShaderStageFlags kAllStages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR | kHitStages;

} // namespace

RtViewPass::RtViewPass(gpu::Context& context, gpu::ResourceManager& resources,
                       VkDescriptorSetLayout bindless_layout)
    : context_(context), resources_(resources) {
    VkDevice device = context.device();
    const VkDescriptorSetLayoutBinding bindings[] = {
        {0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1, VK_SHADER_STAGE_RAYGEN_BIT_KHR,
         nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_RAYGEN_BIT_KHR, nullptr},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kHitStages, nullptr},
        {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kHitStages, nullptr},
        // The rasterizer's frame constants and shadow cascades (shadow-error view).
        {4, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_RAYGEN_BIT_KHR, nullptr},
        {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_RAYGEN_BIT_KHR, nullptr},
    };
    set_layout_ =
        gpu::create_descriptor_set_layout(device, bindings, "vkCreateDescriptorSetLayout(rt)");
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
                                          {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                          {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    pool_ = gpu::create_descriptor_pool(device, 1, sizes, "vkCreateDescriptorPool(rt)");
    set_ = gpu::allocate_descriptor_set(device, pool_.get(), set_layout_.get(),
                                        "vkAllocateDescriptorSets(rt)");

    const VkDescriptorSetLayout sets[] = {bindless_layout, set_layout_.get()};
    const VkPushConstantRange push{kAllStages, 0, sizeof(GPURayPushConstants)};
    layout_ = gpu::create_pipeline_layout(device, sets, {&push, 1}, "vkCreatePipelineLayout(rt)");

    pipeline_ = std::make_unique<RayPipeline>(
        context, resources, layout_.get(),
        RayShaders{spirv_rt_rgen, spirv_rt_rmiss, spirv_rt_rchit, spirv_rt_rahit});
}

RtViewPass::~RtViewPass() {
    resources_.destroy(readback_);
    resources_.images().destroy(target_);
}

void RtViewPass::ensure_target(std::uint32_t width, std::uint32_t height) {
    if (target_.valid() && width == width_ && height == height_) return;
    resources_.images().destroy(target_);
    resources_.destroy(readback_);
    gpu::ImageDesc d;
    d.format = VK_FORMAT_R8G8B8A8_UNORM; // storage: the shader writes sRGB-encoded bytes
    d.width = width;
    d.height = height;
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
              VK_IMAGE_USAGE_SAMPLED_BIT; // read by the comparison pass
    d.name = "ray-traced view";
    target_ = resources_.images().create(d);
    readback_ = resources_.create_buffer({VkDeviceSize(width) * height * 4,
                                          VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          gpu::MemoryUsage::Readback, "ray-traced view readback"});
    width_ = width;
    height_ = height;
}

void RtViewPass::record(VkCommandBuffer cmd, const RayTracedFrame& f, bool readback) {
    ensure_target(f.width, f.height);
    const gpu::Image& image = resources_.images().get(target_);
    auto as_write = gpu::vk_init<VkWriteDescriptorSetAccelerationStructureKHR>(
        VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR);
    as_write.accelerationStructureCount = 1;
    as_write.pAccelerationStructures = &f.tlas;
    const VkDescriptorImageInfo image_info{VK_NULL_HANDLE, image.view.get(),
                                           VK_IMAGE_LAYOUT_GENERAL};
    const VkDescriptorBufferInfo buffers[] = {{f.materials, 0, VK_WHOLE_SIZE},
                                              {f.material_extras, 0, VK_WHOLE_SIZE}};
    const VkDescriptorBufferInfo frame_info{f.frame_data, 0, VK_WHOLE_SIZE};
    std::array<VkWriteDescriptorSet, 6> writes{};
    for (std::uint32_t i = 0; i < writes.size(); ++i) {
        writes[i] = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstSet = set_;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
    }
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
    writes[0].pNext = &as_write;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    writes[1].pImageInfo = &image_info;
    for (std::uint32_t i = 2; i < 4; ++i) {
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &buffers[i - 2];
    }
    writes[4].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[4].pBufferInfo = &frame_info;
    writes[5].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[5].pImageInfo = &f.shadow_map;
    vkUpdateDescriptorSets(context_.device(), static_cast<std::uint32_t>(writes.size()),
                           writes.data(), 0, nullptr);

    // The cascades were drawn by an earlier submission (render_rt): their depth
    // writes made visible to the rays.
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR,
                        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    gpu::ImageTransition t;
    t.image = image.image.get();
    t.to = VK_IMAGE_LAYOUT_GENERAL;
    t.dst_stage = VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR;
    t.dst_access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    gpu::transition(cmd, t);
    pipeline_->bind(cmd);
    const VkDescriptorSet sets[] = {f.bindless, set_};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout_.get(), 0, 2, sets,
                            0, nullptr);
    vkCmdPushConstants(cmd, layout_.get(), kAllStages, 0, sizeof(f.push), &f.push);
    pipeline_->trace(cmd, f.width, f.height);
    if (!readback) {
        gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        return;
    }
    t.from = VK_IMAGE_LAYOUT_GENERAL;
    t.to = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    t.src_stage = VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR;
    t.src_access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    t.dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT;
    t.dst_access = VK_ACCESS_2_TRANSFER_READ_BIT;
    gpu::transition(cmd, t);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {f.width, f.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           resources_.get(readback_).buffer.get(), 1, &region);
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void RtViewPass::read(std::vector<std::uint8_t>& rgba) const {
    rgba.resize(std::size_t(width_) * height_ * 4);
    std::memcpy(rgba.data(), resources_.get(readback_).mapped, rgba.size());
}

} // namespace sherpa::render
