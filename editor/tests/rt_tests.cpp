// Ray tracing in the editor, end to end under Xvfb with the validation layer: the
// acceleration-structure dock and its selection, the viewport's raster and ray traced
// modes, the path-traced lit view and the material variant switch under rays.
// The engine's headers first: Qt's QVulkanInstance defines VK_NO_PROTOTYPES.
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/comparison.h>

#include <QHeaderView>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTableView>
#include <QVulkanInstance>
#include <QtTest>
#include <limits>
#include <set>

#include "acceleration_dock.h"
#include "acceleration_model.h"
#include "command_line.h"
#include "compare_controls.h"
#include "difference_legend.h"
#include "log_dock.h"
#include "main_window.h"
#include "scene_tree_dock.h"
#include "test_assets.h"
#include "view_catalog.h"
#include "viewport_window.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

// Pixels of columns [x0, x1) where the two images differ by more than 2/255 in a channel.
int differing(const QImage& a, const QImage& b, int x0, int x1) {
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = x0; x < x1; ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            if (std::abs(qRed(p) - qRed(q)) > 2 || std::abs(qGreen(p) - qGreen(q)) > 2 ||
                std::abs(qBlue(p) - qBlue(q)) > 2)
                ++n;
        }
    return n;
}

// Pixels whose colour differs from the background corner's: something is drawn.
int covered(const QImage& image) {
    const QRgb bg = image.pixel(0, 0);
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) n += image.pixel(x, y) != bg;
    return n;
}

} // namespace

class RtTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void commandLineTakesRt();
    void accelerationDockListsBlasAndSelectsMesh();
    void rtOffBuildsNothing();
    void rayTracedModeDrawsRtFrames();
    void refusedViewGoesBackToRaster();
    void litIsPathTracedAndAccumulatesAtRest();
    void variantMenuSwitchesTheRayTracedFrame();
    void emitterWarningsReachTheLog();
    void cleanup();

private:
    void checkValidation();

    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_ = 0;
};

void RtTests::initTestCase() {
    window_ = test::open_validated_window(vulkan_);
    QVERIFY(window_);
    if (!window_->frames().renderer()) QSKIP("no Vulkan device");
    QTRY_VERIFY_WITH_TIMEOUT(window_->frames().rayTracing(), 10000);
}

void RtTests::cleanupTestCase() {
    if (window_) checkValidation();
    window_.reset();
}

void RtTests::checkValidation() {
    const QString fresh = test::fresh_validation_messages(*window_, seen_);
    QVERIFY2(fresh.isEmpty(), qPrintable(fresh));
}

void RtTests::commandLineTakesRt() {
    CommandLine cl;
    QString error;
    QVERIFY(parse_command_line({QStringLiteral("sherpa")}, cl, error));
    QVERIFY(cl.ray_tracing); // default on where the device has it
    QVERIFY(parse_command_line(
        {QStringLiteral("sherpa"), QStringLiteral("--rt"), QStringLiteral("off")}, cl, error));
    QVERIFY(!cl.ray_tracing);
    QVERIFY(!parse_command_line(
        {QStringLiteral("sherpa"), QStringLiteral("--rt"), QStringLiteral("maybe")}, cl, error));
    QVERIFY(error.contains(QStringLiteral("--rt")));
    QVERIFY(parse_command_line({QStringLiteral("sherpa"), QStringLiteral("--mode"),
                                QStringLiteral("difference"), QStringLiteral("--compare-with"),
                                QStringLiteral("view:uv0")},
                               cl, error));
    QCOMPARE(cl.mode, QStringLiteral("difference"));
    QVERIFY(!parse_command_line(
        {QStringLiteral("sherpa"), QStringLiteral("--mode"), QStringLiteral("blend")}, cl, error));
    QVERIFY(!parse_command_line(
        {QStringLiteral("sherpa"), QStringLiteral("--compare-with"), QStringLiteral("view:nope")},
        cl, error));
}

void RtTests::accelerationDockListsBlasAndSelectsMesh() {
    MainWindow& w = *window_;
    QVERIFY(test::load(w, test::asset(QStringLiteral("2CylinderEngine"))));
    AccelerationDock& dock = *w.docks().acceleration;
    AccelerationModel& model = *dock.model();
    // Handed over from the render thread after the upload: one BLAS per glTF mesh.
    const scene::Scene& scene = *w.context().scene();
    std::set<std::uint32_t> gltf_meshes;
    for (const scene::Mesh& m : scene.meshes) gltf_meshes.insert(m.group_id);
    QTRY_COMPARE_WITH_TIMEOUT(model.rowCount(), static_cast<int>(gltf_meshes.size()), 30000);
    std::uint64_t triangles = 0;
    for (const scene::Mesh& m : scene.meshes) triangles += m.indices.size() / 3;
    QCOMPARE(model.stats()->blas_triangles(), triangles);
    QVERIFY(dock.summaryText().contains(QStringLiteral("%1 BLAS").arg(gltf_meshes.size())));
    for (int r = 0; r < model.rowCount(); ++r) {
        QVERIFY(!model.index(r, AccelerationModel::MeshColumn).data().toString().isEmpty());
        QVERIFY(model.stats()->blas[static_cast<std::size_t>(r)].compacted_bytes > 0);
    }

    // Selecting a row selects a primitive of that glTF mesh (the scene tree's path).
    const int row = model.rowCount() / 2;
    const int gltf_mesh = model.index(row, 0).data(AccelerationModel::MeshRole).toInt();
    dock.view()->setCurrentIndex(model.index(row, 0));
    const Selection& sel = w.context().selection().current();
    QVERIFY(sel.mesh >= 0);
    QCOMPARE(static_cast<int>(scene.meshes[static_cast<std::size_t>(sel.mesh)].group_id),
             gltf_mesh);
    QVERIFY(sel.node >= 0);
    QVERIFY(w.selection().selectedInstance() >= 0); // the viewport highlights it
    // And back: a primitive selected elsewhere moves the dock's current row.
    const int other = (row + 1) % model.rowCount();
    const int other_mesh = model.index(other, 0).data(AccelerationModel::MeshRole).toInt();
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        if (static_cast<int>(scene.meshes[m].group_id) == other_mesh) {
            QSignalSpy none(&dock, &AccelerationDock::selectMeshRequested);
            Q_EMIT w.docks().sceneTree->selectMeshRequested(static_cast<int>(m), -1);
            QCOMPARE(dock.view()->currentIndex().row(), other);
            QCOMPARE(none.count(), 0); // no echo
            break;
        }
    checkValidation();
}

void RtTests::rtOffBuildsNothing() {
    // --rt off: a device without ray tracing, no structures, the dock says why.
    MainWindow off(&vulkan_, nullptr, false);
    off.show();
    QVERIFY(QTest::qWaitForWindowExposed(&off));
    QVERIFY(test::load(off, test::asset(QStringLiteral("Box"))));
    QVERIFY(!off.frames().rayTracing());
    QTRY_VERIFY_WITH_TIMEOUT(
        off.docks().acceleration->summaryText().contains(QStringLiteral("--rt off")), 10000);
    QCOMPARE(off.docks().acceleration->model()->rowCount(), 0);
    QVERIFY(!off.docks().acceleration->model()->stats());
    // The ray-traced mode is refused there, never drawn: back to raster.
    off.views().setDebugView(QStringLiteral("normal"), false);
    off.comparison().state().setMode(ViewportMode::RayTraced);
    test::viewport_shot(off);
    QTRY_COMPARE_WITH_TIMEOUT(off.comparison().state().comparison().mode, ViewportMode::Raster,
                              10000);
    qsizetype seen = 0;
    const QString fresh = test::fresh_validation_messages(off, seen);
    QVERIFY2(fresh.isEmpty(), qPrintable(fresh));
}

void RtTests::cleanup() {
    if (!window_) return;
    window_->comparison().state().setMode(ViewportMode::Raster);
    window_->views().setDebugView(QStringLiteral("lit"), false);
}

void RtTests::rayTracedModeDrawsRtFrames() {
    MainWindow& w = *window_;
    QVERIFY(test::load(w, test::asset(QStringLiteral("Suzanne"))));
    w.selection().pickAt(QPointF(-0.99, 0.99)); // nothing selected: no highlight on the raster side
    QVERIFY(w.views().setDebugView(QStringLiteral("normal"), false));
    const QImage raster = test::viewport_shot(w);
    w.comparison().state().setMode(ViewportMode::RayTraced);
    const QImage rays = test::viewport_shot(w);
    QCOMPARE(w.frames().lastFrame().compare.mode, ViewportMode::RayTraced);
    QCOMPARE(w.comparison().state().comparison().mode, ViewportMode::RayTraced); // not refused
    QVERIFY(w.frames().lastReport().refused.isEmpty());
    // The ray tracer's pass drew it: its timings name it.
    QStringList passes;
    for (int i = 0; i < 4 && !passes.join(' ').contains(QStringLiteral("ray")); ++i) {
        w.frames().renderer()->renderAndWait(w.frames().lastFrame(), w.viewport()->vulkanSurface());
        passes = w.frames().renderer()->call(
            [](GpuViewport& gpu) { return test::last_pass_times(gpu); });
    }
    QVERIFY2(passes.join(' ').contains(QStringLiteral("ray"), Qt::CaseInsensitive),
             qPrintable(passes.join(QStringLiteral(", "))));
    // The same surface as the rasterizer (the engine's exactness check holds >= 99.5%
    // of covered pixels; silhouettes differ by a pixel here and there).
    QVERIFY(covered(rays) > rays.width() * rays.height() / 20);
    const int diff = differing(raster, rays, 0, rays.width());
    QVERIFY2(diff < covered(rays) / 20,
             qPrintable(QStringLiteral("%1 of %2").arg(diff).arg(covered(rays))));
    checkValidation();
}

// Ray-traced mode draws the lit view path traced: at rest the render thread keeps
// adding samples (no new request needed), the count and then the estimated error
// reach the report and the frame label, and the error falls as samples grow.
void RtTests::litIsPathTracedAndAccumulatesAtRest() {
    MainWindow& w = *window_;
    QVERIFY(test::load(w, QStringLiteral("builtin:default")));
    QVERIFY(w.views().setDebugView(QStringLiteral("lit"), false));
    w.comparison().state().setMode(ViewportMode::RayTraced);
    test::viewport_shot(w);
    QCOMPARE(w.comparison().state().comparison().mode, ViewportMode::RayTraced); // not refused
    QTRY_VERIFY2_WITH_TIMEOUT(
        w.frames().lastReport().path_traced && w.frames().lastReport().path_samples >= 6,
        qPrintable(QString::number(w.frames().lastReport().path_samples)), 90000);
    QTRY_VERIFY_WITH_TIMEOUT(w.frames().lastReport().path_error >= 0.0, 60000);
    checkValidation();
}

// KHR_materials_variants in ray-traced mode: the Variants menu switches what the rays
// draw (not refused, not reloaded), the switched rays show what the raster shows, and
// the defaults bring the first image back.
void RtTests::variantMenuSwitchesTheRayTracedFrame() {
    MainWindow& w = *window_;
    QVERIFY(test::load(w, QString::fromUtf8(SHERPA_TEST_DATA_DIR) +
                              QStringLiteral("/material_sweeps/variants.gltf")));
    w.selection().pickAt(QPointF(0.999, 0.999)); // no selection highlight on the raster side
    QVERIFY(w.views().setDebugView(QStringLiteral("base-color"), false));
    w.comparison().state().setMode(ViewportMode::RayTraced);
    const QImage before = test::viewport_shot(w);
    QMenu* variants = nullptr;
    for (QAction* top : w.menuBar()->actions())
        if (top->menu() && top->menu()->title() == QStringLiteral("Va&riants"))
            variants = top->menu();
    QVERIFY(variants);
    const auto* session = w.context().session();
    variants->actions().at(2)->trigger(); // Warm (after the separator)
    QTRY_VERIFY_WITH_TIMEOUT(
        w.docks().log->text().contains(QStringLiteral("Material variant: Warm")), 30000);
    QCOMPARE(w.context().session(), session); // not reloaded
    const QImage warm = test::viewport_shot(w);
    QCOMPARE(w.comparison().state().comparison().mode, ViewportMode::RayTraced); // not refused
    QVERIFY(w.frames().lastReport().refused.isEmpty());
    const int changed = differing(before, warm, 0, warm.width());
    QVERIFY2(changed > 200, qPrintable(QStringLiteral("%1 pixels changed").arg(changed)));
    w.comparison().state().setMode(ViewportMode::Raster);
    const QImage raster = test::viewport_shot(w);
    const int diff = differing(raster, warm, 0, warm.width());
    QVERIFY2(diff < covered(warm) / 20,
             qPrintable(QStringLiteral("%1 of %2").arg(diff).arg(covered(warm))));
    w.comparison().state().setMode(ViewportMode::RayTraced);
    variants->actions().at(0)->trigger(); // back to the defaults
    QTRY_VERIFY_WITH_TIMEOUT(
        w.docks().log->text().contains(QStringLiteral("Material variant: default materials")),
        30000);
    QCOMPARE(differing(before, test::viewport_shot(w), 0, before.width()), 0);
    checkValidation();
}

void RtTests::refusedViewGoesBackToRaster() {
    MainWindow& w = *window_;
    QVERIFY(test::load(w, QStringLiteral("builtin:default")));
    QVERIFY(w.views().setDebugView(QStringLiteral("uv0-checker"),
                                   false)); // derivatives: no ray formula
    const int errors = w.docks().log->errorCount();
    w.comparison().state().setMode(ViewportMode::RayTraced);
    test::viewport_shot(w);
    QTRY_COMPARE_WITH_TIMEOUT(w.comparison().state().comparison().mode, ViewportMode::Raster,
                              10000);
    QVERIFY2(w.docks().log->text().contains(QStringLiteral("The ray tracer cannot draw")),
             qPrintable(w.docks().log->text()));
    QVERIFY(w.docks().log->text().contains(QStringLiteral("uv0-checker")));
    QCOMPARE(w.docks().log->errorCount(), errors); // a warning, and rendering goes on
    const std::uint64_t before = w.viewport()->framesRendered();
    w.viewport()->scheduleFrame();
    QTRY_VERIFY_WITH_TIMEOUT(w.viewport()->framesRendered() > before, 10000);
    checkValidation();
}

// The path tracer's emitters it cannot sample as lights (tests/data/make_emitter_warnings.py):
// each upload with ray tracing on logs why, once, naming the file and the JSON pointer.
void RtTests::emitterWarningsReachTheLog() {
    MainWindow& w = *window_;
    const QString data = QString::fromUtf8(SHERPA_TEST_DATA_DIR) + QLatin1Char('/');
    const std::pair<const char*, const char*> cases[] = {
        {"emitter_animated.gltf", "/animations: the scene animates (1 animation)"},
        {"emitter_variants.gltf", "/meshes/1/primitives/0/extensions/KHR_materials_variants: "
                                  "material variant 0 'Dark' changes which surfaces emit"},
        {"emitter_bad_image.gltf", "/materials/1/emissiveTexture: its image (/images/0, "},
    };
    for (const auto& [file, problem] : cases) {
        const QString path = data + QString::fromUtf8(file);
        const QString line = QStringLiteral("path tracer lights: ") + path + QStringLiteral(": ") +
                             QString::fromUtf8(problem);
        QVERIFY(test::load(w, path));
        QTRY_VERIFY2_WITH_TIMEOUT(w.docks().log->text().contains(line),
                                  qPrintable(w.docks().log->text()), 30000);
        // Toggles that upload the same scene again say it no more.
        QAction* checker = nullptr;
        for (QAction* top : w.menuBar()->actions())
            if (top->menu())
                for (QAction* a : top->menu()->actions())
                    if (a->text() == QStringLiteral("&Missing Textures as Checker")) checker = a;
        QVERIFY(checker);
        checker->trigger();
        test::viewport_shot(w);
        checker->trigger();
        test::viewport_shot(w);
        QCOMPARE(w.docks().log->text().count(line), 1);
    }
    checkValidation();
}

QTEST_MAIN(RtTests)
#include "rt_tests.moc"
