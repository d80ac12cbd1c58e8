#pragma once
// The renderer as the frame source of a Presenter (sherpa/gpu/presenter.h): one
// frame of `settings`, drawn at the swapchain's size into the image the presenter
// acquired, with the renderer's frame slots. Made per presented frame:
//     PresentedFrame frame(renderer, settings);
//     presenter.present_frame(frame);
#include <sherpa/gpu/frame_source.h>
#include <sherpa/render/renderer.h>

namespace sherpa::render {

class PresentedFrame final : public gpu::FrameSource {
public:
    // `settings`' width and height are replaced by the target's. `resolution_scale`
    // below 1 (interaction on slow devices) draws each side at that fraction into an
    // intermediate image and scales it up (the target's blit filter) into the
    // target; 1, or a target that takes no blits, draws at full size. Ray-traced
    // settings (RendererKind::RayTraced) trace the rays into the renderer's storage
    // image and composite it into the target (any target; reduced frames scale up
    // nearest); what the ray tracer refuses throws GpuError here, before recording.
    // The ray tracer rewrites its descriptor set per frame, so a ray-traced frame
    // waits for the renderer's frame in flight before it records.
    PresentedFrame(Renderer& renderer, const FrameRequest& settings, float resolution_scale = 1.0f);

    std::uint32_t frames_in_flight() const override { return Renderer::kFramesInFlight; }
    void wait_for_slot(std::uint32_t slot) override;
    void record(VkCommandBuffer cmd, std::uint32_t slot, const gpu::RenderTarget& target) override;
    void submitted(std::uint32_t slot, std::uint64_t submission) override;

    // Statistics (GPU timestamps, culling) of the latest frame known to be complete:
    // the one drawn before in this frame's slot, kFramesInFlight frames back, read
    // once the presenter has waited for the slot. Empty before that.
    const FrameStats& completed_stats() const { return completed_; }

private:
    Renderer& renderer_;
    FrameRequest settings_;
    float resolution_scale_;
    FrameStats completed_;
};

} // namespace sherpa::render
