#pragma once
// Which frame the render thread draws next and at what size: a frame whose camera or
// pose differs from the last one drawn is moving (drawn at the interactive resolution
// scale, chosen from what the frames before cost); once no new request comes for
// kRestMs the last frame is drawn again at full size, and a path-traced still frame is
// drawn again at once until it has kPathSamples. Pure policy: no thread, no clock, no
// lock (RenderThread holds its own around every call).
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>

#include "resolution_scale.h"
#include "viewport_request.h"

namespace sherpa::editor {

// One frame asked of the render thread: what to draw, on which surface, and its
// serial (RenderThread::requestFrame()).
struct FrameOrder {
    ViewportRequest frame;
    std::uint64_t surface = 0;
    std::uint64_t serial = 0;
};

// How moving frames are paced (RenderThread::setPacing()).
struct PacingOptions {
    bool interactiveScaling = true;        // reduced resolution while moving; off: full size
    double targetFrameMs = kTargetFrameMs; // what moving frames aim at
};

class FramePacing {
public:
    static constexpr int kRestMs = 80; // no new camera for this long: the camera rests

    void setOptions(const PacingOptions& options) { options_ = options; }
    // Whether `order` is still: nothing drawn to compare with, or the same camera,
    // size and pose as the last frame drawn (a playing animation is motion too: the
    // timeline makes a new pose per step, and the same one while paused).
    bool still(const FrameOrder& order) const;
    // The fraction of each side to draw a frame at.
    float scale(bool still) const;
    // How long to wait for a new request before drawing the last frame again
    // (again()); nullopt: nothing to refine, wait for a request.
    std::optional<std::chrono::milliseconds> restWait() const;
    // The last frame drawn, to draw again at rest (full size, or one more sample).
    const std::optional<FrameOrder>& again() const { return last_; }
    // `order` was drawn at `scale`, as `outcome` says, in `ms` (wall clock): the next
    // moving frame's scale, and whether the frame is refined at rest.
    void drawn(const FrameOrder& order, float scale, const PresentOutcome& outcome, double ms);
    // Nothing to refine until the next frame is drawn (one drawn full size now).
    void stopRefining() { refine_ = false; }
    // No last frame: the next one is still whatever its camera (a new scene's framing,
    // a surface gone, a frame that failed).
    void forget();

private:
    PacingOptions options_;
    std::optional<FrameOrder> last_; // the last frame drawn (for the refinement at rest)
    bool refine_ = false;            // last_ was drawn reduced: draw it full at rest
    bool accumulating_ = false;      // last_ is path traced and wants more samples
    float scale_ = 1.0f;             // for the next moving frame
    std::deque<float> drawn_scales_; // of the last presents (to match GPU timings)
};

} // namespace sherpa::editor
