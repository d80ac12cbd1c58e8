// The viewport's inspection features end to end under Xvfb: the selection
// highlight, node visibility, the GPU culling path with its CPU/GPU agreement, and framing
// for the viewport's aspect. (Loading, cancel and texture cache actions: loading_tests.cpp.)
// The engine's headers first: Qt's QVulkanInstance defines VK_NO_PROTOTYPES.
#include <sherpa/render/renderer.h>

#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QVulkanInstance>
#include <QtTest>

#include "culling_dock.h"
#include "culling_monitor.h"
#include "gpu_viewport.h"
#include "log_dock.h"
#include "main_window.h"
#include "mesh_dock.h"
#include "orbit_camera.h"
#include "render_thread.h"
#include "scene_tree_dock.h"
#include "scene_tree_model.h"
#include "test_assets.h"
#include "viewport_window.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

using test::kLoadTimeoutMs;
using test::load;

namespace {

// Pixels of the highlight colour (sRGB of render::kHighlightColor) in the viewport.
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
    return std::abs(v.camera().pose().spec().aspect - aspect) < 1e-3f;
}

// The largest |x| and |y| in NDC of the box's corners seen by `camera`.
QPointF ndcExtent(const scene::CameraSpec& camera, const core::Aabb& box) {
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

// The same over points (the drawn vertices automatic framing fits).
QPointF ndcExtent(const scene::CameraSpec& camera, const std::vector<glm::vec3>& points) {
    QPointF out(0, 0);
    for (const glm::vec3& p : points) {
        const glm::vec4 clip = camera.view_projection() * glm::vec4(p, 1.0f);
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
    void fileCamerasAreOfferedAndSetTheFront();
    void variantMenuSwitchesMaterialsWithoutReloading();

private:
    bool hasGpu() const { return window_->frames().renderer() != nullptr; }
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
    const core::Aabb box = core::Aabb::from_min_max({-0.94f, -0.9f, -0.82f}, {0.94f, 0.9f, 0.82f});
    for (float aspect : {0.2f, 0.5f, 1.0f, 1.78f, 4.0f}) {
        OrbitCamera cam;
        cam.setAspect(aspect);
        cam.frame(box);
        const QPointF e = ndcExtent(cam.pose().spec(), box);
        QVERIFY2(e.x() <= 1.0 && e.y() <= 1.0,
                 qPrintable(QStringLiteral("aspect %1: %2 %3").arg(aspect).arg(e.x()).arg(e.y())));
        QVERIFY2(std::max(e.x(), e.y()) > 0.9, qPrintable(QString::number(aspect)));
    }
}

void ViewportTests::highlightFollowsSelection() {
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    if (!hasGpu()) QSKIP("no Vulkan device: nothing is rendered");
    window_->selection().pickAt(QPointF(0.999, 0.999)); // background: clears the selection
    QVERIFY(test::next_frame(*window_));
    QVERIFY(!window_->frames().lastFrame().request.highlight_instance);
    const int plain = orangePixels(*window_);

    QVERIFY(window_->selection().selectNodeNamed(QStringLiteral("sphere")));
    const int instance = window_->selection().selectedInstance();
    QVERIFY(instance >= 0);
    QVERIFY(test::next_frame(*window_));
    QCOMPARE(window_->frames().lastFrame().request.highlight_instance.value_or(~0u),
             static_cast<std::uint32_t>(instance));
    QVERIFY2(orangePixels(*window_) > plain + 100, "the highlight is drawn");

    // The mesh dock's vertex and triangle ride along.
    Q_EMIT window_->docks().mesh->selectTriangleRequested(7);
    Q_EMIT window_->docks().mesh->selectVertexRequested(3);
    QVERIFY(test::next_frame(*window_));
    QCOMPARE(window_->frames().lastFrame().request.highlight_triangle.value_or(~0u), 7u);
    QCOMPARE(window_->frames().lastFrame().request.highlight_vertex.value_or(~0u), 3u);
    QVERIFY(!window_->docks().log->text().contains(QStringLiteral("Rendering stopped")));

    // A node without a mesh (the instance grid's parent) outlines its subtree: every
    // instance placed by a descendant, found here by walking the parents.
    QVERIFY(window_->selection().selectNodeNamed(QStringLiteral("instance grid")));
    const scene::Scene& scene = *window_->context().scene();
    const int grid = window_->context().selection().current().node;
    QCOMPARE(scene.nodes[std::size_t(grid)].mesh, -1);
    std::vector<std::uint32_t> expected;
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i)
        for (int n = int(scene.instances[i].node_id); n >= 0;
             n = scene.nodes[std::size_t(n)].parent)
            if (n == grid) {
                expected.push_back(i);
                break;
            }
    QVERIFY(expected.size() > 1);
    QVERIFY(test::next_frame(*window_));
    QVERIFY(!window_->frames().lastFrame().request.highlight_instance);
    QCOMPARE(window_->frames().lastFrame().request.highlight_outline, expected);
    QVERIFY2(orangePixels(*window_) > plain + 100, "the subtree's outline is drawn");
}

void ViewportTests::uncheckedNodeLeavesTheViewport() {
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    if (!hasGpu()) QSKIP("no Vulkan device: nothing is rendered");
    window_->selection().pickAt(QPointF(0.999, 0.999)); // background: no selection highlight
    QVERIFY(test::next_frame(*window_));
    QVERIFY(!window_->frames().lastFrame().hiddenNodes);
    const QImage shown = test::viewport_shot(*window_);
    const scene::Scene& scene = *window_->context().scene();
    int sphere = -1;
    for (std::size_t n = 0; n < scene.nodes.size(); ++n)
        if (scene.nodes[n].name == "sphere") sphere = static_cast<int>(n);
    QVERIFY(sphere >= 0);
    // The checkbox, as a user unticks it: model -> context -> frame -> renderer.
    SceneTreeModel& tree = *window_->docks().sceneTree->model();
    QVERIFY(tree.setData(tree.indexOfNode(sphere), Qt::Unchecked, Qt::CheckStateRole));
    QVERIFY(!window_->context().visibility().nodeVisible(sphere));
    QVERIFY(test::next_frame(*window_));
    const auto mask = window_->frames().lastFrame().hiddenNodes;
    QVERIFY(mask && static_cast<std::size_t>(sphere) < mask->size() &&
            (*mask)[static_cast<std::size_t>(sphere)]);
    const QImage hidden = test::viewport_shot(*window_);
    const int changed = differingPixels(shown, hidden);
    QVERIFY2(changed > 500, qPrintable(QStringLiteral("%1 pixels changed").arg(changed)));
    QVERIFY(tree.setData(tree.indexOfNode(sphere), Qt::Checked, Qt::CheckStateRole));
    QVERIFY(test::next_frame(*window_));
    QVERIFY(!window_->frames().lastFrame().hiddenNodes);
    QCOMPARE(differingPixels(shown, test::viewport_shot(*window_)), 0);
}

void ViewportTests::gpuCullingAgreesWithCpu() {
    QVERIFY(load(*window_, QStringLiteral("builtin:grid?n=20")));
    if (!hasGpu()) QSKIP("no Vulkan device: no GPU culling");
    const int errors = window_->docks().log->errorCount();
    window_->views().setGpuCulling(true);
    for (int step = 0; step < 3; ++step) {
        window_->viewport()->camera().orbit(120.0f, 20.0f); // new frustum each step
        Q_EMIT window_->viewport()->input().cameraChanged();
        // The CPU pass is there at once; the GPU's answer comes from the render thread.
        QVERIFY(test::culling_monitor(*window_).history().latest());
        QTRY_VERIFY_WITH_TIMEOUT(
            test::culling_monitor(*window_).history().latest()->gpu_visible >= 0, kLoadTimeoutMs);
        const CullSample* s = test::culling_monitor(*window_).history().latest();
        QCOMPARE(s->cpu_gpu_differences, 0);
        QCOMPARE(static_cast<std::uint64_t>(s->gpu_visible), s->cpu.visible);
        QVERIFY(window_->docks().culling->agreementText().contains(QStringLiteral("✔")));
        QVERIFY(window_->docks().culling->valueText(CullingDock::GpuMs) != QStringLiteral("—"));
        QVERIFY(test::next_frame(*window_));
        QVERIFY(window_->frames().lastFrame().request.cull == render::CullPath::Gpu);
    }
    // Scene switches with the GPU path on: each new scene is checked against its own culler.
    for (const QString& spec :
         {QStringLiteral("builtin:default"), QStringLiteral("builtin:grid?n=10"),
          test::asset(QStringLiteral("DamagedHelmet"))}) {
        QVERIFY(load(*window_, spec));
        QTRY_VERIFY_WITH_TIMEOUT(
            test::culling_monitor(*window_).history().latest()->gpu_visible >= 0, kLoadTimeoutMs);
        const CullSample* s = test::culling_monitor(*window_).history().latest();
        QCOMPARE(s->cpu_gpu_differences, 0);
    }
    window_->views().setGpuCulling(false);
    QCOMPARE(test::culling_monitor(*window_).history().latest()->gpu_visible, -1);
    QVERIFY(window_->docks().culling->agreementText().contains(QStringLiteral("off")));
    QVERIFY(test::next_frame(*window_));
    QVERIFY(window_->frames().lastFrame().request.cull == render::CullPath::Cpu);
    QCOMPARE(window_->docks().log->errorCount(), errors);
}

void ViewportTests::cullingDockShowsTheRenderersPasses() {
    // builtin:default has a sun: the renderer culls the camera and each cascade.
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    if (!hasGpu()) QSKIP("no Vulkan device: nothing is rendered");
    // Full-size frames: moving frames drawn reduced on a slow device have no shadows.
    window_->frames().renderer()->setPacing({.interactiveScaling = false});
    const auto restore = qScopeGuard(
        [this] { window_->frames().renderer()->setPacing({.interactiveScaling = true}); });
    window_->viewport()->camera().orbit(30.0f, 0.0f); // the shadow cascades are redrawn
    Q_EMIT window_->viewport()->input().cameraChanged();
    // A frame's statistics are read when its frame slot comes round again.
    const CullingDock& dock = *window_->docks().culling;
    for (int frame = 0; frame < 6 && dock.passRows() < 2; ++frame) {
        window_->viewport()->camera().orbit(5.0f, 0.0f);
        Q_EMIT window_->viewport()->input().cameraChanged();
        QVERIFY(test::next_frame(*window_));
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
    // Automatic framing fits the drawn vertices to 80% of the tighter side.
    const std::vector<glm::vec3> bounds = scene::framing_points(*window_->context().scene());
    QVERIFY(window_->viewport()->width() > 480);
    vp->setMaximumWidth(330); // the viewport's minimum is 320
    QTRY_VERIFY(vp->width() <= 330);
    QTRY_COMPARE(window_->viewport()->width(), vp->width()); // the native window follows
    QTRY_VERIFY(aspectFollows(*window_->viewport()));        // and its resize event has come
    QVERIFY(window_->viewport()->height() > window_->viewport()->width());
    QPointF e = ndcExtent(window_->viewport()->camera().pose().spec(), bounds);
    QVERIFY2(e.x() <= 1.0 && e.y() <= 1.0, "re-framed for the narrow viewport");
    QVERIFY(std::max(e.x(), e.y()) > 0.79 && std::max(e.x(), e.y()) < 0.81); // tight
    // Once the user has moved the camera it stays; F frames for the aspect again.
    window_->viewport()->input().setAutoFrame(false);
    window_->viewport()->camera().dolly(6.0f);
    e = ndcExtent(window_->viewport()->camera().pose().spec(), bounds);
    QVERIFY(e.x() > 1.0); // dollied in: clipped, as the user asked
    QTest::keyClick(window_->viewport(), Qt::Key_F);
    e = ndcExtent(window_->viewport()->camera().pose().spec(), bounds);
    QVERIFY2(e.x() <= 1.0 && e.y() <= 1.0, "frame all (F)");
    QVERIFY(std::max(e.x(), e.y()) > 0.79 && std::max(e.x(), e.y()) < 0.81);
    vp->setMaximumWidth(QWIDGETSIZE_MAX);
}

void ViewportTests::framingIsTheEnginesOnLoadFrameAllAndSelection() {
    // On load and on Frame all (F) the editor shows what `sherpa-cli render --camera
    // auto` shows (sherpa::scene::frame_scene at the viewport's aspect), looking down on the
    // cube; Frame selection (Shift+F) keeps the user's direction.
    QVERIFY(load(*window_, test::asset(QStringLiteral("OrientationTest"))));
    ViewportWindow& vp = *window_->viewport();
    QTRY_VERIFY(aspectFollows(vp));
    const core::Aabb bounds = window_->context().scene()->bounds;
    auto expectAuto = [&](const char* when) {
        scene::FramingOptions options;
        options.aspect = vp.camera().pose().spec().aspect;
        options.fov_y_degrees = vp.camera().pose().fov_degrees;
        const scene::CameraSpec engine =
            scene::frame_scene(*window_->context().scene(), nullptr, options);
        const float scale = glm::length(bounds.extent());
        QVERIFY2(glm::length(vp.camera().pose().eye() - engine.eye) < 1e-4f * scale, when);
        QVERIFY2(glm::length(vp.camera().pose().target - engine.target) < 1e-4f * scale, when);
        QVERIFY2(vp.camera().pose().forward().y < -0.3f, when);
    };
    expectAuto("on load");
    vp.camera().orbit(200.0f, -90.0f);
    vp.camera().dolly(3.0f);
    QTest::keyClick(&vp, Qt::Key_F);
    expectAuto("frame all");
    QVERIFY(window_->selection().selectNodeNamed(QStringLiteral("0")));
    vp.camera().orbit(-150.0f, 40.0f);
    const glm::vec3 direction = vp.camera().pose().forward();
    QTest::keyClick(&vp, Qt::Key_F, Qt::ShiftModifier);
    QVERIFY(glm::dot(vp.camera().pose().forward(), direction) > 0.9999f);
    QVERIFY(ndcExtent(vp.camera().pose().spec(), bounds).x() > 0.0); // still a usable camera
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
}

void ViewportTests::fileCamerasAreOfferedAndSetTheFront() {
    // The Duck's file places a camera behind and to the right of the duck: the log says
    // where the file's cameras are, the automatic view looks from that camera's side, and
    // View › glTF Cameras looks through it.
    QVERIFY(load(*window_, test::asset(QStringLiteral("Duck"))));
    QVERIFY2(window_->docks().log->text().contains(
                 QStringLiteral("The file places 1 camera(s): View › glTF Cameras")),
             qPrintable(window_->docks().log->text()));
    const scene::Scene& scene = *window_->context().scene();
    const glm::vec3 file_eye = glm::vec3(scene.placed_cameras.at(0).world[3]);
    const OrbitCamera& cam = window_->viewport()->camera();
    const auto horizontal = [](glm::vec3 v) { return glm::normalize(glm::vec2(v.x, v.z)); };
    QVERIFY(glm::dot(horizontal(cam.pose().eye() - cam.pose().target),
                     horizontal(file_eye - scene.bounds.center())) > 0.8f);
    QMenu* cameras = nullptr;
    for (QMenu* m : window_->menuBar()->findChildren<QMenu*>())
        if (m->title() == QStringLiteral("glTF &Cameras")) cameras = m;
    QVERIFY(cameras);
    Q_EMIT cameras->aboutToShow();
    QCOMPARE(cameras->actions().size(), 1);
    QVERIFY(cameras->actions().front()->isEnabled());
    cameras->actions().front()->trigger();
    QVERIFY(glm::length(window_->viewport()->camera().pose().eye() - file_eye) <
            1e-3f * glm::length(scene.bounds.extent()));
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
}

void ViewportTests::variantMenuSwitchesMaterialsWithoutReloading() {
    // KHR_materials_variants: the Variants menu lists the file's variants; choosing one
    // switches the materials on the render thread (the log says what changed, GPU bytes
    // included), the scene is not reloaded, and the image changes; the defaults restore it.
    QVERIFY(load(*window_, QString::fromUtf8(SHERPA_TEST_DATA_DIR) +
                               QStringLiteral("/material_sweeps/variants.gltf")));
    if (!hasGpu()) QSKIP("no Vulkan device: nothing is rendered");
    QMenu* variants = nullptr;
    for (QAction* top : window_->menuBar()->actions())
        if (top->menu() && top->menu()->title() == QStringLiteral("Va&riants"))
            variants = top->menu();
    QVERIFY(variants);
    QVERIFY(variants->isEnabled());
    QStringList names;
    for (QAction* a : variants->actions())
        if (!a->isSeparator()) names << a->text();
    QCOMPARE(names, (QStringList{QStringLiteral("&Default Materials"), QStringLiteral("Warm"),
                                 QStringLiteral("Cool")}));
    window_->selection().pickAt(QPointF(0.999, 0.999)); // no selection highlight
    QVERIFY(test::next_frame(*window_));
    const QImage before = test::viewport_shot(*window_);
    const auto* session = window_->context().session();
    variants->actions().at(2)->trigger(); // Warm (after the separator)
    // With ray tracing (the window's default where the device can), the ray tracer's
    // geometry records follow too: 2 material words.
    const QString rays = window_->frames().renderer()->call([](GpuViewport& gpu) {
        return gpu.renderer().resident().acceleration
                   ? QStringLiteral("; ray tracer: 2 geometry record(s), 8 bytes")
                   : QString();
    });
    QTRY_VERIFY_WITH_TIMEOUT(
        window_->docks().log->text().contains(
            QStringLiteral("Material variant: Warm (2 primitive(s), 2 draw(s) changed material; "
                           "8 GPU bytes uploaded") +
            rays + QStringLiteral("; nothing reloaded).")),
        kLoadTimeoutMs);
    QCOMPARE(window_->context().session(), session); // not reloaded
    QVERIFY(test::next_frame(*window_));
    const int changed = differingPixels(before, test::viewport_shot(*window_));
    QVERIFY2(changed > 200, qPrintable(QStringLiteral("%1 pixels changed").arg(changed)));
    variants->actions().at(0)->trigger(); // back to the defaults
    QTRY_VERIFY_WITH_TIMEOUT(window_->docks().log->text().contains(
                                 QStringLiteral("Material variant: default materials")),
                             kLoadTimeoutMs);
    QVERIFY(test::next_frame(*window_));
    QCOMPARE(differingPixels(before, test::viewport_shot(*window_)), 0);
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    QVERIFY(!variants->isEnabled()); // no variants in that scene
}

QTEST_MAIN(ViewportTests)
#include "viewport_tests.moc"
