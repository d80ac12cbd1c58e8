// The culling dock's CPU monitor (culling_monitor.h): freezing the culling camera and
// coalescing passes that cost more than the GUI thread can spare.
#include <QSignalSpy>
#include <QtTest>

#include "culling_monitor.h"
#include "editor_context.h"
#include "orbit_camera.h"
#include "scene_load_job.h"

using namespace sherpa;
using namespace sherpa::editor;

class CullingMonitorTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void cullingMonitorFreezes();
    void cullingMonitorCoalescesExpensivePasses();
};

void CullingMonitorTests::cullingMonitorFreezes() {
    const LoadOutcome out = SceneLoadJob::loadNow(QStringLiteral("builtin:default"));
    EditorContext context;
    CullingMonitor monitor(context);
    context.setSession(out.session);
    OrbitCamera cam;
    cam.frame(out.session->scene->bounds);
    monitor.update(cam.pose().spec());
    const std::uint64_t total = out.session->scene->instances.size();
    QCOMPARE(monitor.history().latest()->cpu.total, total);
    QCOMPARE(monitor.history().latest()->cpu.visible, total); // framed: everything in view
    monitor.setFrozen(true);
    scene::CameraSpec away = cam.pose().spec();
    away.target = away.eye + (away.eye - cam.pose().target); // look away from the scene
    monitor.update(away);
    QCOMPARE(monitor.history().latest()->cpu.visible,
             total); // still culling with the frozen camera
    monitor.setFrozen(false);
    QVERIFY(monitor.history().latest()->cpu.visible < total);
    QVERIFY(monitor.history().size() >= 4);
}

void CullingMonitorTests::cullingMonitorCoalescesExpensivePasses() {
    const LoadOutcome out = SceneLoadJob::loadNow(QStringLiteral("builtin:default"));
    QVERIFY(out.session);
    EditorContext context;
    CullingMonitor monitor(context);
    context.setSession(out.session);
    OrbitCamera cam;
    cam.frame(out.session->scene->bounds);
    const std::uint64_t total = out.session->scene->instances.size();
    QSignalSpy updated(&monitor, &CullingMonitor::updated);
    // Cheap passes (ten instances: microseconds, far under 4 ms) run at once, one
    // sample per camera step.
    QVERIFY(monitor.pacing().lastPassMs() < 4.0);
    std::size_t samples = monitor.history().size();
    for (int i = 0; i < 5; ++i) {
        cam.orbit(10.0f, 0.0f);
        monitor.update(cam.pose().spec());
    }
    QCOMPARE(monitor.history().size(), samples + 5);
    QCOMPARE(updated.count(), 5);
    QVERIFY(!monitor.pacing().deferred());
    // Passes over the limit (every pass, with the limit at 0): a burst of camera steps
    // runs no pass on the GUI thread until the timer fires, then one for the latest camera.
    monitor.pacing().setCoalesceAboveMs(0.0);
    samples = monitor.history().size();
    updated.clear();
    scene::CameraSpec away = cam.pose().spec();
    for (int i = 0; i < 20; ++i) {
        cam.orbit(10.0f, 0.0f);
        monitor.update(cam.pose().spec());
    }
    away.target = away.eye + (away.eye - cam.pose().target); // the last step looks away
    monitor.update(away);
    QVERIFY(monitor.pacing().deferred());
    QCOMPARE(monitor.history().size(), samples);
    QCOMPARE(updated.count(), 0);
    QTRY_VERIFY(!monitor.pacing().deferred()); // the timer: twice the last pass's cost
    QCOMPARE(monitor.history().size(), samples + 1);
    QCOMPARE(updated.count(), 1);
    QVERIFY(monitor.history().latest()->cpu.visible < total); // culled for the latest camera
    QVERIFY(monitor.history().latest()->cpu.view_projection == away.view_projection());
    // flush() runs a waiting pass at once.
    OrbitCamera framed;
    framed.frame(out.session->scene->bounds);
    monitor.update(framed.pose().spec());
    QVERIFY(monitor.pacing().deferred());
    monitor.pacing().flush();
    QVERIFY(!monitor.pacing().deferred());
    QCOMPARE(monitor.history().size(), samples + 2);
    QCOMPARE(monitor.history().latest()->cpu.visible, total);
}

QTEST_MAIN(CullingMonitorTests)
#include "culling_monitor_tests.moc"
