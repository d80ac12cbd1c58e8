#pragma once
// Loads a scene off the UI thread (QtConcurrent) while the current one stays
// interactive. The engine's load_scene is synchronous and has no cancellation
// hook, so Cancel discards the result when it arrives and says so; the thumbnail
// stage that follows it checks the flag per texture and stops early.
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QTimer>

#include <atomic>
#include <memory>

#include <sherpa/scene/scene.h>

#include "scene_extras.h"

namespace sherpa::editor {

enum class LoadStage : int { Idle, Loading, Textures };

struct LoadOutcome {
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<const SceneExtras> extras;
    QString error; // empty on success
};

class SceneLoadJob : public QObject {
    Q_OBJECT
public:
    explicit SceneLoadJob(QObject* parent = nullptr);
    ~SceneLoadJob() override; // waits for a running load (its result is dropped)

    // Starts loading `spec`; a load already running is cancelled first.
    void start(const QString& spec);
    void cancel();
    bool running() const { return state_ != nullptr; }
    const QString& spec() const { return spec_; }

    // Synchronous variant used by the command line's first scene and the tests.
    static LoadOutcome loadNow(const QString& spec);

    struct State; // progress and the cancel flag, shared with the worker

Q_SIGNALS:
    void progress(sherpa::editor::LoadStage stage, int done, int total);
    void loaded(const QString& spec, const sherpa::editor::LoadOutcome& outcome, double ms);
    void failed(const QString& spec, const QString& error);
    void canceled(const QString& spec);

private:
    void onFinished();
    void pollProgress();

    QString spec_;
    std::shared_ptr<State> state_;
    QFutureWatcher<LoadOutcome>* watcher_ = nullptr;
    QTimer poll_;
};

} // namespace sherpa::editor
