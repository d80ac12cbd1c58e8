#pragma once
// What a Presenter needs from whatever draws its frames: the presenter owns the
// surface, swapchain, acquire, submission and present; a FrameSource records one
// frame into the image it is handed. The render layer's PresentedFrame
// (sherpa/render/presented_frame.h) is the renderer as a frame source.
#include <cstdint>
#include <span>

#include <vulkan/vulkan.h>

namespace sherpa::gpu {

// A colour image the caller owns, drawn by one frame and left in `final_layout`
// after it.
struct RenderTarget {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t width = 0, height = 0;
    VkImageLayout final_layout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    // The image also takes blits (transfer writes), filtered with `blit_filter`: a
    // source may draw a reduced-resolution frame elsewhere and scale it up into it.
    bool blit_target = false;
    VkFilter blit_filter = VK_FILTER_NEAREST;
};

// Frame slots: the presenter cycles slot = 0, 1, .., frames_in_flight() - 1 and,
// for each frame, calls wait_for_slot, record (into a command buffer it has begun),
// then submits the buffer and calls submitted with the submission's timeline value.
class FrameSource {
public:
    virtual ~FrameSource() = default;
    // How many frames may be in flight; the presenter keeps that many slots.
    virtual std::uint32_t frames_in_flight() const = 0;
    // Returns once the frame last recorded in `slot` has completed on the GPU.
    virtual void wait_for_slot(std::uint32_t slot) = 0;
    // Records the frame drawing into `target` (its size is the swapchain's).
    virtual void record(VkCommandBuffer cmd, std::uint32_t slot, const RenderTarget& target) = 0;
    // Semaphores the submission of the frame just recorded in `slot` also signals
    // (asked after record): a source drawing with another ResourceManager's
    // resources signals that manager's timeline too, so its waits and deferred
    // releases see the frame.
    virtual std::span<const VkSemaphoreSubmitInfo> signals(std::uint32_t slot) const {
        (void)slot;
        return {};
    }
    // The frame recorded in `slot` was submitted, signalling `submission`.
    virtual void submitted(std::uint32_t slot, std::uint64_t submission) = 0;
};

} // namespace sherpa::gpu
