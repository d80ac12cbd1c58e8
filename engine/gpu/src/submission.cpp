#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/submission.h>

namespace sherpa::gpu {

SubmissionTimeline::SubmissionTimeline(VkDevice device) : device_(device) {
    VkSemaphoreTypeCreateInfo type =
        vk_init<VkSemaphoreTypeCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO);
    type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
    type.initialValue = 0;
    VkSemaphoreCreateInfo ci =
        vk_init<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    ci.pNext = &type;
    VkSemaphore s = VK_NULL_HANDLE;
    vk_check(vkCreateSemaphore(device_, &ci, nullptr, &s), "vkCreateSemaphore(timeline)");
    semaphore_ = UniqueSemaphore(device_, s);
}

std::uint64_t SubmissionTimeline::completed_submission() const {
    std::uint64_t value = 0;
    vk_check(vkGetSemaphoreCounterValue(device_, semaphore_.get(), &value),
             "vkGetSemaphoreCounterValue");
    return value;
}

void SubmissionTimeline::wait_for(std::uint64_t value) const {
    VkSemaphore s = semaphore_.get();
    VkSemaphoreWaitInfo wi = vk_init<VkSemaphoreWaitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO);
    wi.semaphoreCount = 1;
    wi.pSemaphores = &s;
    wi.pValues = &value;
    vk_check(vkWaitSemaphores(device_, &wi, UINT64_MAX), "vkWaitSemaphores");
}

} // namespace sherpa::gpu
