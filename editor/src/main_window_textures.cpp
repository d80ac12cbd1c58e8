// The texture dock's cache actions. The engine's cache has no per-entry API: its
// entries are KTX2 files named by content hash in the cache directory, so both
// actions delete files and the next preparation makes them again.
#include "main_window.h"

#include <QDir>
#include <QFile>

#include <sherpa/texture/texture_pipeline.h>

#include "gpu_viewport.h"
#include "log_dock.h"

namespace sherpa::editor {

int MainWindow::clearTextureCache() {
    QDir dir(settings_.cacheDirectory());
    int removed = 0;
    for (const QString& name : dir.entryList({QStringLiteral("*.ktx2")}, QDir::Files))
        removed += dir.remove(name) ? 1 : 0;
    log_->append(LogDock::Level::Info,
                 tr("Texture cache cleared: %1 files deleted from %2; the next load compresses "
                    "again.")
                     .arg(removed)
                     .arg(QDir::toNativeSeparators(dir.absolutePath())));
    return removed;
}

void MainWindow::recompressTexture(int texture) {
    const SceneSession* session = context_.session();
    const PreparedTextures prepared = session ? session->textures : nullptr;
    if (!prepared || texture < 0) return;
    int removed = 0;
    for (const tex::PreparedTexture& t : prepared->textures)
        if (!t.cache_file.empty() &&
            std::find(t.textures.begin(), t.textures.end(), texture) != t.textures.end())
            removed += QFile::remove(QString::fromStdString(t.cache_file.string())) ? 1 : 0;
    log_->append(LogDock::Level::Info,
                 tr("Texture %1: %2 cache files deleted; reloading to compress it again.")
                     .arg(texture)
                     .arg(removed));
    reloadScene();
}

void MainWindow::logTextureMessages() {
    const SceneSession* session = context_.session();
    const PreparedTextures prepared = session ? session->textures : nullptr;
    // uploadScene() runs again for the same set (settings toggles): say it once.
    if (!prepared || prepared == logged_textures_.lock()) return;
    logged_textures_ = prepared;
    for (const std::string& w : prepared->warnings)
        log_->append(LogDock::Level::Warning, QString::fromStdString(w));
    for (const std::string& n : prepared->notices)
        log_->append(LogDock::Level::Info, QString::fromStdString(n));
}

} // namespace sherpa::editor
