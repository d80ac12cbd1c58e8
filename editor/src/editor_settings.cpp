#include "editor_settings.h"

#include <sherpa/texture/texture_cache.h>

namespace sherpa::editor {

namespace {
const QString kRecent = QStringLiteral("recentFiles");
const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");
const QString kView = QStringLiteral("viewport/lastView");
const QString kCacheDir = QStringLiteral("textures/cacheDirectory");
const QString kQuality = QStringLiteral("textures/quality");
const QString kLanguage = QStringLiteral("ui/language");
const QString kCheckerDensity = QStringLiteral("viewport/checkerDensity");
const QString kReloadAutomatically = QStringLiteral("files/reloadAutomatically");
} // namespace

QStringList EditorSettings::recentFiles() const {
    return settings_.value(kRecent).toStringList();
}

void EditorSettings::addRecentFile(const QString& spec) {
    if (spec.startsWith(QLatin1String("builtin:"))) return;
    QStringList list = recentFiles();
    list.removeAll(spec);
    list.prepend(spec);
    while (list.size() > kMaxRecent) list.removeLast();
    settings_.setValue(kRecent, list);
}

void EditorSettings::clearRecentFiles() {
    settings_.remove(kRecent);
}

QByteArray EditorSettings::geometry() const {
    return settings_.value(kGeometry).toByteArray();
}

QByteArray EditorSettings::windowState() const {
    return settings_.value(kState).toByteArray();
}

void EditorSettings::saveLayout(const QByteArray& geometry, const QByteArray& state) {
    settings_.setValue(kGeometry, geometry);
    settings_.setValue(kState, state);
}

QString EditorSettings::lastView() const {
    return settings_.value(kView, QStringLiteral("lit")).toString();
}

void EditorSettings::setLastView(const QString& view) {
    settings_.setValue(kView, view);
}

QString EditorSettings::cacheDirectory() const {
    // The engine's directory, so the editor and sherpa-cli share one cache.
    const QString fallback =
        QString::fromStdString(sherpa::tex::default_cache_dir_from_environment().string());
    return settings_.value(kCacheDir, fallback).toString();
}

void EditorSettings::setCacheDirectory(const QString& dir) {
    settings_.setValue(kCacheDir, dir);
}

QString EditorSettings::textureQuality() const {
    return settings_.value(kQuality, QStringLiteral("balanced")).toString();
}

void EditorSettings::setTextureQuality(const QString& quality) {
    settings_.setValue(kQuality, quality);
}

int EditorSettings::checkerDensity() const {
    return settings_.value(kCheckerDensity, 32).toInt();
}

void EditorSettings::setCheckerDensity(int checks) {
    settings_.setValue(kCheckerDensity, checks);
}

bool EditorSettings::reloadAutomatically() const {
    return settings_.value(kReloadAutomatically, false).toBool();
}

void EditorSettings::setReloadAutomatically(bool automatic) {
    settings_.setValue(kReloadAutomatically, automatic);
}

QString EditorSettings::language() const {
    return settings_.value(kLanguage).toString();
}

void EditorSettings::setLanguage(const QString& code) {
    settings_.setValue(kLanguage, code);
}

} // namespace sherpa::editor
