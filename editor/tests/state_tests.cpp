// The editor's state without widgets, each piece on its own: the settings table, the
// camera's pose and input mapping (against the engine's CameraSpec projection and
// camera string), the timeline's playback (against the engine's evaluate_pose), the
// culling history and pass pacing, the comparison's rules.
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

namespace {
// Where `p` lands in normalised device coordinates through `spec`.
glm::vec2 ndc_of(const sherpa::scene::CameraSpec& spec, glm::vec3 p) {
    const glm::vec4 clip = spec.view_projection() * glm::vec4(p, 1.0f);
    return glm::vec2(clip) / clip.w;
}
bool near(glm::vec3 a, glm::vec3 b, float eps = 1e-4f) {
    return glm::length(a - b) <= eps * std::max(1.0f, glm::length(b));
}
} // namespace

using namespace sherpa;
using namespace sherpa::editor;

class StateTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void settingsReadTheirFallbackUntilSet();
    void settingsKeepTheirKeysAndTypes();
    void recentFilesAreNewestFirstWithoutRepeats();
    void poseRaysAgreeWithTheProjection();
    void poseReadsBackFromItsStringAndSpec();
    void poseTakesAGltfCamera();
    void cameraInputMovesThePose();
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

void StateTests::poseRaysAgreeWithTheProjection() {
    OrbitPose pose;
    pose.yaw = 0.0f;
    pose.pitch = 0.0f;
    QVERIFY(near(pose.forward(), glm::vec3(0, 0, -1))); // glTF's default camera
    pose.target = {1.0f, 2.0f, -3.0f};
    pose.yaw = -0.7f;
    pose.pitch = 0.4f;
    pose.distance = 6.0f;
    pose.aspect = 1.5f;
    QVERIFY(near(pose.eye(), pose.target - pose.forward() * pose.distance));
    QVERIFY(glm::length(ndc_of(pose.spec(), pose.target)) < 1e-5f); // the target is centred
    glm::vec3 right, up;
    pose.axes(right, up);
    QVERIFY(std::abs(glm::dot(right, pose.forward())) < 1e-6f);
    QVERIFY(std::abs(glm::dot(up, pose.forward())) < 1e-6f);
    QVERIFY(up.y > 0.0f);
    // A ray through a point of the image hits what the engine's projection puts there.
    for (const glm::vec2 ndc : {glm::vec2(0.0f), glm::vec2(0.9f, -0.6f), glm::vec2(-1.0f, 1.0f)}) {
        glm::vec3 origin, direction;
        pose.ray(ndc, origin, direction);
        QVERIFY(near(origin, pose.eye()));
        QCOMPARE(glm::length(direction), 1.0f);
        const glm::vec2 back = ndc_of(pose.spec(), origin + direction * 4.0f);
        QVERIFY2(
            glm::length(back - ndc) < 1e-4f,
            qPrintable(
                QStringLiteral("%1 %2 -> %3 %4").arg(ndc.x).arg(ndc.y).arg(back.x).arg(back.y)));
    }
}

void StateTests::poseReadsBackFromItsStringAndSpec() {
    OrbitPose pose;
    pose.target = {0.5f, -1.0f, 2.0f};
    pose.yaw = 2.0f;
    pose.pitch = -0.3f;
    pose.distance = 3.5f;
    pose.fov_degrees = 45.0f;
    pose.near_plane = 0.01f;
    scene::CameraSpec parsed;
    std::string error;
    QVERIFY2(parse_camera_spec(pose.toString(), parsed, error), error.c_str());
    QVERIFY(near(parsed.eye, pose.eye()));
    QVERIFY(near(parsed.target, pose.target));
    QCOMPARE(parsed.fov_y_degrees, 45.0f);
    QCOMPARE(parsed.near_plane, 0.01f);
    // From the spec back to a pose: the same camera, the lens kept.
    OrbitPose lens;
    lens.fov_degrees = 45.0f;
    lens.aspect = 2.0f;
    const OrbitPose again = orbit_pose_from(pose.spec(), lens);
    QVERIFY(near(again.eye(), pose.eye()));
    QVERIFY(near(again.target, pose.target));
    QCOMPARE(again.aspect, 2.0f);
    QCOMPARE(again.near_plane, 0.01f);
    // Straight down is past the pitch limit: the pose keeps a valid up.
    scene::CameraSpec down;
    down.eye = {0, 10, 0};
    down.target = {0, 0, 0};
    const OrbitPose clamped = orbit_pose_from(down, lens);
    QCOMPARE(clamped.pitch, OrbitPose::kPitchLimit);
    QCOMPARE(clamped.distance, 10.0f);
}

void StateTests::poseTakesAGltfCamera() {
    scene::Scene scene;
    scene::Camera cam;
    cam.yfov = glm::radians(30.0f);
    cam.znear = 0.2f;
    scene.cameras.push_back(cam);
    scene::PlacedCamera placed;
    // At (0, 1, 10), turned 90 degrees about +Y: looks down -X.
    placed.world = glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 10)) *
                   glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0));
    scene.placed_cameras.push_back(placed);
    scene.bounds = core::Aabb::from_min_max({-1, -1, -1}, {1, 1, 1});
    const OrbitPose before;
    QVERIFY(orbit_pose_at_camera(scene, 1, before).toString() == before.toString()); // no such
    const OrbitPose pose = orbit_pose_at_camera(scene, 0, before);
    QVERIFY(near(pose.eye(), glm::vec3(0, 1, 10)));
    QVERIFY(near(pose.forward(), glm::vec3(-1, 0, 0)));
    QVERIFY(std::abs(pose.distance - glm::length(glm::vec3(0, 1, 10))) < 1e-4f);
    QVERIFY(std::abs(pose.fov_degrees - 30.0f) < 1e-4f);
    QCOMPARE(pose.near_plane, 0.2f);
}

void StateTests::cameraInputMovesThePose() {
    OrbitCamera cam;
    cam.setAspect(0.0f);
    QCOMPARE(cam.pose().aspect, 1.0f); // no aspect: square
    cam.setAspect(1.5f);
    // Orbit: 0.3 degrees per pixel, the pitch held short of the poles.
    const float yaw = cam.pose().yaw;
    cam.orbit(100.0f, 0.0f);
    QVERIFY(std::abs(cam.pose().yaw - (yaw - glm::radians(30.0f))) < 1e-5f);
    cam.orbit(0.0f, 1e6f);
    QCOMPARE(cam.pose().pitch, OrbitPose::kPitchLimit);
    cam.orbit(0.0f, -2e6f);
    QCOMPARE(cam.pose().pitch, -OrbitPose::kPitchLimit);
    cam.orbit(0.0f, 250.0f); // a pitch of about -14 degrees
    // Look turns in place: the eye stays.
    const glm::vec3 eye = cam.pose().eye();
    cam.look(40.0f, -25.0f);
    QVERIFY(near(cam.pose().eye(), eye));
    // Pan: the point under the cursor follows it, pixel for pixel.
    const float height = 600.0f, width = height * cam.pose().aspect;
    const glm::vec3 target = cam.pose().target;
    cam.pan(30.0f, -12.0f, height);
    const glm::vec2 moved = ndc_of(cam.pose().spec(), target);
    QVERIFY(std::abs(moved.x * width / 2.0f - 30.0f) < 1e-2f);
    QVERIFY(std::abs(-moved.y * height / 2.0f - -12.0f) < 1e-2f); // screen y is down
    // Dolly: 0.85 per notch, never through the target.
    const float d = cam.pose().distance;
    cam.dolly(2.0f);
    QVERIFY(std::abs(cam.pose().distance - d * 0.85f * 0.85f) < 1e-5f);
    cam.dolly(1e4f);
    QCOMPARE(cam.pose().distance, 1e-4f);
    cam.dolly(-80.0f);
    // Fly: eye and target move together, the direction stays.
    const OrbitPose before = cam.pose();
    cam.fly({1.0f, 2.0f, 3.0f});
    glm::vec3 right, up;
    before.axes(right, up);
    const glm::vec3 step = right + 2.0f * up + 3.0f * before.forward();
    QVERIFY(near(cam.pose().target, before.target + step));
    QVERIFY(near(cam.pose().eye(), before.eye() + step));
    QVERIFY(near(cam.pose().forward(), before.forward()));
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
