// LoadController: opening, reloading and closing scenes, and the background load's
// progress, result and failure (the load itself runs in SceneLoadJob); the texture
// cache settings and actions. The engine's cache has no per-entry API: its entries
// are KTX2 files named by content hash in the cache directory, so both cache actions
// delete files and the next preparation makes them again.
#include "load_controller.h"
#include "main_window_actions.h"

#include <QDesktopServices>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QMainWindow>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <QUrl>

#include <algorithm>
#include <utility>

#include <sherpa/texture/quality_levels.h>

#include "editor_context.h"
#include "editor_settings.h"
#include "log_dock.h"
#include "texture_dock.h"
#include "viewport_window.h"

namespace sherpa::editor {

LoadController::LoadController(EditorContext& context, EditorSettings& settings, LogDock& log,
                               ViewportWindow& viewport, TextureDock& textures,
                               const WindowActions& actions, QProgressBar& progress,
                               QPushButton& cancel, QMainWindow& window, bool device_pending)
    : QObject(&window), context_(context), settings_(settings), log_(log), viewport_(viewport),
      progress_(progress), cancel_(cancel), window_(window), device_pending_(device_pending) {
    // Named children: tests and tools find them with findChild(), not through accessors.
    loader_.setParent(this); // a member: it leaves the children before QObject deletes them
    loader_.setObjectName(QStringLiteral("sceneLoader"));
    connect(&loader_, &SceneLoadJob::loaded, this, &LoadController::onLoaded);
    connect(&loader_, &SceneLoadJob::failed, this, &LoadController::onLoadFailed);
    connect(&loader_, &SceneLoadJob::progress, this, &LoadController::onProgress);
    connect(&loader_, &SceneLoadJob::canceled, this, [this](const QString& spec) {
        log_.append(LogDock::Level::Info,
                    tr("Loading %1 cancelled; the result is discarded.").arg(spec));
        onProgress(LoadStep::Idle, 0, 0);
        Q_EMIT loadCanceled(spec);
    });
    connect(&cancel, &QPushButton::clicked, this, &LoadController::cancelLoad);
    connectActions(actions, textures);
}

void LoadController::connectActions(const WindowActions& a, TextureDock& textures) {
    connect(a.open, &QAction::triggered, this, &LoadController::openFileDialog);
    connect(a.reload, &QAction::triggered, this, [this] { reloadScene(); });
    connect(a.close, &QAction::triggered, this, &LoadController::closeScene);
    connect(a.recent, &QMenu::aboutToShow, this, [this, recent = a.recent, clear = a.clear_recent] {
        rebuildRecentMenu(*recent, *clear);
    });
    connect(a.clear_recent, &QAction::triggered, this,
            [this] { settings_.reset(setting::kRecentFiles); });
    for (QAction* act : a.builtin_actions)
        connect(act, &QAction::triggered, this, [this, act] { openScene(act->data().toString()); });
    for (QAction* act : a.quality_actions)
        connect(act, &QAction::triggered, this,
                [this, act] { settings_.set(setting::kTextureQuality, act->data().toString()); });
    connect(a.cache_dir, &QAction::triggered, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(
            &window_, tr("Texture cache directory"), settings_.get(setting::kCacheDirectory));
        if (!dir.isEmpty()) settings_.set(setting::kCacheDirectory, dir);
    });
    connect(&textures, &TextureDock::clearCacheRequested, this, &LoadController::clearTextureCache);
    connect(&textures, &TextureDock::recompressRequested, this, &LoadController::recompressTexture);
    connect(&textures, &TextureDock::openCacheFolderRequested, this, [this] {
        QDir().mkpath(settings_.get(setting::kCacheDirectory));
        QDesktopServices::openUrl(QUrl::fromLocalFile(settings_.get(setting::kCacheDirectory)));
    });
}

void LoadController::openScene(const QString& spec) {
    if (device_pending_) { // textures are prepared for the device: wait for it
        pending_open_ = spec;
        return;
    }
    log_.append(LogDock::Level::Info, tr("Loading %1…").arg(spec));
    loader_.start(spec, texture_target_, textureOptions());
}

void LoadController::deviceKnown(const std::optional<tex::TextureTarget>& target) {
    if (target) texture_target_ = target;
    device_pending_ = false;
    if (!pending_open_.isEmpty()) openScene(std::exchange(pending_open_, QString()));
}

tex::PipelineOptions LoadController::textureOptions() const {
    // Textures are prepared on the loader thread with the cache settings of this moment.
    tex::PipelineOptions options;
    const QString dir = settings_.get(setting::kCacheDirectory);
    if (!dir.isEmpty()) options.cache_dir = std::filesystem::path(dir.toStdString());
    const QString quality = settings_.get(setting::kTextureQuality);
    options.bc7_level = quality == QLatin1String("fast")   ? tex::kBc7MinLevel
                        : quality == QLatin1String("best") ? tex::kBc7MaxLevel
                                                           : tex::kBc7DefaultLevel;
    return options;
}

void LoadController::reloadScene(bool keep_camera) {
    if (context_.sceneSpec().isEmpty()) return;
    keep_camera_ = keep_camera; // the same file again: the user looks at one spot
    openScene(context_.sceneSpec());
}

void LoadController::closeScene() {
    pending_open_.clear();
    loader_.cancel();
    context_.setSession(nullptr);
    viewport_.scheduleFrame();
}

void LoadController::cancelLoad() {
    loader_.cancel();
}

void LoadController::onProgress(LoadStep step, int done, int total) {
    const bool busy = step != LoadStep::Idle;
    progress_.setVisible(busy);
    cancel_.setVisible(busy);
    if (!busy) return;
    progress_.setRange(0, std::max(total, 1));
    progress_.setValue(std::min(done, std::max(total, 1)));
    switch (step) {
    case LoadStep::Parse:
        progress_.setFormat(tr("1/4 parsing…"));
        break;
    case LoadStep::Geometry:
        progress_.setFormat(tr("2/4 geometry…"));
        break;
    case LoadStep::Tangents:
        progress_.setFormat(tr("3/4 tangents: mesh %1 of %2").arg(done).arg(total));
        break;
    case LoadStep::Textures:
        progress_.setFormat(tr("4/4 textures: %1 of %2").arg(done).arg(total));
        break;
    case LoadStep::Idle:
        break;
    }
}

void LoadController::onLoaded(SharedSession session) {
    const SceneSession& s = *session;
    // The swap: one assignment, so the old scene is shown until this very moment. Its
    // sceneReady reaches the docks and the scene's upload.
    context_.setSession(session);
    settings_.addRecentFile(s.spec);
    for (const std::string& w : s.scene->warnings)
        log_.append(LogDock::Level::Warning, QString::fromStdString(w));
    log_.append(LogDock::Level::Info,
                tr("Loaded %1 in %2 ms (engine %3 ms, thumbnails %4 ms, textures %5 ms).")
                    .arg(s.spec)
                    .arg(s.timings.total_ms, 0, 'f', 1)
                    .arg(s.timings.engine_ms, 0, 'f', 1)
                    .arg(s.timings.thumbnails_ms, 0, 'f', 1)
                    .arg(s.timings.textures_ms, 0, 'f', 1));
    if (!s.scene->placed_cameras.empty())
        log_.append(LogDock::Level::Info,
                    tr("The file places %1 camera(s): View › glTF Cameras looks through them; "
                       "the automatic view looks from the side of the first.")
                        .arg(s.scene->placed_cameras.size()));
    // The same file reloaded after a change keeps the view; any other is framed (the
    // ground plane left out).
    if (!std::exchange(keep_camera_, false)) {
        viewport_.camera().frameAuto(*s.scene);
        viewport_.input().setAutoFrame(true);
    }
    Q_EMIT sceneLoaded(s.spec, s.timings.total_ms);
}

void LoadController::onLoadFailed(const QString& spec, const QString& error) {
    keep_camera_ = false;
    log_.append(LogDock::Level::Error, error);
    // Say what is on screen now: the previous scene, or nothing when there was none.
    const bool kept = context_.scene() != nullptr;
    window_.statusBar()->showMessage(
        kept ? tr("Could not load %1; the current scene is kept.").arg(spec)
             : tr("Could not load %1; no scene is open.").arg(spec),
        8000);
    auto* box = new QMessageBox(
        QMessageBox::Warning, tr("Load failed"),
        kept ? tr("Could not load %1:\n%2\n\nThe current scene is kept.").arg(spec, error)
             : tr("Could not load %1:\n%2\n\nNo scene is open.").arg(spec, error),
        QMessageBox::Ok, &window_);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open(); // not modal: the editor stays usable (and scriptable)
    Q_EMIT loadFailed(spec, error);
}

void LoadController::rebuildRecentMenu(QMenu& menu, QAction& clear) {
    menu.clear();
    const QStringList files = settings_.get(setting::kRecentFiles);
    if (files.isEmpty()) menu.addAction(tr("(no recent files)"))->setEnabled(false);
    for (const QString& f : files)
        connect(menu.addAction(f), &QAction::triggered, this, [this, f] { openScene(f); });
    menu.addSeparator();
    menu.addAction(&clear);
}

void LoadController::openFileDialog() {
    const QString path =
        QFileDialog::getOpenFileName(&window_, tr("Open glTF scene"), QString(),
                                     tr("glTF scenes (*.gltf *.glb);;All files (*)"));
    if (!path.isEmpty()) openScene(path);
}

int LoadController::clearTextureCache() {
    QDir dir(settings_.get(setting::kCacheDirectory));
    int removed = 0;
    for (const QString& name : dir.entryList({QStringLiteral("*.ktx2")}, QDir::Files))
        removed += dir.remove(name) ? 1 : 0;
    log_.append(LogDock::Level::Info,
                tr("Texture cache cleared: %1 files deleted from %2; the next load compresses "
                   "again.")
                    .arg(removed)
                    .arg(QDir::toNativeSeparators(dir.absolutePath())));
    return removed;
}

void LoadController::recompressTexture(int texture) {
    const SceneSession* session = context_.session();
    const PreparedTextures prepared = session ? session->textures : nullptr;
    if (!prepared || texture < 0) return;
    int removed = 0;
    for (const tex::PreparedTexture& t : prepared->textures)
        if (!t.cache_file.empty() &&
            std::find(t.textures.begin(), t.textures.end(), texture) != t.textures.end())
            removed += QFile::remove(QString::fromStdString(t.cache_file.string())) ? 1 : 0;
    log_.append(LogDock::Level::Info,
                tr("Texture %1: %2 cache files deleted; reloading to compress it again.")
                    .arg(texture)
                    .arg(removed));
    reloadScene();
}

} // namespace sherpa::editor
