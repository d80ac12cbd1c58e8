// The editor's state without widgets, checked on its own: the settings table.
#include <QSet>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

#include <utility>

#include "editor_settings.h"

using namespace sherpa;
using namespace sherpa::editor;

class StateTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void settingsReadTheirFallbackUntilSet();
    void settingsKeepTheirKeysAndTypes();
    void recentFilesAreNewestFirstWithoutRepeats();

private:
    QTemporaryDir settings_dir_;
};

void StateTests::initTestCase() {
    QVERIFY(settings_dir_.isValid());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings_dir_.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings_dir_.path());
    QSettings().clear();
    qputenv("XDG_CACHE_HOME", (settings_dir_.path() + QStringLiteral("/cache")).toUtf8());
}

void StateTests::settingsReadTheirFallbackUntilSet() {
    EditorSettings s;
    QCOMPARE(s.get(setting::kLastView), QStringLiteral("lit"));
    QCOMPARE(s.get(setting::kTextureQuality), QStringLiteral("balanced"));
    QCOMPARE(s.get(setting::kCheckerDensity), 32);
    QCOMPARE(s.get(setting::kReloadAutomatically), false);
    QCOMPARE(s.get(setting::kLanguage), QString());
    QVERIFY(s.get(setting::kRecentFiles).isEmpty());
    QVERIFY(s.get(setting::kGeometry).isEmpty());
    // A fallback from the environment is asked at each read (the XDG rule, written out).
    QCOMPARE(s.get(setting::kCacheDirectory), settings_dir_.path() + "/cache/sherpa/textures");
    qputenv("XDG_CACHE_HOME", (settings_dir_.path() + QStringLiteral("/other")).toUtf8());
    QCOMPARE(s.get(setting::kCacheDirectory), settings_dir_.path() + "/other/sherpa/textures");
    qputenv("XDG_CACHE_HOME", (settings_dir_.path() + QStringLiteral("/cache")).toUtf8());

    s.set(setting::kCheckerDensity, 8);
    s.set(setting::kReloadAutomatically, true);
    s.set(setting::kLastView, QStringLiteral("normal"));
    s.set(setting::kCacheDirectory, QStringLiteral("/tmp/x"));
    {
        const EditorSettings again; // another object reads what this one stored
        QCOMPARE(again.get(setting::kCheckerDensity), 8);
        QCOMPARE(again.get(setting::kReloadAutomatically), true);
        QCOMPARE(again.get(setting::kLastView), QStringLiteral("normal"));
        QCOMPARE(again.get(setting::kCacheDirectory), QStringLiteral("/tmp/x"));
    }
    s.reset(setting::kCheckerDensity);
    s.reset(setting::kReloadAutomatically);
    s.reset(setting::kLastView);
    s.reset(setting::kCacheDirectory);
    QCOMPARE(s.get(setting::kCheckerDensity), 32);
    QCOMPARE(s.get(setting::kReloadAutomatically), false);
    QCOMPARE(s.get(setting::kLastView), QStringLiteral("lit"));
    QCOMPARE(s.get(setting::kCacheDirectory), settings_dir_.path() + "/cache/sherpa/textures");
}

// The keys are those the settings files of earlier versions hold, and values stored as
// text there (as QSettings' INI files hold every scalar) read back as their type.
void StateTests::settingsKeepTheirKeysAndTypes() {
    const std::pair<QString, QString> keys[] = {
        {setting::kRecentFiles.key, QStringLiteral("recentFiles")},
        {setting::kGeometry.key, QStringLiteral("window/geometry")},
        {setting::kWindowState.key, QStringLiteral("window/state")},
        {setting::kLastView.key, QStringLiteral("viewport/lastView")},
        {setting::kCacheDirectory.key, QStringLiteral("textures/cacheDirectory")},
        {setting::kTextureQuality.key, QStringLiteral("textures/quality")},
        {setting::kCheckerDensity.key, QStringLiteral("viewport/checkerDensity")},
        {setting::kReloadAutomatically.key, QStringLiteral("files/reloadAutomatically")},
        {setting::kLanguage.key, QStringLiteral("ui/language")}};
    QSet<QString> seen;
    for (const auto& [key, expected] : keys) {
        QCOMPARE(key, expected);
        QVERIFY2(!seen.contains(key), qPrintable(key)); // one setting per key
        seen.insert(key);
    }
    QSettings raw;
    raw.setValue(QStringLiteral("viewport/checkerDensity"), QStringLiteral("64"));
    raw.setValue(QStringLiteral("files/reloadAutomatically"), QStringLiteral("true"));
    raw.setValue(QStringLiteral("recentFiles"), QStringLiteral("/one.gltf")); // a list of one
    raw.sync();
    EditorSettings s;
    QCOMPARE(s.get(setting::kCheckerDensity), 64);
    QCOMPARE(s.get(setting::kReloadAutomatically), true);
    QCOMPARE(s.get(setting::kRecentFiles), QStringList{QStringLiteral("/one.gltf")});
    raw.setValue(QStringLiteral("files/reloadAutomatically"), QStringLiteral("false"));
    QCOMPARE(s.get(setting::kReloadAutomatically), false);
    s.reset(setting::kCheckerDensity);
    s.reset(setting::kReloadAutomatically);
    s.reset(setting::kRecentFiles);
}

void StateTests::recentFilesAreNewestFirstWithoutRepeats() {
    EditorSettings s;
    s.addRecentFile(QStringLiteral("/a.gltf"));
    s.addRecentFile(QStringLiteral("builtin:default")); // not a file
    s.addRecentFile(QStringLiteral("/b.glb"));
    s.addRecentFile(QStringLiteral("/a.gltf")); // to the front, once
    QCOMPARE(s.get(setting::kRecentFiles),
             (QStringList{QStringLiteral("/a.gltf"), QStringLiteral("/b.glb")}));
    for (int i = 0; i < 2 * EditorSettings::kMaxRecent; ++i)
        s.addRecentFile(QStringLiteral("/%1.gltf").arg(i));
    const QStringList recent = s.get(setting::kRecentFiles);
    QCOMPARE(recent.size(), EditorSettings::kMaxRecent);
    QCOMPARE(recent.front(), QStringLiteral("/%1.gltf").arg(2 * EditorSettings::kMaxRecent - 1));
    s.reset(setting::kRecentFiles);
    QVERIFY(s.get(setting::kRecentFiles).isEmpty());
}

QTEST_GUILESS_MAIN(StateTests)
#include "state_tests.moc"
