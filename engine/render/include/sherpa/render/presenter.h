#pragma once
// Swapchain rendering on a VkSurfaceKHR the caller (the editor, a test window)
// created from Context::instance(). The engine never sees window-system types:
// the surface is opaque here and stays owned by the caller, who must destroy it
// after the Presenter.
#include <cstdint>
#include <vector>

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/renderer.h>

namespace sherpa::gpu {

struct PresenterOptions {
    bool vsync = true; // FIFO; false prefers MAILBOX, then IMMEDIATE
};

class Presenter {
public:
    // Throws GpuError when the device cannot present to `surface`.
    Presenter(Renderer& renderer, VkSurfaceKHR surface, std::uint32_t width, std::uint32_t height,
              const PresenterOptions& options = {});
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    // Renders `settings` (its width/height are replaced by the swapchain's) into
    // the next image and queues it for presentation. Returns false when the
    // swapchain was out of date: it is recreated and the frame is skipped.
    // `resolution_scale` below 1 (interaction on slow devices) draws each side at
    // that fraction into an intermediate image and scales it up (linear filter)
    // into the swapchain image; 1, or a surface that cannot be a blit target,
    // draws at full size.
    bool present_frame(RenderSettings settings, float resolution_scale = 1.0f);
    // Statistics (GPU timestamps, culling) of the latest frame known to be complete:
    // read when its frame slot comes round again, kFramesInFlight frames behind the
    // last one queued. Empty before that.
    const FrameStats& completed_stats() const { return completed_; }
    // The window changed size: recreate the swapchain at the new size.
    void resize(std::uint32_t width, std::uint32_t height);

    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    std::uint32_t image_count() const { return static_cast<std::uint32_t>(images_.size()); }
    std::uint64_t frames_presented() const { return presented_; }

private:
    void create_swapchain(std::uint32_t width, std::uint32_t height);
    void destroy_swapchain_views();

    Renderer& renderer_;
    Context& context_;
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
    bool blit_target_ = false; // swapchain images take transfer writes (scaled frames)
    VkFilter blit_filter_ = VK_FILTER_NEAREST;
    FrameStats completed_;
};

} // namespace sherpa::gpu
