// MotionController: the timeline's pose to the viewport and the culling dock.
#include "motion_controller.h"

#include "culling_monitor.h"
#include "editor_context.h"
#include "log_dock.h"
#include "motion_playback.h"
#include "timeline_dock.h"
#include "viewport_window.h"

namespace sherpa::editor {

MotionController::MotionController(EditorContext& context, TimelineDock& timeline,
                                   CullingMonitor& culling, LogDock& log, ViewportWindow& viewport,
                                   QObject* parent)
    : QObject(parent), context_(context), timeline_(timeline), culling_(culling), log_(log) {
    connect(&timeline_, &TimelineDock::poseChanged, this, [this, &viewport] {
        culling_.setPose(timeline_.playback().pose()); // the culling dock follows the motion
        logPoseOverflow();
        viewport.scheduleFrame();
    });
    connect(&context_, &EditorContext::sceneReady, this, [this] {
        showTimelineForScene();
        pose_overflow_logged_.clear();
    });
}

void MotionController::showTimelineForScene() {
    const scene::Scene* scene = context_.scene();
    timeline_.setVisible(scene && (!scene->animations.empty() || !scene->motions.empty()));
}

void MotionController::fill(render::FrameRequest& request) const {
    request.pose = timeline_.playback().pose();
}

void MotionController::logPoseOverflow() {
    const scene::Scene* scene = context_.scene();
    const auto pose = timeline_.playback().pose();
    std::vector<std::uint32_t> nodes;
    if (scene && pose) nodes = scene::posed_overflow_nodes(*scene, *pose);
    if (nodes == pose_overflow_logged_) return;
    pose_overflow_logged_ = nodes;
    for (std::uint32_t node : nodes)
        log_.append(LogDock::Level::Warning,
                    tr("At %1 s: %2")
                        .arg(timeline_.playback().clock().time, 0, 'g', 4)
                        .arg(QString::fromStdString(scene::posed_overflow_warning(*scene, node))));
}

} // namespace sherpa::editor
