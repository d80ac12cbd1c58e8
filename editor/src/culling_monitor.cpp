#include "culling_monitor.h"

#include <QElapsedTimer>

namespace sherpa::editor {

CullingMonitor::CullingMonitor(const EditorContext& context, QObject* parent)
    : QObject(parent), context_(context) {
    options_.count_false_positives = true; // the dock shows them; the exact test is cheap
    deferred_ = new QTimer(this);
    deferred_->setSingleShot(true);
    connect(deferred_, &QTimer::timeout, this, &CullingMonitor::rerun);
    connect(&context_, &EditorContext::sceneReady, this, [this] {
        input_ = context_.scene() ? prepare_cull_input(*context_.scene()) : CullInput{};
        pose_.reset();
        history_ = RingHistory<CullSample>(kHistory);
        frozen_.reset();
        rerun();
    });
}

void CullingMonitor::setMethod(CullMethod method) {
    options_.method = method;
    rerun();
}

void CullingMonitor::setFrozen(bool frozen) {
    if (frozen)
        frozen_ = camera_;
    else
        frozen_.reset();
    rerun();
}

void CullingMonitor::setGpuPath(bool gpu) {
    gpu_path_ = gpu;
    rerun();
}

void CullingMonitor::update(const CameraSpec& camera) {
    camera_ = camera;
    if (last_ms_ < coalesce_above_ms_) return rerun();
    // Expensive: the latest camera once the GUI thread has had twice the pass's time.
    if (!deferred_->isActive()) deferred_->start(static_cast<int>(2.0 * last_ms_));
}

void CullingMonitor::setPose(std::shared_ptr<const Pose> pose) {
    const Scene* scene = context_.scene();
    if (!scene || pose == pose_) return;
    pose_ = std::move(pose);
    if (pose_)
        input_.boxes.assign(instance_culling_bounds(*scene, *pose_));
    else
        input_.boxes = instance_boxes(*scene); // as prepare_cull_input() made them
    // The GPU path's check waits for the render thread: at most a few per second while
    // the timeline plays, not one per tick.
    if (gpu_path_ && gpu_check_) {
        if (!deferred_->isActive()) deferred_->start(kPosedGpuCheckMs);
        return;
    }
    update(camera_); // coalesced like camera moves: playing costs the GUI what orbiting does
}

void CullingMonitor::flush() {
    if (deferred_->isActive()) {
        deferred_->stop();
        rerun();
    }
}

void CullingMonitor::rerun() {
    deferred_->stop();
    const Scene* scene = context_.scene();
    if (!scene) {
        visible_.clear();
        Q_EMIT updated();
        return;
    }
    const CameraSpec& cam = cullingCamera();
    const Frustum frustum = frustum_from_view_projection(cam.view_projection());
    QElapsedTimer clock; // the CPU pass alone
    clock.start();
    PassResult pass = cull_pass(input_, frustum, cam.eye, options_, "camera");
    last_ms_ = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    visible_.assign(scene->instances.size(), 0);
    for (std::uint32_t i : pass.visible_opaque) visible_[i] = 1;
    for (std::uint32_t i : pass.visible_transparent) visible_[i] = 1;
    CullSample sample;
    sample.cpu = std::move(pass.stats);
    history_.push(std::move(sample));
    const std::uint64_t serial = ++samples_;
    Q_EMIT updated();
    if (!gpu_path_ || !gpu_check_) return;
    gpu_check_(frustum, options_.method, visible_, [this, serial](std::optional<GpuCullResult> r) {
        // Only for the sample it was asked for: a newer pass (camera, scene, method)
        // asks again.
        if (!r || serial != samples_ || history_.size() == 0) return;
        CullSample& s = history_.back();
        s.gpu_ms = r->gpu_ms;
        s.gpu_visible = r->visible;
        s.cpu_gpu_differences = r->differences;
        s.cpu.cpu_gpu_differences = r->differences;
        Q_EMIT updated();
    });
}

} // namespace sherpa::editor
