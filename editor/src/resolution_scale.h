#pragma once
// Interactive resolution: while the camera moves, frames are drawn at a fraction of
// the viewport's size (each side times `scale`) chosen from the measured cost of the
// frames before, so that a slow device (lavapipe) keeps a target frame rate; at
// rest the frame is drawn at full size again. Pure arithmetic, no clock.
#include <cstddef>
#include <deque>

namespace sherpa::editor {

// The goal is 30 fps while moving; the scale aims at 36 so that the frames slower
// than the estimate (present, load from elsewhere) leave the mean at 30
// (sherpa-bench-orbit, DamagedHelmet on lavapipe: aiming at 30 itself held 27-29).
inline constexpr int kGoalFps = 30;
inline constexpr double kTargetFrameMs = 1000.0 / 36.0;
inline constexpr float kMinResolutionScale = 0.25f; // a quarter of each side at most
inline constexpr float kResolutionScaleStep = 1.0f / 16.0f;

// The scale of the next moving frame, given the last one drawn at `scale` cost
// `frame_ms`. Frame cost is taken as proportional to the pixels drawn (scale²), so
// the area is multiplied by target/cost; the result is clamped to
// [kMinResolutionScale, 1] and rounded to kResolutionScaleStep, and changes
// of less than one step are ignored (a new size reallocates the reduced image).
// A non-positive `frame_ms` (not measured) keeps `scale`.
float next_resolution_scale(float scale, double frame_ms, double target_ms = kTargetFrameMs);

// Frame times of the recent frames for the status bar, leaving out the first frame
// of a renderer (pipeline creation makes it ten times as slow as the rest).
class FrameTimes {
public:
    static constexpr std::size_t kWindow = 30;
    void add(double ms);
    // Mean of the recent frames after the first; 0 before there is one.
    double meanMs() const;
    double fps() const { return meanMs() > 0.0 ? 1000.0 / meanMs() : 0.0; }
    std::size_t count() const { return recent_.size(); }

private:
    bool first_seen_ = false;
    std::deque<double> recent_;
};

} // namespace sherpa::editor
