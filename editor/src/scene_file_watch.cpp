#include "scene_file_watch.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUrl>
#include <QtEndian>

#include <sherpa/scene/image_sources.h>
#include <sherpa/scene/scene.h>

namespace sherpa::editor {

namespace {

// The glTF JSON of a .gltf, or a .glb's first chunk (JSON by the GLB spec).
QByteArray gltf_json(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QByteArray head = f.peek(20);
    if (head.size() >= 20 && head.startsWith("glTF")) {
        const quint32 length = qFromLittleEndian<quint32>(head.constData() + 12);
        const quint32 type = qFromLittleEndian<quint32>(head.constData() + 16);
        if (type != 0x4E4F534Au || length > quint32(f.size() - 20)) return {}; // "JSON"
        f.seek(20);
        return f.read(length);
    }
    return f.readAll();
}

} // namespace

QStringList scene_files(const QString& path, const scene::Scene& scene) {
    QStringList files;
    const QFileInfo info(path);
    if (!info.exists()) return files; // builtin:..., or gone
    files << info.absoluteFilePath();
    const QDir dir = info.absoluteDir();
    const QJsonArray buffers = QJsonDocument::fromJson(gltf_json(path))
                                   .object()
                                   .value(QStringLiteral("buffers"))
                                   .toArray();
    for (const QJsonValue& b : buffers) {
        const QString uri = b.toObject().value(QStringLiteral("uri")).toString();
        if (uri.isEmpty() || uri.startsWith(QLatin1String("data:"))) continue;
        files << QDir::cleanPath(dir.absoluteFilePath(QUrl::fromPercentEncoding(uri.toUtf8())));
    }
    for (const scene::ImageRecord& image : scene.images)
        if (const auto file = scene::image_file_path(scene, image); !file.empty())
            files << QDir::cleanPath(dir.absoluteFilePath(QString::fromStdString(file.string())));
    files.removeDuplicates();
    return files;
}

SceneFileWatch::SceneFileWatch(QObject* parent) : QObject(parent) {
    settle_.setSingleShot(true);
    settle_.setInterval(kSettleMs);
    connect(&watcher_, &QFileSystemWatcher::fileChanged, this, &SceneFileWatch::onChanged);
    // A file missing when watching began (an image not exported yet) shows up in its folder.
    connect(&watcher_, &QFileSystemWatcher::directoryChanged, this, [this] {
        for (const QString& f : files_)
            if (!watcher_.files().contains(f) && QFileInfo::exists(f)) onChanged(f);
    });
    connect(&settle_, &QTimer::timeout, this, [this] {
        // Renamed over or rewritten: watch what has the name now.
        for (const QString& f : pending_)
            if (!watcher_.files().contains(f) && QFileInfo::exists(f)) watcher_.addPath(f);
        Q_EMIT changed(std::exchange(pending_, {}));
    });
}

void SceneFileWatch::watch(const QStringList& files) {
    if (!watcher_.files().isEmpty()) watcher_.removePaths(watcher_.files());
    if (!watcher_.directories().isEmpty()) watcher_.removePaths(watcher_.directories());
    settle_.stop();
    pending_.clear();
    files_ = files;
    QStringList dirs;
    for (const QString& f : files) {
        if (QFileInfo::exists(f)) watcher_.addPath(f);
        dirs << QFileInfo(f).absolutePath();
    }
    dirs.removeDuplicates();
    if (!dirs.isEmpty()) watcher_.addPaths(dirs);
}

void SceneFileWatch::onChanged(const QString& path) {
    if (!pending_.contains(path)) pending_ << path;
    settle_.start(); // restarts: the burst goes on
}

} // namespace sherpa::editor
