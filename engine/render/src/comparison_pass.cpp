#include "comparison_pass.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>

#include <array>
#include <cstring>

#include "compare_comp.h"
#include "compare_frag.h"
#include "compare_vert.h"
#include "pipelines.h"

namespace sherpa::render {
namespace {

constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
// compare.comp: each invocation reduces kRun pixels of a row, kGroup invocations a group.
constexpr std::uint32_t kRun = 16, kGroup = 64;

bool encodes_srgb(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
        return true;
    default:
        return false;
    }
}

// One triangle, no vertex input, no depth, no blending: the fragment shader writes
// every pixel of the target.
gpu::UniquePipeline make_composite(VkDevice device, VkPipelineLayout layout, VkShaderModule vert,
                                   VkShaderModule frag, VkFormat format) {
    PipelineDesc d{vert, frag};
    d.depth = false;
    return make_graphics_pipeline(device, layout, format, d, "vkCreateGraphicsPipelines(compare)");
}

} // namespace

ComparisonPass::ComparisonPass(gpu::Context& context, gpu::ResourceManager& resources,
                               std::uint32_t slots)
    : context_(context), resources_(resources) {
    VkDevice device = context.device();
    const VkDescriptorSetLayoutBinding bindings[] = {
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, kStages, nullptr},
        {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, kStages, nullptr},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
    };
    set_layout_ =
        gpu::create_descriptor_set_layout(device, bindings, "vkCreateDescriptorSetLayout(compare)");
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2 * slots},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, slots}};
    pool_ = gpu::create_descriptor_pool(device, slots, sizes, "vkCreateDescriptorPool(compare)");
    const VkDescriptorSetLayout set_layout = set_layout_.get();
    const VkPushConstantRange push{kStages, 0, sizeof(GPUComparePush)};
    layout_ = gpu::create_pipeline_layout(device, {&set_layout, 1}, {&push, 1},
                                          "vkCreatePipelineLayout(compare)");

    const gpu::UniqueShaderModule comp =
        gpu::create_shader_module(device, spirv_compare_comp, "vkCreateShaderModule(compare.comp)");
    stats_pipeline_ = gpu::create_compute_pipeline(device, layout_.get(), comp.get(),
                                                   "vkCreateComputePipelines(compare)");
    vert_ =
        gpu::create_shader_module(device, spirv_compare_vert, "vkCreateShaderModule(compare.vert)");
    frag_ =
        gpu::create_shader_module(device, spirv_compare_frag, "vkCreateShaderModule(compare.frag)");

    auto si = gpu::vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    si.magFilter = si.minFilter = VK_FILTER_NEAREST; // the shaders only texelFetch
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler_ = resources.images().create_sampler(si);

    if (context.info().timestamps)
        timestamps_ = gpu::create_query_pool(device, VK_QUERY_TYPE_TIMESTAMP, 4 * slots);
    slots_.resize(slots);
    for (Slot& s : slots_) {
        auto ai = gpu::vk_init<VkDescriptorSetAllocateInfo>(
            VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
        ai.descriptorPool = pool_.get();
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &set_layout;
        gpu::vk_check(vkAllocateDescriptorSets(device, &ai, &s.set),
                      "vkAllocateDescriptorSets(compare)");
        s.stats = resources.create_buffer(
            {sizeof(GPUCompareStats),
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
             gpu::MemoryUsage::Readback, "comparison statistics"});
    }
}

ComparisonPass::~ComparisonPass() {
    for (Slot& s : slots_) resources_.destroy(s.stats);
    resources_.images().destroy(sampler_);
}

VkPipeline ComparisonPass::pipeline_for(VkFormat format) {
    gpu::UniquePipeline& p = composite_[format];
    if (!p) p = make_composite(context_.device(), layout_.get(), vert_.get(), frag_.get(), format);
    return p.get();
}

void ComparisonPass::bind(std::uint32_t index, const CompositeInputs& in) {
    Slot& slot = slots_.at(index);
    const VkSampler sampler = resources_.images().get(sampler_);
    const VkDescriptorImageInfo images[] = {{sampler, in.a.view, in.a.layout},
                                            {sampler, in.b.view, in.b.layout}};
    const VkDescriptorBufferInfo buffer{resources_.get(slot.stats).buffer.get(), 0,
                                        sizeof(GPUCompareStats)};
    std::array<VkWriteDescriptorSet, 3> writes{};
    for (std::uint32_t i = 0; i < writes.size(); ++i) {
        writes[i] = gpu::vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstSet = slot.set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType =
            i < 2 ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    }
    writes[0].pImageInfo = &images[0];
    writes[1].pImageInfo = &images[1];
    writes[2].pBufferInfo = &buffer;
    vkUpdateDescriptorSets(context_.device(), 3, writes.data(), 0, nullptr);
}

void ComparisonPass::record_stats(VkCommandBuffer cmd, std::uint32_t index,
                                  const CompositeInputs& in) {
    Slot& slot = slots_.at(index);
    const VkBuffer stats = resources_.get(slot.stats).buffer.get();
    timestamp(cmd, 4 * index, VK_PIPELINE_STAGE_2_NONE);
    vkCmdFillBuffer(cmd, stats, 0, VK_WHOLE_SIZE, 0);
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    GPUComparePush push{};
    push.side_size = {in.width, in.height};
    push.target_size = push.side_size;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, stats_pipeline_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1, &slot.set, 0,
                            nullptr);
    vkCmdPushConstants(cmd, layout_.get(), kStages, 0, sizeof(push), &push);
    const std::uint32_t runs = (in.width + kRun - 1) / kRun * in.height;
    vkCmdDispatch(cmd, (runs + kGroup - 1) / kGroup, 1, 1);
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                        VK_ACCESS_2_HOST_READ_BIT);
    timestamp(cmd, 4 * index + 1, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    slot.stats_pending = true;
    slot.pixels = std::uint64_t(in.width) * in.height;
}

void ComparisonPass::record_composite(VkCommandBuffer cmd, std::uint32_t index,
                                      const CompositeInputs& in, const gpu::RenderTarget& target,
                                      CompositeMode mode, float divider, float heat_max) {
    Slot& slot = slots_.at(index);
    timestamp(cmd, 4 * index + 2, VK_PIPELINE_STAGE_2_NONE);
    gpu::transition(cmd, {target.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          // After the acquire wait, or an earlier frame's readback copy.
                          VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                              VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                          VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
    auto color =
        gpu::vk_init<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
    color.imageView = target.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE; // every pixel is written
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    auto ri = gpu::vk_init<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    ri.renderArea = {{0, 0}, {target.width, target.height}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &color;
    vkCmdBeginRendering(cmd, &ri);
    const VkViewport vp{0.0f, 0.0f, float(target.width), float(target.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {target.width, target.height}};
    vkCmdSetViewport(cmd, 0, 1, &vp);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    GPUComparePush push{};
    push.side_size = {in.width, in.height};
    push.target_size = {target.width, target.height};
    push.mode = static_cast<std::uint32_t>(mode);
    push.target_srgb = encodes_srgb(target.format) ? 1u : 0u;
    push.divider_px = divider * float(target.width);
    push.heat_max = heat_max * 255.0f;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_for(target.format));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &slot.set, 0,
                            nullptr);
    vkCmdPushConstants(cmd, layout_.get(), kStages, 0, sizeof(push), &push);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
    const bool to_transfer = target.final_layout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    gpu::transition(cmd, {target.image, VK_IMAGE_ASPECT_COLOR_BIT,
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, target.final_layout,
                          VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                          to_transfer ? VK_PIPELINE_STAGE_2_COPY_BIT : VK_PIPELINE_STAGE_2_NONE,
                          to_transfer ? VK_ACCESS_2_TRANSFER_READ_BIT : VK_ACCESS_2_NONE});
    timestamp(cmd, 4 * index + 3, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    slot.composite_pending = true;
}

void ComparisonPass::timestamp(VkCommandBuffer cmd, std::uint32_t query,
                               VkPipelineStageFlags2 stage) {
    if (!timestamps_) return;
    // The slot's previous frame has completed: its queries may be reset from the host.
    if (query % 2 == 0) vkResetQueryPool(context_.device(), timestamps_.get(), query, 2);
    vkCmdWriteTimestamp2(cmd, stage, timestamps_.get(), query);
}

double ComparisonPass::elapsed_ms(std::uint32_t first_query) const {
    if (!timestamps_) return 0.0;
    std::uint64_t ts[2] = {};
    gpu::vk_check(vkGetQueryPoolResults(context_.device(), timestamps_.get(), first_query, 2,
                                        sizeof(ts), ts, sizeof(std::uint64_t),
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  "vkGetQueryPoolResults(compare timestamps)");
    return double(ts[1] - ts[0]) * context_.info().timestamp_period_ns * 1e-6;
}

ReducedStats ComparisonPass::take_stats(std::uint32_t index) {
    Slot& slot = slots_.at(index);
    ReducedStats out;
    if (slot.stats_pending) {
        GPUCompareStats raw;
        std::memcpy(&raw, resources_.get(slot.stats).mapped, sizeof(raw));
        out.raw = raw;
        out.pixels = slot.pixels;
        out.reduce_ms = elapsed_ms(4 * index);
    }
    if (slot.composite_pending) out.composite_ms = elapsed_ms(4 * index + 2);
    slot.stats_pending = slot.composite_pending = false;
    return out;
}

} // namespace sherpa::render
