// The editor's state without widgets, each piece on its own: the settings table, the
// timeline's playback (against the engine's evaluate_pose), the culling history and
// pass pacing, the comparison's rules.
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include <sherpa/scene/scene_loader.h>

#include "compare_state.h"
#include "cull_history.h"
#include "culling_monitor.h"
#include "editor_settings.h"
#include "motion_playback.h"
#include "orbit_camera.h"
#include "test_assets.h"
#include "view_catalog.h"

namespace {} // namespace

using namespace sherpa;
using namespace sherpa::editor;

class StateTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void settingsReadTheirFallbackUntilSet();
    void settingsKeepTheirKeysAndTypes();
    void recentFilesAreNewestFirstWithoutRepeats();
    void playbackSelectsPlaysAndPoses();
    void cullHistoryKeepsAnswersForTheirPass();
    void passPacingCoalescesExpensivePasses();
    void compareStateRules();

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

void StateTests::playbackSelectsPlaysAndPoses() {
    scene::LoadResult loaded =
        scene::load_scene(test::asset(QStringLiteral("BoxAnimated")).toStdString());
    QVERIFY(loaded);
    const std::shared_ptr<const scene::Scene> shared(std::move(loaded.scene));
    const scene::Scene& scene = *shared;
    QVERIFY(!scene.animations.empty());
    const scene::Animation& anim = scene.animations[0];
    Playback p;
    QVERIFY(p.updatePose({})); // nothing yet: made once, null
    QVERIFY(!p.pose());
    QVERIFY(!p.updatePose({}));
    p.setScene(shared);
    QCOMPARE(p.animation(), -1);
    QVERIFY(!p.playable());
    p.selectAnimation(int(scene.animations.size())); // no such animation
    QCOMPARE(p.animation(), -1);
    p.selectAnimation(0);
    QCOMPARE(p.animation(), 0);
    QVERIFY(p.playable());
    QCOMPARE(p.clock().start, double(anim.start));
    QCOMPARE(p.clock().time, double(anim.start));
    QVERIFY(!p.clock().playing);
    const std::vector<double> ticks = p.keyFractions();
    QCOMPARE(ticks.size(), key_times(anim).size());
    QCOMPARE(ticks.front(), 0.0);
    QCOMPARE(ticks.back(), 1.0);
    QVERIFY(std::is_sorted(ticks.begin(), ticks.end()));
    // The pose is the engine's, made again only when time, animation or overrides change.
    QVERIFY(p.updatePose({}));
    const std::shared_ptr<const scene::Pose> first = p.pose();
    QVERIFY(first);
    QVERIFY(!p.updatePose({}));
    QCOMPARE(p.pose(), first);
    const double t = anim.start + 0.4 * (anim.end - anim.start);
    p.clock().scrub(t);
    QVERIFY(p.updatePose({}));
    const scene::Pose expected = scene::evaluate_pose(scene, 0, t);
    const std::uint32_t node = anim.channels[0].node;
    QVERIFY(p.pose()->world[node] == expected.world[node]);
    // The clock's rules: clamped scrubs, NaN ignored, a finished run plays from the start.
    p.clock().scrub(std::nan(""));
    QCOMPARE(p.clock().time, t);
    p.clock().scrub(anim.end + 5.0);
    QCOMPARE(p.clock().time, double(anim.end));
    p.clock().loop = false;
    p.clock().play(true);
    QCOMPARE(p.clock().time, double(anim.start));
    QVERIFY(p.clock().playing);
    QVERIFY(p.clock().advance(10.0 * (anim.end - anim.start)));
    QVERIFY(!p.clock().playing); // stopped on the last key
    QCOMPARE(p.clock().time, double(anim.end));
    p.clock().loop = true;
    p.clock().play(true); // looping: from where it is
    QCOMPARE(p.clock().time, double(anim.end));
    p.setScene(nullptr);
    QCOMPARE(p.animation(), -1);
    QVERIFY(p.updatePose({}));
    QVERIFY(!p.pose());
}

void StateTests::cullHistoryKeepsAnswersForTheirPass() {
    CullHistory h;
    QVERIFY(!h.latest());
    CullSample s;
    s.cpu.total = 10;
    s.cpu.visible = 4;
    s.cpu.culled = 6;
    const std::uint64_t a = h.push(s);
    const std::uint64_t b = h.push(s);
    QVERIFY(b > a);
    QVERIFY(!h.answer(a, GpuCullResult{1.0, 4, 0})); // a newer pass asked again
    QCOMPARE(h.latest()->gpu_visible, std::int64_t{-1});
    QVERIFY(h.answer(b, GpuCullResult{1.5, 5, 1}));
    QCOMPARE(h.latest()->gpu_ms, 1.5);
    QCOMPARE(h.latest()->gpu_visible, std::int64_t{5});
    QCOMPARE(h.latest()->cpu_gpu_differences, std::int64_t{1});
    QCOMPARE(h.latest()->cpu.cpu_gpu_differences, std::int64_t{1});
    h.clear();
    QCOMPARE(h.size(), std::size_t{0});
    QVERIFY(!h.answer(b, GpuCullResult{})); // another scene
    const std::uint64_t c = h.push(s);
    QVERIFY(c > b); // serials never repeat
    // Full: the oldest go; the chart's series follow the ring.
    for (std::size_t i = 0; i < CullHistory::kCapacity + 9; ++i) {
        s.cpu.total = i + 1;
        s.cpu.visible = i;
        s.cpu.culled = 1;
        h.push(s);
    }
    QCOMPARE(h.size(), CullHistory::kCapacity);
    QCOMPARE(h[0].cpu.visible, std::uint64_t{9});
    const CullChartSeries series = cull_chart_series(h);
    QCOMPARE(std::size_t(series.visible.size()), CullHistory::kCapacity);
    QCOMPARE(series.visible.front(), QPointF(0.0, 9.0));
    QCOMPARE(series.culled.back(), QPointF(double(CullHistory::kCapacity - 1), 1.0));
    QCOMPARE(series.top, double(CullHistory::kCapacity + 9));
    QCOMPARE(cull_chart_series(CullHistory{}).top, 1.0);
}

void StateTests::passPacingCoalescesExpensivePasses() {
    int runs = 0;
    PassPacing pacing([&runs] { ++runs; });
    pacing.request(); // no pass measured yet: cheap
    QCOMPARE(runs, 1);
    pacing.ran(1.0);
    pacing.request();
    QCOMPARE(runs, 2);
    pacing.ran(30.0); // over the 4 ms default: coalesced
    QCOMPARE(pacing.lastPassMs(), 30.0);
    for (int i = 0; i < 10; ++i) pacing.request();
    QCOMPARE(runs, 2);
    QVERIFY(pacing.deferred());
    QTRY_COMPARE(runs, 3); // after twice the last pass's cost, once
    QVERIFY(!pacing.deferred());
    pacing.request();
    pacing.flush();
    QCOMPARE(runs, 4);
    QVERIFY(!pacing.deferred());
    pacing.flush(); // nothing waits: nothing runs
    QCOMPARE(runs, 4);
    pacing.setCoalesceAboveMs(100.0);
    pacing.request();
    QCOMPARE(runs, 5);
    pacing.requestWithin(10'000);
    pacing.cancel(); // a pass ran meanwhile
    QVERIFY(!pacing.deferred());
    QCOMPARE(runs, 5);
}

void StateTests::compareStateRules() {
    CompareState state;
    QSignalSpy changed(&state, &CompareState::changed);
    QSignalSpy offer(&state, &CompareState::offerChanged);
    QCOMPARE(state.comparison().mode, ViewportMode::Raster);
    // Choosing side B starts a comparison; in one it keeps the mode.
    state.chooseSide(SideB::RayTraced);
    QCOMPARE(state.comparison().mode, ViewportMode::Split);
    QCOMPARE(changed.count(), 1);
    state.setMode(ViewportMode::Difference);
    const auto uv0 = ViewCatalog::viewId(QStringLiteral("uv0"));
    QVERIFY(uv0);
    state.chooseSide(SideB::OtherView, *uv0);
    QCOMPARE(state.comparison().mode, ViewportMode::Difference);
    QCOMPARE(state.comparison().view, *uv0);
    // setSide alone does not start one.
    state.setMode(ViewportMode::Raster);
    state.setSide(SideB::RayTraced);
    QCOMPARE(state.comparison().mode, ViewportMode::Raster);
    changed.clear();
    // Without rays, side B falls back to the normal view; only the offer changed.
    state.setRayTracing(false);
    QCOMPARE(state.comparison().side, SideB::OtherView);
    QCOMPARE(state.comparison().view, *ViewCatalog::viewId(QStringLiteral("normal")));
    QVERIFY(!state.offer().ray_tracing);
    QCOMPARE(changed.count(), 0);
    QCOMPARE(offer.count(), 1);
    state.setOtherFile(QStringLiteral("b.gltf"), scene::TangentMethod::Lengyel);
    QCOMPARE(state.offer().file, QStringLiteral("b.gltf"));
    QVERIFY(state.offer().tangents == scene::TangentMethod::Lengyel);
    state.setOtherFile(QString(), scene::TangentMethod::Lengyel); // no file: no tangents
    QVERIFY(!state.offer().tangents);
    QCOMPARE(changed.count(), 0);
    state.setDivider(0.3f);
    state.setHeatScale(0.0f);
    state.setThreshold(4.0f / 255.0f);
    QCOMPARE(changed.count(), 3);
    QCOMPARE(state.comparison().divider, 0.3f);
    QCOMPARE(state.comparison().heat_max, 0.0f);
    QCOMPARE(state.comparison().threshold, 4.0f / 255.0f);
}

QTEST_GUILESS_MAIN(StateTests)
#include "state_tests.moc"
