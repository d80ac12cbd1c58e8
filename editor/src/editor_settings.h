#pragma once
// Everything the editor remembers between runs, in one QSettings file: recent
// files, window and dock layout, last debug view, cache directory, texture
// quality, checker density, reload policy, language. One table (setting::) names
// each setting once: its key, its type and what it reads as while nothing is stored.
#include <QByteArray>
#include <QSettings>
#include <QString>
#include <QStringList>

#include <type_traits>
#include <utility>

namespace sherpa::editor {

// One stored setting: where it lives in the file and its value while none is stored,
// a constant or, where it depends on the machine, a function asked at each read.
template <typename T> struct Setting {
    Setting(const char* k, T value)
        : key(QString::fromLatin1(k)), fallback_value(std::move(value)) {}
    Setting(const char* k, T (*from_environment)())
        : key(QString::fromLatin1(k)), fallback_from(from_environment) {}
    T fallback() const { return fallback_from ? fallback_from() : fallback_value; }

    QString key;
    T fallback_value{};
    T (*fallback_from)() = nullptr;
};

// The engine's texture cache directory, so the editor and sherpa-cli share one cache.
QString default_cache_directory();

namespace setting {
// Newest first; builtin specs are not files and never listed (EditorSettings::addRecentFile).
inline const Setting<QStringList> kRecentFiles{"recentFiles", QStringList()};
inline const Setting<QByteArray> kGeometry{"window/geometry", QByteArray()};
inline const Setting<QByteArray> kWindowState{"window/state", QByteArray()};
inline const Setting<QString> kLastView{"viewport/lastView", QStringLiteral("lit")};
inline const Setting<QString> kCacheDirectory{"textures/cacheDirectory", &default_cache_directory};
// "fast" | "balanced" | "best"
inline const Setting<QString> kTextureQuality{"textures/quality", QStringLiteral("balanced")};
// Checks per UV unit of the uv checker views (View › Checker Density): fine enough for
// texture atlases.
inline const Setting<int> kCheckerDensity{"viewport/checkerDensity", 32};
// The open file changed on disk: reload it at once (true) or offer to (false: ask).
inline const Setting<bool> kReloadAutomatically{"files/reloadAutomatically", false};
// "" = follow the system locale.
inline const Setting<QString> kLanguage{"ui/language", QString()};
} // namespace setting

class EditorSettings {
public:
    static constexpr int kMaxRecent = 10;

    template <typename T> T get(const Setting<T>& s) const {
        return settings_.value(s.key, QVariant::fromValue(s.fallback())).template value<T>();
    }
    template <typename T> void set(const Setting<T>& s, const std::type_identity_t<T>& value) {
        settings_.setValue(s.key, QVariant::fromValue(value));
    }
    // Back to the fallback.
    template <typename T> void reset(const Setting<T>& s) { settings_.remove(s.key); }
    // Moves `spec` to the front of setting::kRecentFiles, at most kMaxRecent (builtin
    // specs are not "files" and are skipped).
    void addRecentFile(const QString& spec);

private:
    mutable QSettings settings_;
};

} // namespace sherpa::editor
