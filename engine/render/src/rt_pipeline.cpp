#include "rt_pipeline.h"

#include "as_build.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>

#include <array>
#include <cstring>
#include <vector>

namespace sherpa::render {

RayPipeline::RayPipeline(gpu::Context& context, gpu::ResourceManager& resources,
                         VkPipelineLayout layout, const RayShaders& shaders)
    : context_(context), resources_(resources), fn_(gpu::RayTracingFunctions::load(context)) {
    VkDevice device = context.device();
    const gpu::UniqueShaderModule modules[] = {
        gpu::create_shader_module(device, shaders.raygen, "vkCreateShaderModule(raygen)"),
        gpu::create_shader_module(device, shaders.miss, "vkCreateShaderModule(miss)"),
        gpu::create_shader_module(device, shaders.closest_hit, "vkCreateShaderModule(closest hit)"),
        gpu::create_shader_module(device, shaders.any_hit, "vkCreateShaderModule(any hit)"),
    };
    const VkShaderStageFlagBits stage_bits[] = {
        VK_SHADER_STAGE_RAYGEN_BIT_KHR, VK_SHADER_STAGE_MISS_BIT_KHR,
        VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, VK_SHADER_STAGE_ANY_HIT_BIT_KHR};
    std::array<VkPipelineShaderStageCreateInfo, 4> stages{};
    for (std::size_t i = 0; i < stages.size(); ++i) {
        stages[i] = gpu::vk_init<VkPipelineShaderStageCreateInfo>(
            VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
        stages[i].stage = stage_bits[i];
        stages[i].module = modules[i].get();
        stages[i].pName = "main";
    }
    std::array<VkRayTracingShaderGroupCreateInfoKHR, 3> groups{};
    for (auto& g : groups) {
        g = gpu::vk_init<VkRayTracingShaderGroupCreateInfoKHR>(
            VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR);
        g.generalShader = g.closestHitShader = g.anyHitShader = g.intersectionShader =
            VK_SHADER_UNUSED_KHR;
    }
    groups[0].type = groups[1].type = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
    groups[0].generalShader = 0;
    groups[1].generalShader = 1;
    groups[2].type = VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR;
    groups[2].closestHitShader = 2;
    groups[2].anyHitShader = 3;
    auto ci = gpu::vk_init<VkRayTracingPipelineCreateInfoKHR>(
        VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR);
    ci.stageCount = static_cast<std::uint32_t>(stages.size());
    ci.pStages = stages.data();
    ci.groupCount = static_cast<std::uint32_t>(groups.size());
    ci.pGroups = groups.data();
    ci.maxPipelineRayRecursionDepth = 1; // raygen traces; hit shaders never do
    ci.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    gpu::vk_check(
        fn_.create_pipelines(device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline),
        "vkCreateRayTracingPipelinesKHR");
    pipeline_ = gpu::UniquePipeline(device, pipeline);

    // Raygen, miss and hit group, each in its own region at the base alignment; the
    // buffer is over-allocated so the first region's address can be aligned.
    const gpu::DeviceInfo& info = context_.info();
    const std::uint32_t handle = info.shader_group_handle_size;
    const VkDeviceSize stride = align_up(handle, info.shader_group_handle_alignment);
    const VkDeviceSize region = align_up(stride, info.shader_group_base_alignment);
    std::vector<std::uint8_t> handles(3 * std::size_t(handle));
    gpu::vk_check(
        fn_.get_group_handles(device, pipeline_.get(), 0, 3, handles.size(), handles.data()),
        "vkGetRayTracingShaderGroupHandlesKHR");
    sbt_ = resources_.create_buffer(
        {3 * region + info.shader_group_base_alignment,
         VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
         gpu::MemoryUsage::Upload, "shader binding table"});
    const gpu::Buffer& b = resources_.get(sbt_);
    const VkDeviceAddress base = align_up(b.address, info.shader_group_base_alignment);
    auto* bytes = static_cast<std::uint8_t*>(b.mapped) + (base - b.address);
    for (std::uint32_t g = 0; g < 3; ++g)
        std::memcpy(bytes + g * region, handles.data() + g * handle, handle);
    raygen_ = {base, stride, stride}; // the raygen region's size must equal its stride
    miss_ = {base + region, stride, stride};
    hit_ = {base + 2 * region, stride, stride};
}

RayPipeline::~RayPipeline() {
    resources_.destroy(sbt_);
}

void RayPipeline::bind(VkCommandBuffer cmd) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_.get());
}

void RayPipeline::trace(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) const {
    fn_.cmd_trace_rays(cmd, &raygen_, &miss_, &hit_, &callable_, width, height, 1);
}

} // namespace sherpa::render
