#pragma once
// Paths of the shared sample models for the editor tests.
#include <QDir>
#include <QString>
#include <QStringList>

namespace sherpa::editor::test {

inline QString asset(const QString& name) {
    return QStringLiteral(SHERPA_ASSETS_DIR "/gltf/%1/glTF/%1.gltf").arg(name);
}

inline QStringList all_assets() {
    QStringList out;
    const QDir dir(QStringLiteral(SHERPA_ASSETS_DIR "/gltf"));
    for (const QString& name : dir.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name))
        if (QFile::exists(asset(name))) out << name;
    return out;
}

} // namespace sherpa::editor::test
