#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>

namespace sherpa::gpu {

UniqueDescriptorSetLayout create_descriptor_set_layout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings, const char* what,
    VkDescriptorSetLayoutCreateFlags flags, const void* next) {
    auto ci = vk_init<VkDescriptorSetLayoutCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    ci.pNext = next;
    ci.flags = flags;
    ci.bindingCount = static_cast<std::uint32_t>(bindings.size());
    ci.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    vk_check(vkCreateDescriptorSetLayout(device, &ci, nullptr, &layout), what);
    return UniqueDescriptorSetLayout(device, layout);
}

VkDescriptorSet allocate_descriptor_set(VkDevice device, VkDescriptorPool pool,
                                        VkDescriptorSetLayout layout, const char* what) {
    auto ai = vk_init<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    ai.descriptorPool = pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    vk_check(vkAllocateDescriptorSets(device, &ai, &set), what);
    return set;
}

UniqueDescriptorPool create_descriptor_pool(VkDevice device, std::uint32_t max_sets,
                                            std::span<const VkDescriptorPoolSize> sizes,
                                            const char* what, VkDescriptorPoolCreateFlags flags) {
    auto ci = vk_init<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    ci.flags = flags;
    ci.maxSets = max_sets;
    ci.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    ci.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    vk_check(vkCreateDescriptorPool(device, &ci, nullptr, &pool), what);
    return UniqueDescriptorPool(device, pool);
}

UniquePipelineLayout create_pipeline_layout(VkDevice device,
                                            std::span<const VkDescriptorSetLayout> sets,
                                            std::span<const VkPushConstantRange> push_constants,
                                            const char* what) {
    auto ci = vk_init<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    ci.setLayoutCount = static_cast<std::uint32_t>(sets.size());
    ci.pSetLayouts = sets.data();
    ci.pushConstantRangeCount = static_cast<std::uint32_t>(push_constants.size());
    ci.pPushConstantRanges = push_constants.data();
    VkPipelineLayout layout = VK_NULL_HANDLE;
    vk_check(vkCreatePipelineLayout(device, &ci, nullptr, &layout), what);
    return UniquePipelineLayout(device, layout);
}

UniqueShaderModule create_shader_module(VkDevice device, std::span<const std::uint32_t> code,
                                        const char* what) {
    auto ci = vk_init<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    ci.codeSize = code.size_bytes();
    ci.pCode = code.data();
    VkShaderModule module = VK_NULL_HANDLE;
    vk_check(vkCreateShaderModule(device, &ci, nullptr, &module), what);
    return UniqueShaderModule(device, module);
}

UniquePipeline create_compute_pipeline(VkDevice device, VkPipelineLayout layout,
                                       VkShaderModule module, const char* what,
                                       const VkSpecializationInfo* constants) {
    auto ci = vk_init<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    ci.stage = vk_init<VkPipelineShaderStageCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = module;
    ci.stage.pName = "main";
    ci.stage.pSpecializationInfo = constants;
    ci.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    vk_check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline), what);
    return UniquePipeline(device, pipeline);
}

UniqueQueryPool create_query_pool(VkDevice device, VkQueryType type, std::uint32_t count,
                                  VkQueryPipelineStatisticFlags statistics) {
    auto ci = vk_init<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    ci.queryType = type;
    ci.queryCount = count;
    ci.pipelineStatistics = statistics;
    VkQueryPool pool = VK_NULL_HANDLE;
    vk_check(vkCreateQueryPool(device, &ci, nullptr, &pool), "vkCreateQueryPool");
    return UniqueQueryPool(device, pool);
}

} // namespace sherpa::gpu
