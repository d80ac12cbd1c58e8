#pragma once
// Reload on change: the open scene's files (the glTF or GLB, its external buffers
// and images) watched on disk. Exporters write a file in several steps, often by
// writing a new file and renaming it over the old one: changes are gathered for a
// moment and announced once, and a replaced file is watched again under its name.
#include <QFileSystemWatcher>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace sherpa::scene {
struct Scene;
} // namespace sherpa::scene

namespace sherpa::editor {

// The files a scene was read from: `path` itself, the buffers its JSON names by
// URI (data URIs excluded; a GLB's JSON chunk is read), and its external images.
// Absolute, existing or not (a missing image appears when the exporter writes it).
QStringList scene_files(const QString& path, const scene::Scene& scene);

class SceneFileWatch : public QObject {
    Q_OBJECT
public:
    // Changes closer together than this are one change.
    static constexpr int kSettleMs = 300;
    explicit SceneFileWatch(QObject* parent = nullptr);
    // Watches `files` instead of what was watched before (empty: nothing).
    void watch(const QStringList& files);
    QStringList watched() const { return files_; }

Q_SIGNALS:
    // Some of the watched files changed (or were removed or replaced), once per burst.
    void changed(const QStringList& files);

private:
    void onChanged(const QString& path);

    QFileSystemWatcher watcher_;
    QStringList files_;
    QStringList pending_; // changed since the burst began
    QTimer settle_;
};

} // namespace sherpa::editor
