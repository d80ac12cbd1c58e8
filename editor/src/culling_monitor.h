#pragma once
// Runs the engine's CPU culling pass for the viewport camera whenever it moves and
// keeps a history for the culling dock's chart. "Freeze" keeps culling with the
// camera as it was, so the user can fly outside and look at what was culled.
#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>
#include <optional>

#include <sherpa/scene/animation.h>
#include <sherpa/scene/culling_passes.h>

#include "editor_context.h"

namespace sherpa::editor {

struct CullSample {
    CullStats cpu;
    // The GPU culling shader run for the same frustum and method while the GPU path
    // is on (the dock's agreement indicator); -1: not run.
    double gpu_ms = -1.0;
    std::int64_t gpu_visible = -1;
    std::int64_t cpu_gpu_differences = -1; // objects the two paths disagree on
};

// What the GPU culling shader made of a frustum, against the CPU's visible set.
struct GpuCullResult {
    double gpu_ms = -1.0;
    std::int64_t visible = -1;
    std::int64_t differences = -1; // objects the two paths disagree on
};
// Called on the GUI thread when the check is done; nullopt when it could not run.
using GpuCullDone = std::function<void(std::optional<GpuCullResult>)>;
// Runs the GPU culling for a frustum and compares it with the CPU's visible set (per
// scene instance) without waiting: the answer comes through `done`, later.
using GpuCullCheck = std::function<void(const Frustum&, CullMethod,
                                        std::vector<std::uint8_t> cpu_visible, GpuCullDone done)>;

class CullingMonitor : public QObject {
    Q_OBJECT
public:
    static constexpr std::size_t kHistory = 240;
    explicit CullingMonitor(const EditorContext& context, QObject* parent = nullptr);

    void setMethod(CullMethod method);
    CullMethod method() const { return options_.method; }
    void setFrozen(bool frozen);
    // The renderer culls on the GPU: each update also asks `check` (the renderer's
    // GPU culling shader) how far it agrees with the CPU pass; the answer fills the
    // newest sample when it comes (one for an older sample is dropped) and emits
    // updated() again. Nothing waits for it.
    void setGpuPath(bool gpu);
    void setGpuCheck(GpuCullCheck check) { gpu_check_ = std::move(check); }
    bool frozen() const { return frozen_.has_value(); }
    // The camera the culling runs for (the frozen one while frozen).
    const CameraSpec& cullingCamera() const { return frozen_ ? *frozen_ : camera_; }
    // Culls for `camera` (the viewport calls this when the camera moves): now when
    // the pass is cheap, else coalesced so that culling takes at most a third of the
    // GUI thread (the 100k grid costs tens of ms per pass; camera input comes at 60 Hz).
    void update(const CameraSpec& camera);
    // Passes that cost at least this much are coalesced (kCoalesceAboveMs by default).
    void setCoalesceAboveMs(double ms) { coalesce_above_ms_ = ms; }
    // What the last CPU pass cost.
    double lastPassMs() const { return last_ms_; }
    // A coalesced update is waiting.
    bool deferred() const { return deferred_->isActive(); }
    // Runs a deferred update now (tests, before reading latest()).
    void flush();
    // The pose on screen (the timeline's; null: the scene as loaded): instances are
    // culled with their conservative posed bounds (culling_bounds()), as the renderer does.
    void setPose(std::shared_ptr<const Pose> pose);
    // The box instance `i` is culled with now.
    Aabb box(std::size_t i) const { return input_.boxes.box(i); }

    const RingHistory<CullSample>& history() const { return history_; }
    const CullSample* latest() const {
        return history_.size() ? &history_[history_.size() - 1] : nullptr;
    }
    // Per-instance result of the last pass (1 visible), for box colouring.
    const std::vector<std::uint8_t>& visible() const { return visible_; }

Q_SIGNALS:
    void updated();

private:
    void rerun();

    static constexpr double kCoalesceAboveMs = 4.0; // passes cheaper than this run at once
    static constexpr int kPosedGpuCheckMs = 200;    // pose changes with the GPU check on
    const EditorContext& context_;
    CullInput input_; // boxes and draw groups, prepared once per scene
    CullOptions options_;
    CameraSpec camera_;
    std::optional<CameraSpec> frozen_;
    RingHistory<CullSample> history_{kHistory};
    std::vector<std::uint8_t> visible_;
    std::shared_ptr<const Pose> pose_;
    bool gpu_path_ = false;
    GpuCullCheck gpu_check_;
    double last_ms_ = 0.0; // cost of the last pass
    double coalesce_above_ms_ = kCoalesceAboveMs;
    std::uint64_t samples_ = 0; // passes run; a GPU answer belongs to one of them
    QTimer* deferred_;          // a coalesced update waiting
};

} // namespace sherpa::editor
