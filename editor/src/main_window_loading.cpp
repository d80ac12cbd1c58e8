// MainWindow: opening, reloading and closing scenes, and the background load's
// progress, result and failure (the load itself runs in SceneLoadJob).
#include "main_window.h"
#include "main_window_actions.h"

#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>

#include <sherpa/scene/framing.h>
#include <sherpa/texture/quality_levels.h>

#include "culling_dock.h"
#include "culling_monitor.h"
#include "gpu_viewport.h"
#include "log_dock.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "scene_tree_dock.h"
#include "texture_dock.h"
#include "viewport_window.h"

namespace sherpa::editor {

void MainWindow::openScene(const QString& spec) {
    if (device_pending_) { // textures are prepared for the device: wait for it
        pending_open_ = spec;
        return;
    }
    log_->append(LogDock::Level::Info, tr("Loading %1…").arg(spec));
    loader_.start(spec, texture_target_, textureOptions());
}

tex::PipelineOptions MainWindow::textureOptions() const {
    // Textures are prepared on the loader thread with the cache settings of this moment.
    tex::PipelineOptions options;
    const QString dir = settings_.cacheDirectory();
    if (!dir.isEmpty()) options.cache_dir = std::filesystem::path(dir.toStdString());
    const QString quality = settings_.textureQuality();
    options.bc7_level = quality == QLatin1String("fast")   ? tex::kBc7MinLevel
                        : quality == QLatin1String("best") ? tex::kBc7MaxLevel
                                                           : tex::kBc7DefaultLevel;
    return options;
}

void MainWindow::reloadScene() {
    if (!context_.sceneSpec().isEmpty()) openScene(context_.sceneSpec());
}

void MainWindow::closeScene() {
    pending_open_.clear();
    loader_.cancel();
    context_.clearScene();
    updateStatus();
    viewport_->scheduleFrame();
}

void MainWindow::cancelLoad() {
    loader_.cancel();
}

void MainWindow::onProgress(LoadStep step, int done, int total) {
    const bool busy = step != LoadStep::Idle;
    progress_->setVisible(busy);
    cancel_->setVisible(busy);
    if (!busy) return;
    progress_->setRange(0, std::max(total, 1));
    progress_->setValue(std::min(done, std::max(total, 1)));
    switch (step) {
    case LoadStep::Parse:
        progress_->setFormat(tr("1/4 parsing…"));
        break;
    case LoadStep::Geometry:
        progress_->setFormat(tr("2/4 geometry…"));
        break;
    case LoadStep::Tangents:
        progress_->setFormat(tr("3/4 tangents: mesh %1 of %2").arg(done).arg(total));
        break;
    case LoadStep::Textures:
        progress_->setFormat(tr("4/4 textures: %1 of %2").arg(done).arg(total));
        break;
    case LoadStep::Idle:
        break;
    }
}

void MainWindow::onLoaded(SharedSession session) {
    const SceneSession& s = *session;
    // The swap: one assignment, so the old scene is shown until this very moment. Its
    // sceneReady reaches the docks and uploadScene().
    context_.setSession(session);
    settings_.addRecentFile(s.spec);
    for (const std::string& w : s.scene->warnings)
        log_->append(LogDock::Level::Warning, QString::fromStdString(w));
    log_->append(LogDock::Level::Info,
                 tr("Loaded %1 in %2 ms (engine %3 ms, thumbnails %4 ms, textures %5 ms).")
                     .arg(s.spec)
                     .arg(s.timings.total_ms, 0, 'f', 1)
                     .arg(s.timings.engine_ms, 0, 'f', 1)
                     .arg(s.timings.thumbnails_ms, 0, 'f', 1)
                     .arg(s.timings.textures_ms, 0, 'f', 1));
    if (!s.scene->placed_cameras.empty())
        log_->append(LogDock::Level::Info,
                     tr("The file places %1 camera(s): View › glTF Cameras looks through them; "
                        "the automatic view looks from the side of the first.")
                         .arg(s.scene->placed_cameras.size()));
    // The same file reloaded after a change keeps the view; any other is framed (the
    // ground plane left out).
    if (!std::exchange(keep_camera_, false)) {
        viewport_->camera().frameAuto(*s.scene);
        viewport_->setAutoFrame(true);
    }
    onCameraChanged();
    updateStatus();
    // Side B "this file, tangents by ..." follows the file (another file stays).
    if (compare_session_ && compare_tangents_) compareWithTangents(*compare_tangents_);
    Q_EMIT sceneLoaded(s.spec, s.timings.total_ms);
}

void MainWindow::onLoadFailed(const QString& spec, const QString& error) {
    keep_camera_ = false;
    log_->append(LogDock::Level::Error, error);
    // Say what is on screen now: the previous scene, or nothing when there was none.
    const bool kept = context_.scene() != nullptr;
    statusBar()->showMessage(kept ? tr("Could not load %1; the current scene is kept.").arg(spec)
                                  : tr("Could not load %1; no scene is open.").arg(spec),
                             8000);
    auto* box = new QMessageBox(
        QMessageBox::Warning, tr("Load failed"),
        kept ? tr("Could not load %1:\n%2\n\nThe current scene is kept.").arg(spec, error)
             : tr("Could not load %1:\n%2\n\nNo scene is open.").arg(spec, error),
        QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open(); // not modal: the editor stays usable (and scriptable)
    Q_EMIT loadFailed(spec, error);
}

} // namespace sherpa::editor
