#include "renderer_impl.h"

#include <sherpa/render/presented_frame.h>

namespace sherpa::gpu {

PresentedFrame::PresentedFrame(Renderer& renderer, const RenderSettings& settings)
    : renderer_(renderer), settings_(settings) {}

void PresentedFrame::wait_for_slot(std::uint32_t slot) {
    renderer_.impl_->wait_for_slot(slot);
}

void PresentedFrame::record(VkCommandBuffer cmd, std::uint32_t slot, const RenderTarget& target) {
    settings_.width = target.width;
    settings_.height = target.height;
    renderer_.impl_->record_frame(cmd, slot, target, settings_);
}

void PresentedFrame::submitted(std::uint32_t slot, std::uint64_t submission) {
    renderer_.impl_->finish_frame(slot, submission);
}

} // namespace sherpa::gpu
