#include "resolution_scale.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sherpa::editor {

float next_resolution_scale(float scale, double frame_ms, double target_ms) {
    if (frame_ms <= 0.0 || target_ms <= 0.0) return scale;
    const double wanted = static_cast<double>(scale) * std::sqrt(target_ms / frame_ms);
    const double clamped = std::clamp(wanted, static_cast<double>(kMinResolutionScale), 1.0);
    const double step = static_cast<double>(kResolutionScaleStep);
    const auto rounded = static_cast<float>(std::round(clamped / step) * step);
    const float next = std::clamp(rounded, kMinResolutionScale, 1.0f);
    // Within one step of the current scale: keep it (no new image for a jitter).
    if (std::abs(next - scale) < kResolutionScaleStep * 0.999f && next < 1.0f) return scale;
    return next;
}

void FrameTimes::add(double ms) {
    if (!first_seen_) { // pipeline creation: not what a frame costs
        first_seen_ = true;
        return;
    }
    recent_.push_back(ms);
    if (recent_.size() > kWindow) recent_.pop_front();
}

double FrameTimes::meanMs() const {
    if (recent_.empty()) return 0.0;
    return std::accumulate(recent_.begin(), recent_.end(), 0.0) /
           static_cast<double>(recent_.size());
}

} // namespace sherpa::editor
