#pragma once
// Opening, reloading and closing scenes: File › Open, Open Recent, Built-in Scenes,
// Reload and Close, drops and the command line all end in openScene(). It owns the
// background load (SceneLoadJob), its progress bar and Cancel button, the load's
// errors (log, status bar, a non-modal box), the texture cache settings the loader
// prepares textures with, and the texture dock's cache actions.
#include <QObject>
#include <QString>

#include <optional>

#include <sherpa/texture/texture_pipeline.h>
#include <sherpa/texture/texture_target.h>

#include "scene_load_job.h"
#include "scene_session.h"

class QAction;
class QMainWindow;
class QMenu;
class QProgressBar;
class QPushButton;

namespace sherpa::editor {

class EditorContext;
class EditorSettings;
class LogDock;
class TextureDock;
class ViewportWindow;
struct WindowActions;

class LoadController : public QObject {
    Q_OBJECT
public:
    // `device_pending`: a render thread is making the device, whose TextureTarget the
    // textures are prepared for: loads wait for deviceKnown(). `progress` and `cancel`
    // sit in `window`'s status bar.
    LoadController(EditorContext& context, EditorSettings& settings, LogDock& log,
                   ViewportWindow& viewport, TextureDock& textures, const WindowActions& actions,
                   QProgressBar& progress, QPushButton& cancel, QMainWindow& window,
                   bool device_pending);

    // Starts loading; the current scene stays until the new one is ready.
    void openScene(const QString& spec);
    // The open file again; `keep_camera`: the view stays (a reload after a change).
    void reloadScene(bool keep_camera = false);
    void closeScene();
    // Cancels the load in progress (its result is discarded); the scene shown stays.
    void cancelLoad();
    // The texture dock's actions: delete every KTX2 file of the cache directory; delete
    // one texture's cache files and reload, so it is compressed again.
    int clearTextureCache();
    void recompressTexture(int texture);
    // The texture cache settings of now (textures are prepared with them on the
    // loader thread) and the device's target, once known.
    tex::PipelineOptions textureOptions() const;
    const std::optional<tex::TextureTarget>& textureTarget() const { return texture_target_; }
    // The render thread made its device (`target`) or failed to (nullopt): open the
    // scene asked for meanwhile.
    void deviceKnown(const std::optional<tex::TextureTarget>& target);

Q_SIGNALS:
    // After the swap (EditorContext::sceneReady) and the camera framing.
    void sceneLoaded(const QString& spec, double ms);
    void loadFailed(const QString& spec, const QString& error);
    void loadCanceled(const QString& spec);

private:
    void connectActions(const WindowActions& actions, TextureDock& textures);
    void onLoaded(SharedSession session);
    void onLoadFailed(const QString& spec, const QString& error);
    void onProgress(LoadStep step, int done, int total);
    void rebuildRecentMenu(QMenu& menu, QAction& clear);
    void openFileDialog();

    EditorContext& context_;
    EditorSettings& settings_;
    LogDock& log_;
    ViewportWindow& viewport_;
    QProgressBar& progress_;
    QPushButton& cancel_;
    QMainWindow& window_;
    SceneLoadJob loader_;
    std::optional<tex::TextureTarget> texture_target_; // the device's, once it is known
    bool device_pending_ = false; // the render thread is still making the device
    QString pending_open_;        // asked for while the device was pending
    bool keep_camera_ = false;    // the next load is this file again: keep the view
};

} // namespace sherpa::editor
