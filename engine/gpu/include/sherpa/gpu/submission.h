#pragma once
// The submission timeline: one timeline semaphore that every queue submission of a
// ResourceManager's owner signals, with a strictly increasing value per submission.
// What the GPU has finished is then one number (completed_submission()), which is
// how retired resources know when they may go and how callers wait for their work.
#include <cstdint>

#include <vulkan/vulkan.h>

#include <sherpa/gpu/unique_handle.h>

namespace sherpa::gpu {

class SubmissionTimeline {
public:
    explicit SubmissionTimeline(VkDevice device);

    VkSemaphore semaphore() const { return semaphore_.get(); }
    // The value the submission about to be made signals (each call a new one).
    std::uint64_t begin_submission() { return ++submitted_; }
    std::uint64_t last_submission() const { return submitted_; }
    std::uint64_t completed_submission() const;
    void wait_for(std::uint64_t value) const;

private:
    VkDevice device_;
    UniqueSemaphore semaphore_;
    std::uint64_t submitted_ = 0;
};

} // namespace sherpa::gpu
