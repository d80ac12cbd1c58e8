#pragma once
// Everything the editor remembers between runs, in one QSettings file: recent
// files, window and dock layout, last debug view, cache directory, texture
// quality, language.
#include <QByteArray>
#include <QSettings>
#include <QString>
#include <QStringList>

namespace sherpa::editor {

class EditorSettings {
public:
    static constexpr int kMaxRecent = 10;

    QStringList recentFiles() const;
    // Moves `spec` to the front (builtin specs are not "files" and are skipped).
    void addRecentFile(const QString& spec);
    void clearRecentFiles();

    QByteArray geometry() const;
    QByteArray windowState() const;
    void saveLayout(const QByteArray& geometry, const QByteArray& state);

    QString lastView() const;
    void setLastView(const QString& view);
    QString cacheDirectory() const; // default: tex::default_cache_dir_from_environment()
    void setCacheDirectory(const QString& dir);
    QString textureQuality() const; // "fast" | "balanced" | "best"
    void setTextureQuality(const QString& quality);
    // Checks per UV unit of the uv checker views (View › Checker Density).
    int checkerDensity() const; // default 32: fine enough for texture atlases
    void setCheckerDensity(int checks);
    // The open file changed on disk: reload it at once (true) or offer to (false).
    bool reloadAutomatically() const; // default false: ask
    void setReloadAutomatically(bool automatic);
    QString language() const; // "" = follow the system locale
    void setLanguage(const QString& code);

private:
    mutable QSettings settings_;
};

} // namespace sherpa::editor
