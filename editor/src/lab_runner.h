#pragma once
// Runs a Lab family (engine/lab) or the budget report off the UI thread. A family's
// worker loads the scene file again as `sherpa-cli lab` does (lab_load_options():
// tangents as in the file, not as the editor shows them), so the dock and the CLI
// measure the same input, and reports its progress; the budget reads the editor's scene; cancel()
// stops it at its next unit of work and drops what it measured. One run at a time: starting another
// cancels the one in flight. Workers run at nice 10 and post progress at most 20 times a second, so
// the UI thread keeps its cores.
#include <QFuture>
#include <QList>
#include <QObject>
#include <QString>
#include <QThreadPool>

#include <memory>

#include <sherpa/lab/budget.h>
#include <sherpa/lab/family.h>
#include <sherpa/render/environment.h>
#include <sherpa/render/frame_request.h>

namespace sherpa::editor {

class LabRunner : public QObject {
    Q_OBJECT
public:
    explicit LabRunner(QObject* parent = nullptr);
    ~LabRunner() override; // cancels and waits for the worker

    // How the families that draw lit frames (shadows) light them: the main view's
    // environment and display settings. The environment is made by the worker, and only
    // for such a family.
    void setLighting(const render::EnvironmentChoice& environment,
                     const render::FrameRequest& settings);

    // Runs family `family` ("tangents", "textures", "culling") on the scene `spec`.
    void start(const QString& family, const QString& spec);
    // Builds the budget report of `scene`, the scene the editor shows (loaded with the
    // options `sherpa-cli budget` uses), without loading it again.
    void startBudget(std::shared_ptr<const scene::Scene> scene);
    void cancel();
    bool running() const { return job_ != nullptr; }
    // Blocks until the worker has returned (tests, shutdown).
    void wait();

Q_SIGNALS:
    void progress(int done, int total);
    void finished(std::shared_ptr<const sherpa::lab::FamilyReport> report);
    void budgetFinished(std::shared_ptr<const sherpa::lab::BudgetReport> report);
    void failed(const QString& error);
    void cancelled();

private:
    struct Job;
    std::shared_ptr<Job> begin();
    void end(const std::shared_ptr<Job>& job);

    std::shared_ptr<Job> job_; // the run in flight; null: none
    render::EnvironmentChoice environment_{render::EnvironmentChoice::Kind::None, {}};
    render::FrameRequest lighting_;
    // Its own threads: a family runs for seconds, and in the global pool it would hold
    // the thread the scene loader's thumbnails wait for (measured: Box took 29 s to load
    // while a textures run held the pool of a 2-core machine).
    QThreadPool pool_;
    QList<QFuture<void>> workers_; // cancelled ones may still be returning
};

} // namespace sherpa::editor
