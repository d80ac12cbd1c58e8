#pragma once
// The scene's motion: the timeline dock's pose drawn in every frame and followed by
// the culling dock, the timeline shown for scenes that move, and warnings about nodes
// the pose pushes past the float range.
#include <QObject>

#include <cstdint>
#include <vector>

#include "gpu_viewport.h"

namespace sherpa::editor {

class CullingMonitor;
class EditorContext;
class LogDock;
class TimelineDock;
class ViewportWindow;

class MotionController : public QObject {
    Q_OBJECT
public:
    MotionController(EditorContext& context, TimelineDock& timeline, CullingMonitor& culling,
                     LogDock& log, ViewportWindow& viewport, QObject* parent);

    // The timeline dock shows for scenes with animations or motions.
    void showTimelineForScene();
    // The pose of the next frame (null: the scene as loaded).
    void fill(render::FrameRequest& request) const;

private:
    // Warns in the log about nodes the timeline's pose pushes past the float range
    // (their bounds are left out; culling keeps them), once per change of that set.
    void logPoseOverflow();

    EditorContext& context_;
    TimelineDock& timeline_;
    CullingMonitor& culling_;
    LogDock& log_;
    std::vector<std::uint32_t> pose_overflow_logged_; // nodes logPoseOverflow() last named
};

} // namespace sherpa::editor
