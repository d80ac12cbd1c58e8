// The viewport's inspection features end to end under Xvfb: the selection
// highlight, node visibility, the GPU culling path with its CPU/GPU agreement, framing for the
// viewport's aspect, and load progress / cancel.
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QVulkanInstance>
#include <QtTest>

#include "culling_dock.h"
#include "culling_monitor.h"
#include "editor_settings.h"
#include "format_values.h"
#include "gpu_viewport.h"
#include "log_dock.h"
#include "main_window.h"
#include "mesh_dock.h"
#include "orbit_camera.h"
#include "render_thread.h"
#include "scene_tree_dock.h"
#include "scene_tree_model.h"
#include "test_assets.h"
#include "texture_dock.h"
#include "texture_table_model.h"
#include "viewport_window.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

using test::kLoadTimeoutMs;
using test::load;
using test::resident_kib;

namespace {

// Waits (bounded, never asserted on) until the viewport has drawn a new frame.
// Waits for a frame to be drawn and for a frame to have been asked for after this
// call: lastFrame() is the last frame asked for, and a frame already in flight can be
// drawn before the scheduled one is asked for (gpuCullingAgreesWithCpu then read the
// state from before setGpuCulling, 2 runs in 3).
bool nextFrame(MainWindow& w) {
    const std::uint64_t before = w.viewport()->framesRendered();
    const std::uint64_t asked_before = w.lastRequest();
    w.viewport()->scheduleFrame();
    QElapsedTimer t;
    t.start();
    const auto done = [&] {
        return w.viewport()->framesRendered() > before && w.lastRequest() > asked_before;
    };
    while (!done() && t.elapsed() < kLoadTimeoutMs)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    return done();
}

// Pixels of the highlight colour (sRGB of gpu::kHighlightColor) in the viewport.
int orangePixels(MainWindow& w) {
    const QImage shot = w.screenshot().convertToFormat(QImage::Format_RGB32);
    const QWidget* vp = w.findChild<QWidget*>(QStringLiteral("viewport"));
    const QRect r(vp->mapTo(&w, QPoint(0, 0)), vp->size());
    int n = 0;
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x) {
            const QRgb p = shot.pixel(x, y);
            if (qRed(p) > 235 && qGreen(p) > 160 && qGreen(p) < 200 && qBlue(p) < 30) ++n;
        }
    return n;
}

// The viewport's pixels in a screenshot of the window.
QImage viewportShot(MainWindow& w) {
    const QImage shot = w.screenshot().convertToFormat(QImage::Format_RGB32);
    const QWidget* vp = w.findChild<QWidget*>(QStringLiteral("viewport"));
    return shot.copy(QRect(vp->mapTo(&w, QPoint(0, 0)), vp->size()));
}

int differingPixels(const QImage& a, const QImage& b) {
    if (a.size() != b.size()) return -1;
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) n += a.pixel(x, y) != b.pixel(x, y);
    return n;
}

// The camera has seen the window's current size.
bool aspectFollows(const ViewportWindow& v) {
    const float aspect =
        static_cast<float>(v.width()) / static_cast<float>(std::max(v.height(), 1));
    return std::abs(v.camera().spec().aspect - aspect) < 1e-3f;
}

// The largest |x| and |y| in NDC of the box's corners seen by `camera`.
QPointF ndcExtent(const CameraSpec& camera, const Aabb& box) {
    QPointF out(0, 0);
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 c((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                          (i & 4) ? box.max.z : box.min.z, 1.0f);
        const glm::vec4 clip = camera.view_projection() * c;
        out.setX(std::max(out.x(), static_cast<double>(std::abs(clip.x / clip.w))));
        out.setY(std::max(out.y(), static_cast<double>(std::abs(clip.y / clip.w))));
    }
    return out;
}

} // namespace

class ViewportTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup() {
        // Every test here runs under the Khronos validation layer: any message fails it.
        if (!window_) return;
        const QString fresh = test::fresh_validation_messages(*window_, seen_validation_);
        QVERIFY2(fresh.isEmpty(), qPrintable(fresh));
    }
    void cleanupTestCase() { window_.reset(); }
    void framingFitsEveryAspect();
    void highlightFollowsSelection();
    void gpuCullingAgreesWithCpu();
    void uncheckedNodeLeavesTheViewport();
    void cullingDockShowsTheRenderersPasses();
    void narrowViewportFramesTheHelmet();
    void framingIsTheEnginesOnLoadFrameAllAndSelection();
    void progressReportsEveryStage();
    void cancelDropsTheLoadAndLeaksNothing();
    void textureCacheActions();
    void missingTextureIsNamedInTheDockAndLog();

private:
    bool hasGpu() const { return window_->renderer() != nullptr; }
    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_validation_ = 0;
};

void ViewportTests::initTestCase() {
    window_ = test::open_validated_window(vulkan_);
    QVERIFY(window_);
    QCoreApplication::processEvents();
}

void ViewportTests::framingFitsEveryAspect() {
    // Plain camera math: whatever the aspect, all 8 corners inside, and tight on one axis.
    const Aabb box = Aabb::from_min_max({-0.94f, -0.9f, -0.82f}, {0.94f, 0.9f, 0.82f});
    for (float aspect : {0.2f, 0.5f, 1.0f, 1.78f, 4.0f}) {
        OrbitCamera cam;
        cam.setAspect(aspect);
        cam.frame(box);
        const QPointF e = ndcExtent(cam.spec(), box);
        QVERIFY2(e.x() <= 1.0 && e.y() <= 1.0,
                 qPrintable(QStringLiteral("aspect %1: %2 %3").arg(aspect).arg(e.x()).arg(e.y())));
        QVERIFY2(std::max(e.x(), e.y()) > 0.9, qPrintable(QString::number(aspect)));
    }
}

void ViewportTests::highlightFollowsSelection() {
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    if (!hasGpu()) QSKIP("no Vulkan device: nothing is rendered");
    window_->pickAt(QPointF(0.999, 0.999)); // background: clears the selection
    QVERIFY(nextFrame(*window_));
    QVERIFY(!window_->lastFrame().highlightInstance);
    const int plain = orangePixels(*window_);

    QVERIFY(window_->selectNodeNamed(QStringLiteral("sphere")));
    const int instance = window_->selectedInstance();
    QVERIFY(instance >= 0);
    QVERIFY(nextFrame(*window_));
    QCOMPARE(window_->lastFrame().highlightInstance.value_or(~0u),
             static_cast<std::uint32_t>(instance));
    QVERIFY2(orangePixels(*window_) > plain + 100, "the highlight is drawn");

    // The mesh dock's vertex and triangle ride along.
    Q_EMIT window_->meshDock()->selectTriangleRequested(7);
    Q_EMIT window_->meshDock()->selectVertexRequested(3);
    QVERIFY(nextFrame(*window_));
    QCOMPARE(window_->lastFrame().highlightTriangle.value_or(~0u), 7u);
    QCOMPARE(window_->lastFrame().highlightVertex.value_or(~0u), 3u);
    QVERIFY(!window_->logDock()->text().contains(QStringLiteral("Rendering stopped")));
}

void ViewportTests::uncheckedNodeLeavesTheViewport() {
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    if (!hasGpu()) QSKIP("no Vulkan device: nothing is rendered");
    window_->pickAt(QPointF(0.999, 0.999)); // background: no selection highlight
    QVERIFY(nextFrame(*window_));
    QVERIFY(!window_->lastFrame().hiddenNodes);
    const QImage shown = viewportShot(*window_);
    const Scene& scene = *window_->context().scene();
    int sphere = -1;
    for (std::size_t n = 0; n < scene.nodes.size(); ++n)
        if (scene.nodes[n].name == "sphere") sphere = static_cast<int>(n);
    QVERIFY(sphere >= 0);
    // The checkbox, as a user unticks it: model -> context -> frame -> renderer.
    SceneTreeModel& tree = *window_->sceneTreeDock()->model();
    QVERIFY(tree.setData(tree.indexOfNode(sphere), Qt::Unchecked, Qt::CheckStateRole));
    QVERIFY(!window_->context().nodeVisible(sphere));
    QVERIFY(nextFrame(*window_));
    const auto mask = window_->lastFrame().hiddenNodes;
    QVERIFY(mask && static_cast<std::size_t>(sphere) < mask->size() &&
            (*mask)[static_cast<std::size_t>(sphere)]);
    const QImage hidden = viewportShot(*window_);
    const int changed = differingPixels(shown, hidden);
    QVERIFY2(changed > 500, qPrintable(QStringLiteral("%1 pixels changed").arg(changed)));
    QVERIFY(tree.setData(tree.indexOfNode(sphere), Qt::Checked, Qt::CheckStateRole));
    QVERIFY(nextFrame(*window_));
    QVERIFY(!window_->lastFrame().hiddenNodes);
    QCOMPARE(differingPixels(shown, viewportShot(*window_)), 0);
}

void ViewportTests::gpuCullingAgreesWithCpu() {
    QVERIFY(load(*window_, QStringLiteral("builtin:grid?n=20")));
    if (!hasGpu()) QSKIP("no Vulkan device: no GPU culling");
    const int errors = window_->logDock()->errorCount();
    window_->setGpuCulling(true);
    for (int step = 0; step < 3; ++step) {
        window_->viewport()->camera().orbit(120.0f, 20.0f); // new frustum each step
        Q_EMIT window_->viewport()->cameraChanged();
        // The CPU pass is there at once; the GPU's answer comes from the render thread.
        QVERIFY(window_->cullingMonitor().latest());
        QTRY_VERIFY_WITH_TIMEOUT(window_->cullingMonitor().latest()->gpu_visible >= 0,
                                 kLoadTimeoutMs);
        const CullSample* s = window_->cullingMonitor().latest();
        QCOMPARE(s->cpu_gpu_differences, 0);
        QCOMPARE(static_cast<std::uint64_t>(s->gpu_visible), s->cpu.visible);
        QVERIFY(window_->cullingDock()->agreementText().contains(QStringLiteral("✔")));
        QVERIFY(window_->cullingDock()->valueText(CullingDock::GpuMs) != QStringLiteral("—"));
        QVERIFY(nextFrame(*window_));
        QVERIFY(window_->lastFrame().gpuCulling);
    }
    // Scene switches with the GPU path on: each new scene is checked against its own culler.
    for (const QString& spec :
         {QStringLiteral("builtin:default"), QStringLiteral("builtin:grid?n=10"),
          test::asset(QStringLiteral("DamagedHelmet"))}) {
        QVERIFY(load(*window_, spec));
        QTRY_VERIFY_WITH_TIMEOUT(window_->cullingMonitor().latest()->gpu_visible >= 0,
                                 kLoadTimeoutMs);
        const CullSample* s = window_->cullingMonitor().latest();
        QCOMPARE(s->cpu_gpu_differences, 0);
    }
    window_->setGpuCulling(false);
    QCOMPARE(window_->cullingMonitor().latest()->gpu_visible, -1);
    QVERIFY(window_->cullingDock()->agreementText().contains(QStringLiteral("off")));
    QVERIFY(nextFrame(*window_));
    QVERIFY(!window_->lastFrame().gpuCulling);
    QCOMPARE(window_->logDock()->errorCount(), errors);
}

void ViewportTests::cullingDockShowsTheRenderersPasses() {
    // builtin:default has a sun: the renderer culls the camera and each cascade.
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    if (!hasGpu()) QSKIP("no Vulkan device: nothing is rendered");
    // Full-size frames: moving frames drawn reduced on a slow device have no shadows.
    window_->renderer()->setInteractiveScaling(false);
    const auto restore = qScopeGuard([this] { window_->renderer()->setInteractiveScaling(true); });
    window_->viewport()->camera().orbit(30.0f, 0.0f); // the shadow cascades are redrawn
    Q_EMIT window_->viewport()->cameraChanged();
    // A frame's statistics are read when its frame slot comes round again.
    const CullingDock& dock = *window_->cullingDock();
    for (int frame = 0; frame < 6 && dock.passRows() < 2; ++frame) {
        window_->viewport()->camera().orbit(5.0f, 0.0f);
        Q_EMIT window_->viewport()->cameraChanged();
        QVERIFY(nextFrame(*window_));
    }
    QVERIFY(dock.passRows() >= 2);
    QCOMPARE(dock.passText(0, 0), QStringLiteral("camera"));
    QCOMPARE(dock.passText(1, 0), QStringLiteral("cascade0"));
    // The camera row is what the renderer counted for its own frame.
    const std::uint64_t total = dock.passText(0, 1).toULongLong();
    const std::uint64_t visible = dock.passText(0, 2).toULongLong();
    const std::uint64_t culled = dock.passText(0, 3).toULongLong();
    const std::uint64_t hidden = dock.passText(0, 8).toULongLong(); // unticked nodes
    QVERIFY(total > 0);
    QCOMPARE(visible + culled + hidden, total);
    QVERIFY(dock.passText(0, 5).toULongLong() > 0); // triangles submitted
}

void ViewportTests::narrowViewportFramesTheHelmet() {
    // Loaded in a wide viewport, then the viewport turns tall and narrow (a dock
    // dragged wider, the window resized) before the user touched the camera: the
    // framing follows the new aspect instead of clipping the sides.
    QWidget* vp = window_->findChild<QWidget*>(QStringLiteral("viewport"));
    QVERIFY(load(*window_, test::asset(QStringLiteral("DamagedHelmet"))));
    const Aabb bounds = window_->context().scene()->bounds;
    QVERIFY(window_->viewport()->width() > 480);
    vp->setMaximumWidth(330); // the viewport's minimum is 320
    QTRY_VERIFY(vp->width() <= 330);
    QTRY_COMPARE(window_->viewport()->width(), vp->width()); // the native window follows
    QTRY_VERIFY(aspectFollows(*window_->viewport()));        // and its resize event has come
    QVERIFY(window_->viewport()->height() > window_->viewport()->width());
    QPointF e = ndcExtent(window_->viewport()->camera().spec(), bounds);
    QVERIFY2(e.x() <= 1.0 && e.y() <= 1.0, "re-framed for the narrow viewport");
    QVERIFY(std::max(e.x(), e.y()) > 0.9); // tight, not just inside
    // Once the user has moved the camera it stays; F frames for the aspect again.
    window_->viewport()->setAutoFrame(false);
    window_->viewport()->camera().dolly(6.0f);
    e = ndcExtent(window_->viewport()->camera().spec(), bounds);
    QVERIFY(e.x() > 1.0); // dollied in: clipped, as the user asked
    QTest::keyClick(window_->viewport(), Qt::Key_F);
    e = ndcExtent(window_->viewport()->camera().spec(), bounds);
    QVERIFY2(e.x() <= 1.0 && e.y() <= 1.0, "frame all (F)");
    QVERIFY(std::max(e.x(), e.y()) > 0.9);
    vp->setMaximumWidth(QWIDGETSIZE_MAX);
}

void ViewportTests::framingIsTheEnginesOnLoadFrameAllAndSelection() {
    // On load and on Frame all (F) the editor shows what `sherpa-cli render --camera
    // auto` shows (sherpa::frame_box at the viewport's aspect), from above the top of
    // the cube; Frame selection (Shift+F) keeps the user's direction.
    QVERIFY(load(*window_, test::asset(QStringLiteral("OrientationTest"))));
    ViewportWindow& vp = *window_->viewport();
    QTRY_VERIFY(aspectFollows(vp));
    const Aabb bounds = window_->context().scene()->bounds;
    auto expectAuto = [&](const char* when) {
        FramingOptions options;
        options.aspect = vp.camera().spec().aspect;
        options.fov_y_degrees = vp.camera().fovDegrees();
        const CameraSpec engine = frame_box(bounds, options);
        const float scale = glm::length(bounds.extent());
        QVERIFY2(glm::length(vp.camera().eye() - engine.eye) < 1e-4f * scale, when);
        QVERIFY2(glm::length(vp.camera().target() - engine.target) < 1e-4f * scale, when);
        QVERIFY2(vp.camera().eye().y > bounds.max.y, when);
    };
    expectAuto("on load");
    vp.camera().orbit(200.0f, -90.0f);
    vp.camera().dolly(3.0f);
    QTest::keyClick(&vp, Qt::Key_F);
    expectAuto("frame all");
    QVERIFY(window_->selectNodeNamed(QStringLiteral("0")));
    vp.camera().orbit(-150.0f, 40.0f);
    const glm::vec3 direction = vp.camera().forward();
    QTest::keyClick(&vp, Qt::Key_F, Qt::ShiftModifier);
    QVERIFY(glm::dot(vp.camera().forward(), direction) > 0.9999f);
    QVERIFY(ndcExtent(vp.camera().spec(), bounds).x() > 0.0); // still a usable camera
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
}

void ViewportTests::progressReportsEveryStage() {
    QSignalSpy progress(&window_->loader(), &SceneLoadJob::progress);
    QVERIFY(load(*window_, test::asset(QStringLiteral("DamagedHelmet"))));
    QList<LoadStep> steps;
    int last_textures_done = -1, textures_total = -1;
    for (const QList<QVariant>& args : progress) {
        const auto step = args.at(0).value<LoadStep>();
        if (steps.isEmpty() || steps.back() != step) steps << step;
        if (step == LoadStep::Textures) {
            last_textures_done = args.at(1).toInt();
            textures_total = args.at(2).toInt();
        }
    }
    const QList<LoadStep> expected = {LoadStep::Parse, LoadStep::Geometry, LoadStep::Tangents,
                                      LoadStep::Textures, LoadStep::Idle};
    QCOMPARE(steps, expected);
    QVERIFY(textures_total > 0);
    QCOMPARE(last_textures_done, textures_total); // the per-texture count reaches the end
    if (!hasGpu()) return;
    // The renderer was there: the loader thread prepared the GPU textures (cache,
    // BC7/BC5), and the texture dock shows their records.
    const SceneSession* session = window_->context().session();
    QVERIFY(session && session->textures);
    QCOMPARE(textures_total, 5); // DamagedHelmet: five images in five roles
    const TextureTableModel* m = window_->textureDock()->model();
    const auto cell = [m](int row, int column) { return m->index(row, column).data().toString(); };
    const QStringList states = {QStringLiteral("hit"), QStringLiteral("miss")};
    for (int row = 0; row < m->rowCount(); ++row) {
        QVERIFY2(states.contains(cell(row, TextureTableModel::CacheStateColumn)),
                 qPrintable(cell(row, TextureTableModel::CacheStateColumn)));
        QVERIFY(cell(row, TextureTableModel::FormatColumn).startsWith(QStringLiteral("BC")) ||
                cell(row, TextureTableModel::FormatColumn).startsWith(QStringLiteral("R8G8B8A8")));
        // The hash elided in the middle; all 32 digits on hover and on copy.
        const QString hash = cell(row, TextureTableModel::HashColumn);
        const QString full =
            m->index(row, TextureTableModel::HashColumn).data(Format::kExactTextRole).toString();
        QCOMPARE(full.size(), 32);
        QCOMPARE(hash, full.left(8) + QChar(0x2026) + full.right(8));
        QCOMPARE(m->index(row, TextureTableModel::HashColumn).data(Qt::ToolTipRole).toString(),
                 full);
        QVERIFY(cell(row, TextureTableModel::GpuBytesColumn) != QStringLiteral("—"));
        QCOMPARE(cell(row, TextureTableModel::MipsColumn), QStringLiteral("12")); // 2048² chain
    }
    // Loaded again: every texture now comes out of the cache.
    QVERIFY(load(*window_, test::asset(QStringLiteral("DamagedHelmet"))));
    for (int row = 0; row < m->rowCount(); ++row)
        QCOMPARE(cell(row, TextureTableModel::CacheStateColumn), QStringLiteral("hit"));
}

void ViewportTests::cancelDropsTheLoadAndLeaksNothing() {
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    const Scene* before = window_->context().scene();
    // Per-frame buffers (overlay lines, culled ids) are made on first use, per frame
    // in flight: draw a few frames first.
    for (int f = 0; hasGpu() && f < 3; ++f) QVERIFY(nextFrame(*window_));
    const std::int64_t objects = hasGpu() ? test::gpu_objects(*window_) : -1;
    QSignalSpy loaded(window_.get(), &MainWindow::sceneLoaded);
    QSignalSpy canceled(window_.get(), &MainWindow::loadCanceled);
    std::uint64_t warm = 0;
    for (int i = 0; i < 12; ++i) {
        // Cancel as soon as the engine reports its first stage: the worker stops there.
        QMetaObject::Connection c =
            connect(&window_->loader(), &SceneLoadJob::progress, this, [this](LoadStep step) {
                if (step == LoadStep::Geometry || step == LoadStep::Tangents) window_->cancelLoad();
            });
        window_->openScene(test::asset(QStringLiteral("DamagedHelmet")));
        QTRY_VERIFY_WITH_TIMEOUT(!window_->loader().running(), kLoadTimeoutMs);
        disconnect(c);
        QTRY_COMPARE_WITH_TIMEOUT(SceneLoadJob::workersInFlight(), 0, kLoadTimeoutMs);
        QCoreApplication::processEvents();
        if (i == 3) warm = resident_kib();
    }
    QCOMPARE(canceled.count(), 12);
    QCOMPARE(loaded.count(), 0);
    QCOMPARE(window_->context().scene(), before); // rolled back: the old scene stays
    QVERIFY(window_->lastProgressText().contains(QStringLiteral("/4")));
    if (objects >= 0) {
        for (int f = 0; f < 3; ++f) QVERIFY(nextFrame(*window_));
        QCOMPARE(test::gpu_objects(*window_), objects);
    }
    QVERIFY2(resident_kib() < warm + 32 * 1024, "cancelled loads leave memory behind");
    QVERIFY(load(*window_, QStringLiteral("builtin:grid?n=10"))); // and loading still works
}

void ViewportTests::textureCacheActions() {
    if (!hasGpu()) QSKIP("no Vulkan device: no texture upload");
    QTemporaryDir dir; // a cache of this test alone
    const QString before = EditorSettings().cacheDirectory();
    EditorSettings().setCacheDirectory(dir.path());
    const TextureTableModel* m = window_->textureDock()->model();
    const auto state = [m](int row) {
        return m->index(row, TextureTableModel::CacheStateColumn).data().toString();
    };
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    QCOMPARE(m->rowCount(), 3);
    for (int row = 0; row < 3; ++row) QCOMPARE(state(row), QStringLiteral("miss"));
    QVERIFY(window_->textureDock()->recompressButton()->isEnabled());
    QVERIFY(window_->textureDock()->clearCacheButton()->isEnabled());
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    for (int row = 0; row < 3; ++row) QCOMPARE(state(row), QStringLiteral("hit"));

    // Recompress texture 0: its file goes, the reload compresses only it again.
    QSignalSpy loaded(window_.get(), &MainWindow::sceneLoaded);
    window_->recompressTexture(0);
    QVERIFY(loaded.wait(kLoadTimeoutMs));
    QCOMPARE(state(0), QStringLiteral("miss"));
    QCOMPARE(state(1), QStringLiteral("hit"));
    QCOMPARE(state(2), QStringLiteral("hit"));

    // Clear: every KTX2 file of the directory is gone.
    QCOMPARE(window_->clearTextureCache(), 3);
    QVERIFY(QDir(dir.path()).entryList({QStringLiteral("*.ktx2")}, QDir::Files).isEmpty());
    EditorSettings().setCacheDirectory(before);
}

QTEST_MAIN(ViewportTests)
// A base-colour image that does not exist: the dock says "missing: FILE" (not a
// cache state), the log names the file and the material slots.
void ViewportTests::missingTextureIsNamedInTheDockAndLog() {
    if (!hasGpu()) QSKIP("no Vulkan device: textures are prepared for the GPU");
    QVERIFY(load(*window_, QStringLiteral(SHERPA_TEST_DATA_DIR "/missing_texture.gltf")));
    QVERIFY(nextFrame(*window_));
    const TextureTableModel* m = window_->textureDock()->model();
    QCOMPARE(m->rowCount(), 1);
    QCOMPARE(m->index(0, TextureTableModel::CacheStateColumn).data().toString(),
             QStringLiteral("missing: does_not_exist.png"));
    QCOMPARE(m->index(0, TextureTableModel::SizeColumn).data().toString(),
             QStringLiteral("missing: does_not_exist.png"));
    const QString tip =
        m->index(0, TextureTableModel::CacheStateColumn).data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(QStringLiteral("material 'Quad' baseColorTexture, occlusionTexture")),
             qPrintable(tip));
    QVERIFY2(window_->logDock()->text().contains(
                 QStringLiteral("texture missing: " SHERPA_TEST_DATA_DIR "/does_not_exist.png")),
             qPrintable(window_->logDock()->text()));
}

#include "viewport_tests.moc"
