#pragma once
// The renderer as the frame source of a Presenter (sherpa/gpu/presenter.h): one
// frame of `settings`, drawn at the swapchain's size into the image the presenter
// acquired, with the renderer's frame slots. Made per presented frame:
//     PresentedFrame frame(renderer, settings);
//     presenter.present_frame(frame);
#include <sherpa/gpu/frame_source.h>
#include <sherpa/render/renderer.h>

namespace sherpa::gpu {

class PresentedFrame final : public FrameSource {
public:
    // `settings`' width and height are replaced by the target's.
    PresentedFrame(Renderer& renderer, const RenderSettings& settings);

    std::uint32_t frames_in_flight() const override { return Renderer::kFramesInFlight; }
    void wait_for_slot(std::uint32_t slot) override;
    void record(VkCommandBuffer cmd, std::uint32_t slot, const RenderTarget& target) override;
    void submitted(std::uint32_t slot, std::uint64_t submission) override;

private:
    Renderer& renderer_;
    RenderSettings settings_;
};

} // namespace sherpa::gpu
