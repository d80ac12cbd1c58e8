#include "frame_pacing.h"

#include <algorithm>

#include "viewport_presenter.h"

namespace sherpa::editor {

namespace {

// The camera and the frame's size (the orbit camera's aspect follows the size; the
// request leaves the aspect to the viewport).
bool same_camera(const render::FrameRequest& a, const render::FrameRequest& b) {
    return a.camera.eye == b.camera.eye && a.camera.target == b.camera.target &&
           a.camera.up == b.camera.up && a.camera.fov_degrees == b.camera.fov_degrees &&
           a.camera.aspect == b.camera.aspect && a.width == b.width && a.height == b.height;
}

} // namespace

bool FramePacing::still(const FrameOrder& order) const {
    return !last_ || (same_camera(last_->frame.request, order.frame.request) &&
                      last_->frame.request.pose == order.frame.request.pose);
}

float FramePacing::scale(bool still) const {
    return !still && options_.interactiveScaling ? scale_ : 1.0f;
}

std::optional<std::chrono::milliseconds> FramePacing::restWait() const {
    if (!refine_) return std::nullopt;
    // Accumulating path-traced samples: the next frame right away unless a request
    // comes (the camera moves) first.
    return std::chrono::milliseconds(accumulating_ ? 0 : kRestMs);
}

void FramePacing::drawn(const FrameOrder& order, float scale, const PresentOutcome& outcome,
                        double ms) {
    // The completed frame's GPU time belongs to the present kFramesInFlight back.
    constexpr std::size_t in_flight = ViewportPresenter::kFramesInFlight;
    drawn_scales_.push_back(scale);
    while (drawn_scales_.size() > in_flight + 1) drawn_scales_.pop_front();
    double cost = ms;
    if (outcome.gpu_ms > 0.0 && drawn_scales_.size() > in_flight) {
        const float then = drawn_scales_.front();
        cost = std::max(cost, outcome.gpu_ms * double(scale * scale) / double(then * then));
    }
    // Every frame informs the next moving frame's scale: a still frame too says what
    // full size costs.
    if (outcome.shown) scale_ = next_resolution_scale(scale, cost, options_.targetFrameMs);
    last_ = order;
    // A path-traced still frame goes on accumulating until kPathSamples.
    accumulating_ = outcome.shown && scale >= 1.0f && outcome.path_traced &&
                    outcome.path_samples < ViewportPresenter::kPathSamples;
    refine_ = outcome.shown && (scale < 1.0f || accumulating_);
}

void FramePacing::forget() {
    last_.reset();
    refine_ = false;
}

} // namespace sherpa::editor
