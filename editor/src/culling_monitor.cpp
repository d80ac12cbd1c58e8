#include "culling_monitor.h"

#include <QElapsedTimer>

namespace sherpa::editor {

PassPacing::PassPacing(std::function<void()> run_pass) : run_pass_(std::move(run_pass)) {
    deferred_.setSingleShot(true);
    QObject::connect(&deferred_, &QTimer::timeout, [this] { run_pass_(); });
}

void PassPacing::request() {
    if (last_ms_ < coalesce_above_ms_) return run_pass_();
    // Expensive: the latest camera once the GUI thread has had twice the pass's time.
    if (!deferred_.isActive()) deferred_.start(static_cast<int>(2.0 * last_ms_));
}

void PassPacing::requestWithin(int ms) {
    if (!deferred_.isActive()) deferred_.start(ms);
}

void PassPacing::flush() {
    if (deferred_.isActive()) {
        deferred_.stop();
        run_pass_();
    }
}

CullingMonitor::CullingMonitor(const EditorContext& context, QObject* parent)
    : QObject(parent), context_(context), pacing_([this] { rerun(); }) {
    options_.count_false_positives = true; // the dock shows them; the exact test is cheap
    connect(&context_, &EditorContext::sceneReady, this, [this] {
        input_ =
            context_.scene() ? scene::prepare_cull_input(*context_.scene()) : scene::CullInput{};
        pose_.reset();
        history_.clear();
        frozen_.reset();
        rerun();
    });
}

void CullingMonitor::setMethod(scene::CullMethod method) {
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

void CullingMonitor::update(const scene::CameraSpec& camera) {
    camera_ = camera;
    pacing_.request();
}

void CullingMonitor::setPose(std::shared_ptr<const scene::Pose> pose) {
    const scene::Scene* scene = context_.scene();
    if (!scene || pose == pose_) return;
    pose_ = std::move(pose);
    if (pose_)
        input_.boxes.assign(scene::instance_culling_bounds(*scene, *pose_));
    else
        input_.boxes = scene::instance_boxes(*scene); // as prepare_cull_input() made them
    // The GPU path's check waits for the render thread: at most a few per second while
    // the timeline plays, not one per tick.
    if (gpu_path_ && gpu_check_) return pacing_.requestWithin(kPosedGpuCheckMs);
    update(camera_); // coalesced like camera moves: playing costs the GUI what orbiting does
}

void CullingMonitor::rerun() {
    pacing_.cancel();
    const scene::Scene* scene = context_.scene();
    if (!scene) {
        visible_.clear();
        Q_EMIT updated();
        return;
    }
    const scene::CameraSpec& cam = frozen_ ? *frozen_ : camera_;
    const scene::Frustum frustum = scene::frustum_from_view_projection(cam.view_projection());
    QElapsedTimer clock; // the CPU pass alone
    clock.start();
    scene::PassResult pass = scene::cull_pass(input_, frustum, cam.eye, options_, "camera");
    pacing_.ran(static_cast<double>(clock.nsecsElapsed()) / 1e6);
    visible_.assign(scene->instances.size(), 0);
    for (std::uint32_t i : pass.visible_opaque) visible_[i] = 1;
    for (std::uint32_t i : pass.visible_transparent) visible_[i] = 1;
    CullSample sample;
    sample.cpu = std::move(pass.stats);
    sample.cpu.view_projection = cam.view_projection(); // what it culled against
    sample.frozen = frozen_.has_value();
    const std::uint64_t serial = history_.push(std::move(sample));
    Q_EMIT updated();
    if (!gpu_path_ || !gpu_check_) return;
    gpu_check_(frustum, options_.method, visible_, [this, serial](std::optional<GpuCullResult> r) {
        // Only for the sample it was asked for: a newer pass (camera, scene, method)
        // asks again.
        if (r && history_.answer(serial, *r)) Q_EMIT updated();
    });
}

} // namespace sherpa::editor
