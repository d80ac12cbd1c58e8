#pragma once
// Loads a scene off the UI thread (QtConcurrent) while the current one stays
// interactive. The engine reports its stages (parse, geometry, tangents per mesh)
// and polls the job's cancel token; the thumbnail stage that follows counts
// textures. Cancel stops the worker at its next check and drops whatever it built:
// the current scene is never touched.
#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>
#include <optional>

#include <sherpa/scene/scene.h>
#include <sherpa/scene/tangents.h>
#include <sherpa/texture/texture_target.h>

#include "scene_session.h"

namespace sherpa::editor {

// What the progress bar shows; Parse..Tangents mirror the engine's LoadStage.
enum class LoadStep : int { Idle, Parse, Geometry, Tangents, Textures };

// The worker's answer: the session, or why there is none.
struct LoadOutcome {
    std::shared_ptr<SceneSession> session; // null on failure or cancel
    QString error;                         // empty on success
    bool cancelled = false;                // stopped by cancel(): no scene, no error to show
};

class SceneLoadJob : public QObject {
    Q_OBJECT
public:
    explicit SceneLoadJob(QObject* parent = nullptr);
    ~SceneLoadJob() override; // cancels and waits for a running load

    // Starts loading `spec`, its textures prepared on the worker for `target` (the
    // viewport's device; none: no textures) with the cache and encoder settings of
    // `textures` (progress per texture); a load already running is cancelled first. With
    // `tangents`, every triangle primitive gets tangents made by that method, authored
    // ones replaced (a comparison's side B); without, the glTF rule (exact MikkTSpace
    // where TANGENT is absent and a normal texture needs it).
    void start(const QString& spec, const std::optional<tex::TextureTarget>& target = {},
               const tex::PipelineOptions& textures = {},
               std::optional<scene::TangentMethod> tangents = std::nullopt);
    void cancel();
    bool running() const { return state_ != nullptr; }
    const QString& spec() const { return spec_; }
    // Loads cancelled whose workers have not finished yet (tests: none may linger).
    static int workersInFlight();

    // Synchronous variant without textures, for the tests.
    static LoadOutcome loadNow(const QString& spec);

    struct State; // progress and the cancel token, shared with the worker

Q_SIGNALS:
    // Every stage change and count change (at most ~100 per stage), in order.
    void progress(sherpa::editor::LoadStep step, int done, int total);
    // The loaded scene as one value (its timings.total_ms filled in).
    void loaded(sherpa::editor::SharedSession session);
    void failed(const QString& spec, const QString& error);
    void canceled(const QString& spec);

private:
    void onFinished();

    QString spec_;
    std::shared_ptr<State> state_;
    QFutureWatcher<LoadOutcome>* watcher_ = nullptr;
};

} // namespace sherpa::editor
