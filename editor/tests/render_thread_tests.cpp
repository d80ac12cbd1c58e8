// The viewport's render thread under Xvfb and the validation layer: the GUI thread
// keeps working while a frame is in flight (and its camera input coalesces), moving
// frames are drawn at a reduced resolution and the still frame after them is the
// exact full-resolution image, and the status bar's GPU time is measured.
#include <QLabel>
#include <QScreen>
#include <QStatusBar>
#include <QVulkanInstance>
#include <QtTest>
#include <future>

#include "gpu_viewport.h"
#include "main_window.h"
#include "mesh_dock.h"
#include "render_thread.h"
#include "resolution_scale.h"
#include "scene_tree_dock.h"
#include "test_assets.h"
#include "timeline_dock.h"
#include "viewport_window.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

// Waits (bounded, never asserted on) until a frame report satisfies `done`.
template <class Pred> bool waitForReport(MainWindow& w, Pred done) {
    QElapsedTimer t;
    t.start();
    while (!done(w.frames().lastReport()) && t.elapsed() < test::kLoadTimeoutMs)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 10);
    return done(w.frames().lastReport());
}

// The viewport as the X server shows it, after the queue has drained.
QImage viewportOnScreen(MainWindow& w) {
    w.frames().renderer()->call([](GpuViewport& gpu) { gpu.finish(); });
    ViewportWindow* vp = w.viewport();
    return vp->screen()->grabWindow(vp->winId()).toImage().convertToFormat(QImage::Format_RGB32);
}

int maxDifference(const QImage& a, const QImage& b) {
    if (a.size() != b.size()) return 256;
    int worst = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            worst = std::max({worst, std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                              std::abs(qBlue(p) - qBlue(q))});
        }
    return worst;
}

} // namespace

class RenderThreadTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup() {
        if (!window_) return;
        const QString fresh = test::fresh_validation_messages(*window_, seen_validation_);
        QVERIFY2(fresh.isEmpty(), qPrintable(fresh));
    }
    void cleanupTestCase() { window_.reset(); }
    void guiWorksWhileAFrameIsInFlight();
    void stillFrameIsFullResolutionAfterMotion();
    void playbackIsMotionAndPauseIsExact();
    void gpuTimeIsMeasured();
    void sceneAskedForBeforeTheDeviceWaitsForIt();

private:
    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_validation_ = 0;
};

void RenderThreadTests::initTestCase() {
    window_ = test::open_validated_window(vulkan_);
    QVERIFY(window_);
}

void RenderThreadTests::guiWorksWhileAFrameIsInFlight() {
    if (!window_->frames().renderer()) QSKIP("no Vulkan device: nothing is rendered");
    MainWindow& w = *window_;
    QVERIFY(waitForReport(w, [](const FrameReport& r) { return r.request > 0; }));
    // The render thread is busy for as long as the test wants (a frame that does not
    // end); it gives up after a while so that a GUI that waits for it cannot hang the
    // suite, and says so.
    struct Busy {
        std::promise<void> release;
        std::shared_future<void> released = release.get_future().share();
        std::atomic<bool> gave_up{false};
    };
    auto busy = std::make_shared<Busy>();
    w.frames().renderer()->post([busy](GpuViewport&) {
        busy->gave_up =
            busy->released.wait_for(std::chrono::seconds(20)) == std::future_status::timeout;
    });
    // Released however the test ends.
    const auto release = qScopeGuard([busy] {
        if (busy->released.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
            busy->release.set_value();
    });
    const std::uint64_t frames = w.viewport()->framesRendered();
    // Fifty camera steps, a selection (docks fill), a view change and a resize.
    for (int i = 0; i < 50; ++i) {
        w.viewport()->camera().orbit(3.0f, 0.5f);
        Q_EMIT w.viewport()->input().cameraChanged();
        w.viewport()->renderNow();
        QCoreApplication::processEvents();
    }
    QVERIFY(w.selection().selectNodeNamed(QStringLiteral("sphere")));
    QVERIFY(w.views().setDebugView(QStringLiteral("normal"), false));
    w.resize(w.width() - 40, w.height() - 20);
    QTRY_COMPARE(QSize(int(w.frames().lastFrame().request.width),
                       int(w.frames().lastFrame().request.height)),
                 w.viewport()->pixelSize());
    QVERIFY(w.docks().mesh->isVisible());
    // All of it happened while the render thread was still busy.
    QVERIFY2(!busy->gave_up, "the GUI thread waited for the render thread");
    QCOMPARE(w.viewport()->framesRendered(), frames);
    const std::uint64_t latest = test::latest_request(w);
    std::vector<std::uint64_t> drawn; // requests in the order they were drawn
    const QMetaObject::Connection c =
        connect(w.frames().renderer(), &RenderThread::frameDone, this,
                [&](const FrameReport& r) { drawn.push_back(r.request); });
    busy->release.set_value();
    // Then the latest request is drawn first: the fifty camera steps coalesced.
    QTRY_VERIFY_WITH_TIMEOUT(!drawn.empty(), test::kLoadTimeoutMs);
    disconnect(c);
    QVERIFY2(drawn.front() >= latest, "an older request was drawn");
    QTest::qWait(2 * FramePacing::kRestMs);
    QVERIFY2(w.viewport()->framesRendered() - frames <= 6,
             qPrintable(QString::number(w.viewport()->framesRendered() - frames)));
    QVERIFY(!busy->gave_up);
    w.views().setDebugView(QStringLiteral("lit"), false);
}

void RenderThreadTests::stillFrameIsFullResolutionAfterMotion() {
    if (!window_->frames().renderer()) QSKIP("no Vulkan device: nothing is rendered");
    MainWindow& w = *window_;
    QVERIFY(test::load(w, test::asset(QStringLiteral("DamagedHelmet"))));
    const QSize pixels = w.viewport()->pixelSize();
    // Every moving frame is "too slow": drawn at the smallest scale.
    w.frames().renderer()->setPacing({.targetFrameMs = 0.01});
    w.screenshot(); // a full-size frame at rest
    const QImage reference = viewportOnScreen(w);
    const OrbitCamera rest = w.viewport()->camera();

    w.viewport()->camera().orbit(40.0f, 10.0f);
    Q_EMIT w.viewport()->input().cameraChanged();
    QVERIFY(waitForReport(w, [](const FrameReport& r) { return r.scale < 1.0f; }));
    // Back to where it was, one moving frame, then nothing: the camera rests.
    w.viewport()->camera() = rest;
    Q_EMIT w.viewport()->input().cameraChanged();
    QTRY_VERIFY(w.frames().lastFrame().request.camera.eye == rest.pose().eye()); // asked for
    const std::uint64_t moving = test::latest_request(w);
    QVERIFY(waitForReport(w, [&](const FrameReport& r) { return r.request == moving; }));
    QCOMPARE(w.frames().lastReport().scale, kMinResolutionScale);
    // Nobody asks again: the render thread draws the same request at full size.
    QVERIFY(waitForReport(w, [](const FrameReport& r) { return r.scale == 1.0f; }));
    QVERIFY(w.frames().lastReport().request >= moving);
    QCOMPARE(QSize(int(w.frames().lastReport().width), int(w.frames().lastReport().height)),
             pixels);
    const QImage still = viewportOnScreen(w);
    QVERIFY2(maxDifference(still, reference) <= 1,
             qPrintable(QString::number(maxDifference(still, reference))));
    // A screenshot is full size whatever the camera did just before.
    w.viewport()->camera().orbit(-40.0f, 0.0f);
    Q_EMIT w.viewport()->input().cameraChanged();
    w.viewport()->camera() = rest;
    w.screenshot();
    QCOMPARE(w.frames().lastReport().scale, 1.0f);
    QVERIFY(maxDifference(viewportOnScreen(w), reference) <= 1);
    w.frames().renderer()->setPacing({.targetFrameMs = kTargetFrameMs});
}

void RenderThreadTests::playbackIsMotionAndPauseIsExact() {
    // A playing animation moves like an orbiting camera: its frames get the adaptive
    // resolution; paused, the frame of that time is drawn at full size.
    if (!window_->frames().renderer()) QSKIP("no Vulkan device: nothing is rendered");
    MainWindow& w = *window_;
    QVERIFY(test::load(w, test::asset(QStringLiteral("AnimatedCube"))));
    TimelineDock& timeline = *w.docks().timeline;
    w.frames().renderer()->setPacing({.targetFrameMs = 0.01}); // every moving frame is "too slow"
    w.screenshot();                                            // a full-size frame at rest
    QCOMPARE(w.frames().lastReport().scale, 1.0f);
    // Steps of the play loop, the camera still: the scale drops.
    timeline.setPlaying(true);
    for (int i = 0; i < 3; ++i) {
        timeline.advance(0.05);
        QTRY_VERIFY(w.frames().lastFrame().request.pose == timeline.playback().pose()); // asked for
        const std::uint64_t step = test::latest_request(w);
        QVERIFY(waitForReport(w, [&](const FrameReport& r) { return r.request >= step; }));
    }
    QVERIFY2(w.frames().lastReport().scale < 1.0f,
             qPrintable(QString::number(w.frames().lastReport().scale)));
    QCOMPARE(w.frames().lastFrame().request.camera.eye,
             w.viewport()->camera().pose().spec().eye); // camera still
    // Paused: nobody asks again, and the pose of this time is drawn at full size.
    timeline.setPlaying(false);
    const std::uint64_t paused = test::latest_request(w);
    QVERIFY(waitForReport(
        w, [&](const FrameReport& r) { return r.scale == 1.0f && r.request >= paused; }));
    QCOMPARE(QSize(int(w.frames().lastReport().width), int(w.frames().lastReport().height)),
             w.viewport()->pixelSize());
    w.frames().renderer()->setPacing({.targetFrameMs = kTargetFrameMs});
    QVERIFY(test::load(w, QStringLiteral("builtin:default")));
}

void RenderThreadTests::gpuTimeIsMeasured() {
    if (!window_->frames().renderer()) QSKIP("no Vulkan device: nothing is rendered");
    MainWindow& w = *window_;
    // The GPU time of a frame is read when its frame slot comes round again.
    for (int i = 0; i < 4; ++i) {
        w.viewport()->camera().orbit(5.0f, 0.0f);
        Q_EMIT w.viewport()->input().cameraChanged();
        const std::uint64_t before = w.viewport()->framesRendered();
        QTRY_VERIFY_WITH_TIMEOUT(w.viewport()->framesRendered() > before, test::kLoadTimeoutMs);
    }
    QVERIFY(w.frames().lastReport().gpu_ms > 0.0);
    const auto* label = w.statusBar()->findChild<QLabel*>(QStringLiteral("frameLabel"));
    QVERIFY(label);
    QVERIFY2(label->text().contains(QStringLiteral("GPU")), qPrintable(label->text()));
    QVERIFY2(label->text().contains(QStringLiteral("fps")), qPrintable(label->text()));
}

// The device is made on the render thread while the window shows: a scene opened
// before it is known (as the command line's is) starts loading once it is, with the
// device's texture plan; never without it (the race of the old zero-delay timer).
void RenderThreadTests::sceneAskedForBeforeTheDeviceWaitsForIt() {
    if (!window_->frames().renderer()) QSKIP("no Vulkan device");
    MainWindow w(&vulkan_);
    w.setLanguage(QStringLiteral("en"), false);
    QVERIFY(w.frames().renderer());
    // deviceReady reaches the GUI thread as a queued call: not before the event loop runs.
    int ready = 0;
    connect(w.frames().renderer(), &RenderThread::deviceReady, this, [&ready] { ++ready; });
    QSignalSpy loaded(&w.loads(), &LoadController::sceneLoaded);
    w.loads().openScene(QStringLiteral("builtin:default"));
    QVERIFY(!test::scene_loader(w).running()); // waits for the device
    QVERIFY(loaded.wait(test::kLoadTimeoutMs));
    QCOMPARE(ready, 1);
    // Its textures were prepared for the device (a plan without one prepares none).
    QVERIFY(w.context().session() && w.context().session()->textures);
}

QTEST_MAIN(RenderThreadTests)
#include "render_thread_tests.moc"
