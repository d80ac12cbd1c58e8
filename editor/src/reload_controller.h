#pragma once
// Reload on change: the open file, its buffers and images are watched (SceneFileWatch);
// a change reloads the scene at once or offers to, as the setting (Settings › When the
// File Changes) says. A reload of the same file keeps the camera: a user with an
// exporter open beside the inspector looks at one spot. The window gives it the
// Settings menu and what a reload does; it owns the watch, its submenu and the offer.
#include <QObject>
#include <QPointer>
#include <QStringList>

#include <functional>

class QActionGroup;
class QMenu;
class QMessageBox;
class QWidget;

namespace sherpa::editor {

class EditorContext;
class EditorSettings;
class LogDock;
class SceneFileWatch;

class ReloadController : public QObject {
    Q_OBJECT
public:
    // `reload` reloads the open scene keeping its camera; `window` parents the offer.
    ReloadController(EditorContext& context, EditorSettings& settings, LogDock& log,
                     QMenu& settings_menu, std::function<void()> reload, QWidget* window);

    // When the open file, its buffers or images change on disk: reload at once
    // (true) or offer to (false, the default); remembered.
    void setReloadAutomatically(bool automatic);
    bool reloadAutomatically() const;
    // The files watched for that.
    QStringList watchedFiles() const;
    void retranslate();

private:
    void onFilesChanged(const QStringList& files);

    EditorContext& context_;
    EditorSettings& settings_;
    LogDock& log_;
    std::function<void()> reload_;
    QWidget* window_;
    SceneFileWatch* file_watch_;
    QMenu* menu_;
    QActionGroup* group_;         // Settings › When the File Changes
    QPointer<QMessageBox> offer_; // the open offer to reload, if any
};

} // namespace sherpa::editor
