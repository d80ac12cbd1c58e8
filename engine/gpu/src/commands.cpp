#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>

namespace sherpa::gpu {

void transition(VkCommandBuffer cmd, const ImageTransition& t) {
    VkImageMemoryBarrier2 b =
        vk_init<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
    b.srcStageMask = t.src_stage;
    b.srcAccessMask = t.src_access;
    b.dstStageMask = t.dst_stage;
    b.dstAccessMask = t.dst_access;
    b.oldLayout = t.from;
    b.newLayout = t.to;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = t.image;
    b.subresourceRange = {t.aspect, t.base_mip, t.mip_count, t.base_layer, t.layer_count};
    VkDependencyInfo dep = vk_init<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    VkMemoryBarrier2 b = vk_init<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
    b.srcStageMask = src_stage;
    b.srcAccessMask = src_access;
    b.dstStageMask = dst_stage;
    b.dstAccessMask = dst_access;
    VkDependencyInfo dep = vk_init<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

CommandRecorder::CommandRecorder(Context& context) : context_(context) {
    VkCommandPoolCreateInfo ci =
        vk_init<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    ci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    ci.queueFamilyIndex = context.queue_family();
    VkCommandPool pool = VK_NULL_HANDLE;
    vk_check(vkCreateCommandPool(context.device(), &ci, nullptr, &pool), "vkCreateCommandPool");
    pool_ = UniqueCommandPool(context.device(), pool);
    VkCommandBufferAllocateInfo ai =
        vk_init<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    ai.commandPool = pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    vk_check(vkAllocateCommandBuffers(context.device(), &ai, &cmd_), "vkAllocateCommandBuffers");
}

VkCommandBuffer CommandRecorder::begin() {
    vk_check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo bi =
        vk_init<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk_check(vkBeginCommandBuffer(cmd_, &bi), "vkBeginCommandBuffer");
    return cmd_;
}

std::uint64_t CommandRecorder::submit(ResourceManager& resources,
                                      const VkSemaphoreSubmitInfo* waits, std::uint32_t wait_count,
                                      const VkSemaphoreSubmitInfo* signals,
                                      std::uint32_t signal_count) {
    vk_check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
    const std::uint64_t value = resources.timeline().begin_submission();
    std::vector<VkSemaphoreSubmitInfo> all_signals(signals, signals + signal_count);
    VkSemaphoreSubmitInfo timeline =
        vk_init<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    timeline.semaphore = resources.timeline().semaphore();
    timeline.value = value;
    timeline.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    all_signals.push_back(timeline);
    VkCommandBufferSubmitInfo cb =
        vk_init<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
    cb.commandBuffer = cmd_;
    VkSubmitInfo2 si = vk_init<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
    si.waitSemaphoreInfoCount = wait_count;
    si.pWaitSemaphoreInfos = waits;
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &cb;
    si.signalSemaphoreInfoCount = static_cast<std::uint32_t>(all_signals.size());
    si.pSignalSemaphoreInfos = all_signals.data();
    vk_check(vkQueueSubmit2(context_.queue(), 1, &si, VK_NULL_HANDLE), "vkQueueSubmit2");
    return value;
}

} // namespace sherpa::gpu
