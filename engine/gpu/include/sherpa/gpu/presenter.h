#pragma once
// Swapchain presentation on a VkSurfaceKHR the caller (the editor, a test window)
// created from Context::instance(): swapchain creation and recreation, acquire,
// submission and present. What each frame shows comes from a FrameSource (the
// renderer's: sherpa/render/presented_frame.h). The engine never sees
// window-system types: the surface is opaque here and stays owned by the caller,
// who must destroy it after the Presenter.
#include <cstdint>
#include <memory>
#include <vector>

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/frame_source.h>
#include <sherpa/gpu/resources.h>

namespace sherpa::gpu {

struct PresenterOptions {
    bool vsync = true; // FIFO; false prefers MAILBOX, then IMMEDIATE
};

class Presenter {
public:
    // Submissions signal `resources`' timeline. Throws GpuError when the device
    // cannot present to `surface`.
    Presenter(Context& context, ResourceManager& resources, VkSurfaceKHR surface,
              std::uint32_t width, std::uint32_t height, const PresenterOptions& options = {});
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    // Has `source` record into the next image and queues it for presentation.
    // Returns false when the swapchain was out of date: it is recreated and the
    // frame is skipped. Every source given must have the same frames_in_flight().
    bool present_frame(FrameSource& source);
    // The window changed size: recreate the swapchain at the new size.
    void resize(std::uint32_t width, std::uint32_t height);

    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    std::uint32_t image_count() const { return static_cast<std::uint32_t>(images_.size()); }
    std::uint64_t frames_presented() const { return presented_; }

private:
    void create_swapchain(std::uint32_t width, std::uint32_t height);
    void destroy_swapchain_views();
    void make_slots(std::uint32_t frames_in_flight);

    Context& context_;
    ResourceManager& resources_;
    VkSurfaceKHR surface_;
    PresenterOptions options_;
    UniqueSwapchain swapchain_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    std::vector<VkImage> images_;
    std::vector<UniqueImageView> views_;
    std::vector<UniqueSemaphore>
        rendered_; // per swapchain image: signalled by the frame, waited by present
    std::vector<UniqueSemaphore>
        acquired_; // per frame slot: signalled by acquire, waited by the frame
    std::vector<std::unique_ptr<CommandRecorder>> recorders_; // per frame slot
    std::uint32_t frame_ = 0;
    std::uint64_t presented_ = 0;
    bool blit_target_ = false; // swapchain images take blits (reduced-resolution frames)
    VkFilter blit_filter_ = VK_FILTER_NEAREST;
};

} // namespace sherpa::gpu
