#pragma once
// Small helpers for recording: synchronization2 barriers and one-shot command
// buffers that signal the resource manager's submission timeline.
#include <cstdint>

#include <vulkan/vulkan.h>

#include <sherpa/gpu/resources.h>

namespace sherpa::gpu {

struct ImageTransition {
    VkImage image = VK_NULL_HANDLE;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageLayout from = VK_IMAGE_LAYOUT_UNDEFINED, to = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 src_stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 src_access = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 dst_stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 dst_access = VK_ACCESS_2_NONE;
    std::uint32_t base_mip = 0, mip_count = VK_REMAINING_MIP_LEVELS;
    std::uint32_t base_layer = 0, layer_count = VK_REMAINING_ARRAY_LAYERS;
};

void transition(VkCommandBuffer cmd, const ImageTransition& t);
void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

// A command pool with one primary command buffer, reset and reused per recording.
class CommandRecorder {
public:
    explicit CommandRecorder(Context& context);
    VkCommandBuffer begin();
    // Ends and submits the buffer, signalling the timeline; returns the value.
    std::uint64_t submit(ResourceManager& resources, const VkSemaphoreSubmitInfo* waits = nullptr,
                         std::uint32_t wait_count = 0,
                         const VkSemaphoreSubmitInfo* signals = nullptr,
                         std::uint32_t signal_count = 0);
    VkCommandBuffer buffer() const { return cmd_; }

private:
    Context& context_;
    UniqueCommandPool pool_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
};

} // namespace sherpa::gpu
