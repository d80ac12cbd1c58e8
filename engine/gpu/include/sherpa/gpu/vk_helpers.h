#pragma once
// One call each for the small objects the engine creates by hand again and again:
// descriptor-set layouts and pools, pipeline layouts, shader modules, compute pipelines,
// query pools.
// Each throws GpuError naming `what` when creation fails and returns the RAII handle.
#include <cstddef>
#include <cstdint>
#include <span>

#include <sherpa/gpu/unique_handle.h>

namespace sherpa::gpu {

UniqueDescriptorSetLayout create_descriptor_set_layout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings, const char* what,
    VkDescriptorSetLayoutCreateFlags flags = 0, const void* next = nullptr);
UniqueDescriptorPool create_descriptor_pool(VkDevice device, std::uint32_t max_sets,
                                            std::span<const VkDescriptorPoolSize> sizes,
                                            const char* what,
                                            VkDescriptorPoolCreateFlags flags = 0);
// One set of `layout` from `pool` (freed with the pool); throws GpuError naming `what`.
VkDescriptorSet allocate_descriptor_set(VkDevice device, VkDescriptorPool pool,
                                        VkDescriptorSetLayout layout, const char* what);
UniquePipelineLayout create_pipeline_layout(VkDevice device,
                                            std::span<const VkDescriptorSetLayout> sets,
                                            std::span<const VkPushConstantRange> push_constants,
                                            const char* what);
// `code`: SPIR-V words.
UniqueShaderModule create_shader_module(VkDevice device, std::span<const std::uint32_t> code,
                                        const char* what);
// A compute pipeline of `module`'s "main", specialised by `constants` (may be null).
UniquePipeline create_compute_pipeline(VkDevice device, VkPipelineLayout layout,
                                       VkShaderModule module, const char* what,
                                       const VkSpecializationInfo* constants = nullptr);
// Pipeline statistics pools name the counters in `statistics`.
UniqueQueryPool create_query_pool(VkDevice device, VkQueryType type, std::uint32_t count,
                                  VkQueryPipelineStatisticFlags statistics = 0);

} // namespace sherpa::gpu
