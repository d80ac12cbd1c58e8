#include "culling_monitor.h"

namespace sherpa::editor {

CullingMonitor::CullingMonitor(const EditorContext& context, QObject* parent)
    : QObject(parent), context_(context) {
    options_.count_false_positives = true; // the dock shows them; the exact test is cheap
    connect(&context_, &EditorContext::sceneChanged, this, [this] {
        input_ = context_.scene() ? prepare_cull_input(*context_.scene()) : CullInput{};
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
    rerun();
}

void CullingMonitor::rerun() {
    const Scene* scene = context_.scene();
    if (!scene) {
        visible_.clear();
        Q_EMIT updated();
        return;
    }
    const CameraSpec& cam = cullingCamera();
    const Frustum frustum = frustum_from_view_projection(cam.view_projection());
    PassResult pass = cull_pass(input_, frustum, cam.eye, options_, "camera");
    visible_.assign(scene->instances.size(), 0);
    for (std::uint32_t i : pass.visible_opaque) visible_[i] = 1;
    for (std::uint32_t i : pass.visible_transparent) visible_[i] = 1;
    CullSample sample;
    sample.cpu = std::move(pass.stats);
    if (gpu_path_ && gpu_check_ && gpu_check_(frustum, options_.method, visible_, sample))
        sample.cpu.cpu_gpu_differences = sample.cpu_gpu_differences;
    history_.push(std::move(sample));
    Q_EMIT updated();
}

} // namespace sherpa::editor
