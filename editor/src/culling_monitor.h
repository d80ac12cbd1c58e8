#pragma once
// Runs the engine's CPU culling pass for the viewport camera whenever it moves, paced
// (PassPacing), into a history for the culling dock (CullHistory), with the GPU path's
// agreement check. "Freeze" keeps culling with the camera as it was, so the user can
// fly outside and look at what was culled.
#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>
#include <optional>

#include <sherpa/scene/animation.h>
#include <sherpa/scene/culling_passes.h>

#include "cull_history.h"
#include "editor_context.h"

namespace sherpa::editor {

// Called on the GUI thread when the check is done; nullopt when it could not run.
using GpuCullDone = std::function<void(std::optional<GpuCullResult>)>;
// Runs the GPU culling for a frustum and compares it with the CPU's visible set (per
// scene instance) without waiting: the answer comes through `done`, later.
using GpuCullCheck = std::function<void(const scene::Frustum&, scene::CullMethod,
                                        std::vector<std::uint8_t> cpu_visible, GpuCullDone done)>;

// When a pass runs: at once while passes are cheap, else coalesced so that culling
// takes at most a third of the GUI thread (the 100k grid costs tens of ms per pass;
// camera input comes at 60 Hz).
class PassPacing {
public:
    explicit PassPacing(std::function<void()> run_pass);
    // A pass is wanted (the camera moved): now when the last one cost less than the
    // threshold, else once the GUI thread has had twice the last pass's time.
    void request();
    // A pass is wanted within `ms` (pose changes while the GPU check is on), unless
    // one is waiting already.
    void requestWithin(int ms);
    // A pass runs now: a waiting one is not needed.
    void cancel() { deferred_.stop(); }
    // What the pass that ran cost.
    void ran(double ms) { last_ms_ = ms; }
    double lastPassMs() const { return last_ms_; }
    // Passes that cost at least this much are coalesced (4 ms by default).
    void setCoalesceAboveMs(double ms) { coalesce_above_ms_ = ms; }
    // A coalesced pass is waiting.
    bool deferred() const { return deferred_.isActive(); }
    // Runs a waiting pass now (tests, before reading the history).
    void flush();

private:
    std::function<void()> run_pass_;
    QTimer deferred_;
    double last_ms_ = 0.0;
    double coalesce_above_ms_ = 4.0; // passes cheaper than this run at once
};

class CullingMonitor : public QObject {
    Q_OBJECT
public:
    explicit CullingMonitor(const EditorContext& context, QObject* parent = nullptr);

    void setMethod(scene::CullMethod method);
    scene::CullMethod method() const { return options_.method; }
    void setFrozen(bool frozen);
    // The camera the culling runs for while frozen; none: the viewport's.
    const std::optional<scene::CameraSpec>& frozenCamera() const { return frozen_; }
    // The renderer culls on the GPU: each pass also asks `check` (the renderer's
    // GPU culling shader) how far it agrees with the CPU pass; the answer fills the
    // pass's sample when it comes (one for an older pass is dropped) and emits
    // updated() again. Nothing waits for it.
    void setGpuPath(bool gpu);
    void setGpuCheck(GpuCullCheck check) { gpu_check_ = std::move(check); }
    // Culls for `camera` (the viewport calls this when the camera moves), paced().
    void update(const scene::CameraSpec& camera);
    // The pose on screen (the timeline's; null: the scene as loaded): instances are
    // culled with their conservative posed bounds (culling_bounds()), as the renderer does.
    void setPose(std::shared_ptr<const scene::Pose> pose);
    // The boxes and draw groups the passes cull (per scene, posed).
    const scene::CullInput& input() const { return input_; }
    const CullHistory& history() const { return history_; }
    PassPacing& pacing() { return pacing_; }

Q_SIGNALS:
    void updated();

private:
    void rerun();

    static constexpr int kPosedGpuCheckMs = 200; // pose changes with the GPU check on
    const EditorContext& context_;
    scene::CullInput input_; // boxes and draw groups, prepared once per scene
    scene::CullOptions options_;
    scene::CameraSpec camera_;
    std::optional<scene::CameraSpec> frozen_;
    CullHistory history_;
    std::vector<std::uint8_t> visible_; // per instance, of the last pass (1 visible)
    std::shared_ptr<const scene::Pose> pose_;
    bool gpu_path_ = false;
    GpuCullCheck gpu_check_;
    PassPacing pacing_;
};

} // namespace sherpa::editor
