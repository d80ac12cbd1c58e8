#pragma once
// Helpers of the window-level QtTest suites (under Xvfb).
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProgressBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QVulkanInstance>
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <vector>

#include <malloc.h>

#include "compare_controller.h"
#include "compare_controls.h"
#include "culling_dock.h"
#include "culling_monitor.h"
#include "difference_legend.h"
#include "engine_probe.h"
#include "environment_menu.h"
#include "lab_dock.h"
#include "load_controller.h"
#include "log_dock.h"
#include "main_window.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "reload_controller.h"
#include "render_controller.h"
#include "render_thread.h"
#include "scene_tree_dock.h"
#include "selection_controller.h"
#include "texture_dock.h"
#include "timeline_dock.h"
#include "validation_dock.h"
#include "view_controller.h"
#include "viewport_window.h"

namespace sherpa::editor::test {

inline constexpr int kLoadTimeoutMs = 60000;

// The window's parts, found as a user of the window would (by object name, or through
// the engine objects on the render thread): MainWindow has no accessors for tests.
inline CullingMonitor& culling_monitor(const MainWindow& w) {
    return *w.findChild<CullingMonitor*>(QStringLiteral("cullingMonitor"));
}
inline SceneLoadJob& scene_loader(const MainWindow& w) {
    return *w.findChild<SceneLoadJob*>(QStringLiteral("sceneLoader"));
}
inline DifferenceLegend& difference_legend(const MainWindow& w) {
    return *w.findChild<DifferenceLegend*>(QStringLiteral("differenceLegend"));
}
// Reload on change (the watched files, the Settings menu's choice).
inline ReloadController& reload_controller(const MainWindow& w) {
    return *w.findChild<ReloadController*>();
}
// View › Reset Layout, as the menu triggers it.
inline void reset_layout(const MainWindow& w) {
    w.findChild<QAction*>(QStringLiteral("resetLayoutAction"))->trigger();
}
// The load progress bar's text as last shown (it stays when the bar hides).
inline QString progress_text(const MainWindow& w) {
    return w.findChild<QProgressBar*>(QStringLiteral("loadProgress"))->text();
}
// The serial of the latest frame the window asked the render thread for; 0 without one.
inline std::uint64_t latest_request(const MainWindow& w) {
    return w.frames().renderer() ? w.frames().renderer()->latestRequest() : 0;
}

// Opens `spec` and waits (bounded) for the load to end; true when it loaded.
inline bool load(MainWindow& w, const QString& spec) {
    QSignalSpy loaded(&w.loads(), &LoadController::sceneLoaded);
    QSignalSpy failed(&w.loads(), &LoadController::loadFailed);
    w.loads().openScene(spec);
    QElapsedTimer t;
    t.start();
    while (loaded.isEmpty() && failed.isEmpty() && t.elapsed() < kLoadTimeoutMs)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    return loaded.count() == 1;
}

// Settings in a directory of this process alone: QStandardPaths' test mode shares
// ~/.qttest between every test process of the user (other worktrees included).
inline void isolate_settings() {
    static QTemporaryDir dir;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir.path());
    QSettings().clear();
    // The texture cache too (the engine's directory is $XDG_CACHE_HOME/sherpa).
    qputenv("XDG_CACHE_HOME", (dir.path() + QStringLiteral("/cache")).toUtf8());
}

// The validation layer's messages since the last call ("" when none); suites set
// SHERPA_VALIDATION=1 before creating the Vulkan instance and fail on any.
inline QString fresh_validation_messages(const MainWindow& w, qsizetype& seen) {
    if (!w.frames().renderer()) return {};
    const QStringList messages =
        w.frames().renderer()->call([](GpuViewport& gpu) { return validation_messages(gpu); });
    const QStringList fresh = messages.mid(seen);
    seen = messages.size();
    return fresh.join(QLatin1Char('\n'));
}

// The window the suites share: settings and caches of this process, the Khronos
// validation layer on (the suites fail on any message), English, shown and exposed,
// builtin:default loaded. Null when it did not come up.
inline std::unique_ptr<MainWindow> open_validated_window(QVulkanInstance& vulkan) {
    QStandardPaths::setTestModeEnabled(true); // caches go to a test location
    isolate_settings();                       // settings to this process's own
    qputenv("SHERPA_VALIDATION", "1");        // before the instance: it enables the layer
    GpuViewport::configureInstance(vulkan);
    vulkan.create(); // optional: without Vulkan the viewport stays empty
    auto window = std::make_unique<MainWindow>(vulkan.isValid() ? &vulkan : nullptr);
    window->setLanguage(QStringLiteral("en"));
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()) ||
        !load(*window, QStringLiteral("builtin:default")))
        return nullptr;
    return window;
}

// GPU objects (buffers, images, samplers) the renderer holds; -1 without one. Frames
// are drawn on another thread: `n` full-size frames are drawn first, so that every
// frame slot holds its per-scene buffers whatever was drawn before.
inline std::int64_t gpu_objects(MainWindow& w, int n = 3) {
    if (!w.frames().renderer()) return -1;
    for (int i = 0; i < n; ++i)
        w.frames().renderer()->renderAndWait(w.frames().lastFrame(), w.viewport()->vulkanSurface());
    return w.frames().renderer()->call([](GpuViewport& gpu) { return gpu_object_count(gpu); });
}

// Bytes malloc has handed out and not yet been given back, in every arena (mmapped
// blocks included): what the process holds, without fragmentation or trimming. It still
// moves by tens of MiB between two identical moments (frames in flight, lavapipe's
// worker threads, Qt caches), so a leak check compares the floor of several samples,
// which moves by a few MiB over 200 scene switches (measured), not single samples.
inline std::uint64_t heap_in_use_kib() {
    const struct mallinfo2 info = mallinfo2();
    return (info.uordblks + info.hblkhd) / 1024;
}

// Lowest of the samples in [first, last).
inline std::uint64_t floor_of(const std::vector<std::uint64_t>& samples, std::size_t first,
                              std::size_t last) {
    std::uint64_t low = UINT64_MAX;
    for (std::size_t i = first; i < last && i < samples.size(); ++i)
        low = std::min(low, samples[i]);
    return low;
}

// Waits (bounded, never asserted on) until the viewport has drawn a new frame.
// Waits for a frame to be drawn and for a frame to have been asked for after this
// call: lastFrame() is the last frame asked for, and a frame already in flight can be
// drawn before the scheduled one is asked for (gpuCullingAgreesWithCpu then read the
// state from before setGpuCulling, 2 runs in 3).
inline bool next_frame(MainWindow& w) {
    const std::uint64_t before = w.viewport()->framesRendered();
    const std::uint64_t asked_before = latest_request(w);
    w.viewport()->scheduleFrame();
    QElapsedTimer t;
    t.start();
    const auto done = [&] {
        return w.viewport()->framesRendered() > before && latest_request(w) > asked_before;
    };
    while (!done() && t.elapsed() < kLoadTimeoutMs)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    return done();
}

// Side B's other file as the viewport compares with it now (null when it does not):
// the session of a frame asked for after this call.
inline SharedSession compare_session(MainWindow& w) {
    next_frame(w);
    return w.frames().lastFrame().compareSession;
}

// The viewport's pixels in a screenshot of the window.
inline QImage viewport_shot(MainWindow& w) {
    const QImage shot = w.screenshot().convertToFormat(QImage::Format_RGB32);
    const QWidget* vp = w.findChild<QWidget*>(QStringLiteral("viewport"));
    return shot.copy(QRect(vp->mapTo(&w, QPoint(0, 0)), vp->size()));
}

} // namespace sherpa::editor::test
