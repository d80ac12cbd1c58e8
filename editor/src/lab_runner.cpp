#include "lab_runner.h"

#include <QtConcurrent/QtConcurrentRun>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>

#include <sherpa/core/progress.h>
#include <sherpa/lab/families.h>
#include <sherpa/scene/scene_loader.h>

namespace sherpa::editor {

// Shared by the UI thread and one worker: the cancel token and when progress was last
// posted. The engine reports per unit of work (the culling family: 128 units in ~50 ms
// on DamagedHelmet), and QProgressBar::setValue repaints synchronously, dock and all:
// posting each percent kept the UI thread busy half the time (sherpa-bench-lab, perf).
// The UI hears at most kProgressHz updates a second, enough for a bar to move smoothly.
struct LabRunner::Job {
    static constexpr int kProgressHz = 20;
    core::CancelToken cancel;
    std::atomic<std::int64_t> next_progress_ns{0};

    // True when progress may be posted now (the first time, then every 1/kProgressHz s).
    bool progress_due() {
        const std::int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                     std::chrono::steady_clock::now().time_since_epoch())
                                     .count();
        std::int64_t next = next_progress_ns.load();
        return now >= next &&
               next_progress_ns.compare_exchange_strong(next, now + 1'000'000'000 / kProgressHz);
    }
};

LabRunner::LabRunner(QObject* parent) : QObject(parent) {
    // One run at a time, and the one cancelled before it may still be returning.
    pool_.setMaxThreadCount(2);
}

LabRunner::~LabRunner() {
    cancel();
    wait();
}

void LabRunner::cancel() {
    if (!job_) return;
    job_->cancel.cancel();
    job_.reset(); // whatever the worker still posts is dropped
    Q_EMIT cancelled();
}

void LabRunner::wait() {
    for (QFuture<void>& f : workers_) f.waitForFinished();
    workers_.clear();
}

std::shared_ptr<LabRunner::Job> LabRunner::begin() {
    cancel();
    workers_.removeIf([](const QFuture<void>& f) { return f.isFinished(); });
    job_ = std::make_shared<Job>();
    return job_;
}

void LabRunner::end(const std::shared_ptr<Job>& job) {
    if (job == job_) job_.reset();
}

namespace {

// Lowers the calling worker thread to nice 10 (Linux: nice is per thread, and the threads
// it starts, lavapipe's included, inherit it), so that the UI thread wins the cores the
// moment it has work. Without it, on the shared 2-core machine at load 5-8, the culling
// family's worker and lavapipe threads held the UI thread's events up to 46 ms (p99);
// niced, 12-15 ms (sherpa-bench-lab culling, alternating). The cost: on a busy machine
// a run takes longer in wall time (CPU methods are timed in thread CPU time; lavapipe's
// GPU timestamps are wall time and include preemption either way).
void lower_worker_priority() {
    setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), 10);
}

// Posts `f` to `runner`'s thread, where it runs only if `job` is still the current one.
template <class F> void post(LabRunner* runner, F f) {
    QMetaObject::invokeMethod(runner, std::move(f), Qt::QueuedConnection);
}

// Nothing may escape a pool thread (the future would hold it unseen and the run
// would never end): a failure of the family or the budget becomes the run's error.
template <class F> auto guarded(F f, QString& error) -> decltype(f()) {
    try {
        return f();
    } catch (const std::exception& e) {
        error = QString::fromUtf8(e.what());
        return nullptr;
    }
}

} // namespace

void LabRunner::setLighting(const render::EnvironmentChoice& environment,
                            const render::FrameRequest& settings) {
    environment_ = environment;
    lighting_ = settings;
}

void LabRunner::start(const QString& family_name, const QString& spec) {
    std::shared_ptr<Job> job = begin();
    workers_ << QtConcurrent::run(&pool_, [this, job, family = family_name.toStdString(),
                                           path = spec.toStdString(), environment = environment_,
                                           settings = lighting_] {
        lower_worker_priority();
        // Lit frames lit as the main view is (the file's warnings are the view's).
        render::Lighting lighting{nullptr, settings};
        if (lab::family_draws_lit_frames(family)) {
            std::vector<std::string> warnings;
            if (auto image = render::make_environment(environment, warnings))
                lighting.environment =
                    std::make_shared<const render::EnvironmentImage>(std::move(*image));
        }
        std::unique_ptr<lab::Family> family_ptr = lab::make_family(family, lighting);
        auto fail = [this, job](QString error) {
            post(this, [this, job, error] {
                if (job != job_) return;
                end(job);
                Q_EMIT failed(error);
            });
        };
        if (!family_ptr) return fail(QStringLiteral("unknown family '%1'").arg(family.c_str()));
        scene::LoadResult loaded = scene::load_scene(path, lab::lab_load_options());
        if (job->cancel.cancelled()) return;
        if (!loaded) return fail(QString::fromStdString(loaded.error));
        lab::RunControl control;
        control.cancel = &job->cancel;
        control.progress = [this, job](std::size_t done, std::size_t total) {
            if (!job->progress_due()) return;
            post(this, [this, job, done, total] {
                if (job == job_) Q_EMIT progress(int(done), int(total));
            });
        };
        QString error;
        auto report = guarded(
            [&] {
                return std::make_shared<const lab::FamilyReport>(
                    family_ptr->run(*loaded.scene, control));
            },
            error);
        if (!report) return fail(error);
        if (report->cancelled) return;
        post(this, [this, job, report] {
            if (job != job_) return;
            end(job);
            Q_EMIT finished(report);
        });
    });
}

void LabRunner::startBudget(std::shared_ptr<const scene::Scene> scene) {
    std::shared_ptr<Job> job = begin();
    workers_ << QtConcurrent::run(&pool_, [this, job, scene = std::move(scene)] {
        lower_worker_priority();
        QString error;
        auto report = guarded(
            [&] { return std::make_shared<const lab::BudgetReport>(lab::build_budget(*scene)); },
            error);
        if (job->cancel.cancelled()) return;
        post(this, [this, job, report, error] {
            if (job != job_) return;
            end(job);
            if (report)
                Q_EMIT budgetFinished(report);
            else
                Q_EMIT failed(error);
        });
    });
}

} // namespace sherpa::editor
