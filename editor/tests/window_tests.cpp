// The editor window end to end under Xvfb: loading, selection across docks,
// cancel, broken files, languages, layout persistence (scene switching: switch_tests.cpp).
#include <QClipboard>
#include <QDockWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTreeView>
#include <QVulkanInstance>
#include <QtTest>

#include "culling_dock.h"
#include "culling_monitor.h"
#include "editor_settings.h"
#include "format_values.h"
#include "gpu_viewport.h"
#include "log_dock.h"
#include "main_window.h"
#include "material_dock.h"
#include "material_fields_model.h"
#include "mesh_dock.h"
#include "render_thread.h"
#include "scene_tree_dock.h"
#include "scene_tree_model.h"
#include "test_assets.h"
#include "texture_dock.h"
#include "texture_table_model.h"
#include "vertex_table_model.h"
#include "viewport_window.h"
#include "window_test_support.h"

#include <sherpa/render/debug_views.h>

using namespace sherpa;
using namespace sherpa::editor;

using test::kLoadTimeoutMs;
using test::load;

class WindowTests : public QObject {
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
    void opensEveryAsset();
    void selectionReachesEveryDock();
    void pickingSelectsInTheTree();
    void failedLoadKeepsTheScene();
    void cancelKeepsTheScene();
    void languagesSwitchAtRuntime();
    void viewMenuIsTheEngineTable();
    void layoutIsSavedAndRestored();

private:
    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_validation_ = 0;
};

void WindowTests::initTestCase() {
    window_ = test::open_validated_window(vulkan_);
    QVERIFY(window_);
}

void WindowTests::opensEveryAsset() {
    for (const QString& name : test::all_assets()) {
        QVERIFY2(load(*window_, test::asset(name)), qPrintable(name));
        const scene::Scene* s = window_->context().scene();
        QCOMPARE(window_->context().sceneSpec(), test::asset(name));
        // Scenes, then skins and animations.
        QCOMPARE(window_->docks().sceneTree->model()->rowCount(),
                 static_cast<int>(s->scenes.size() + s->skins.size() + s->animations.size()));
        QCOMPARE(window_->docks().textures->model()->rowCount(),
                 static_cast<int>(s->textures.size()));
        QCOMPARE(test::culling_monitor(*window_).history().latest()->cpu.total,
                 s->instances.size());
    }
}

void WindowTests::selectionReachesEveryDock() {
    QVERIFY(load(*window_, test::asset(QStringLiteral("DamagedHelmet"))));
    const scene::Scene& s = *window_->context().scene();
    // Select through the tree view as a user would: the node's primitive row.
    QTreeView* tree = window_->docks().sceneTree->view();
    const QModelIndex node = tree->model()->index(0, 0, tree->model()->index(0, 0));
    QVERIFY(node.isValid());
    tree->setCurrentIndex(node);
    QCOMPARE(window_->context().selection().current().node, 0);
    const int mesh = window_->context().selection().current().mesh;
    QVERIFY(mesh >= 0);
    QCOMPARE(window_->docks().mesh->vertices()->rowCount(),
             static_cast<int>(s.meshes[static_cast<std::size_t>(mesh)].vertices.size()));
    QCOMPARE(window_->docks().material->model()->rowCount(), 14);
    QCOMPARE(window_->docks().material->model()->textureOfRow(6),
             s.materials[0].base_color.texture);
    // Jump to a vertex: the table scrolls there and the selection says so.
    window_->docks().mesh->jumpToVertex(12345);
    QCOMPARE(window_->context().selection().current().vertex, 12345);
    // Tangent comparison runs off the UI thread and fills the sortable column.
    QSignalSpy ready(window_->docks().mesh, &MeshDock::tangentErrorsReady);
    window_->docks().mesh->computeTangentErrors();
    QVERIFY(ready.wait(kLoadTimeoutMs));
    QVERIFY(window_->docks()
                .mesh->vertices()
                ->data(window_->docks().mesh->vertices()->index(
                           0, VertexTableModel::TangentErrorColumn),
                       Qt::DisplayRole)
                .toString() != QStringLiteral("—"));
    // Numbers show six significant digits; Ctrl+C copies all nine of the float.
    QTableView* vertices = window_->docks().mesh->vertexView();
    const QAbstractItemModel* vm = vertices->model();
    QModelIndex rounded;
    for (int row = 0; row < 64 && !rounded.isValid(); ++row)
        for (int c = VertexTableModel::PosX; c <= VertexTableModel::PosZ; ++c) {
            const QModelIndex i = vm->index(row, c);
            if (i.data(format::kExactTextRole).toString() != i.data().toString()) {
                rounded = i;
                break;
            }
        }
    QVERIFY2(rounded.isValid(), "a DamagedHelmet position needs more than six digits");
    QVERIFY(rounded.data().toString().size() <
            rounded.data(format::kExactTextRole).toString().size());
    vertices->setCurrentIndex(rounded);
    vertices->setFocus();
    QApplication::clipboard()->clear();
    QTest::keyClick(vertices, Qt::Key_C, Qt::ControlModifier);
    QCOMPARE(QApplication::clipboard()->text(), rounded.data(format::kExactTextRole).toString());
    QCOMPARE(QApplication::clipboard()->text().toFloat(),
             rounded.data(format::kExactTextRole).toString().toFloat());
    // Filter the tree: only matching names (and their ancestors) stay.
    window_->docks().sceneTree->setFilter(QStringLiteral("no such node"));
    QCOMPARE(tree->model()->rowCount(), 0);
    window_->docks().sceneTree->setFilter(QString());
    QCOMPARE(tree->model()->rowCount(), static_cast<int>(s.scenes.size()));
}

void WindowTests::pickingSelectsInTheTree() {
    QVERIFY(load(*window_, test::asset(QStringLiteral("Duck"))));
    const int instance =
        window_->selection().pickAt(QPointF(0.0, 0.0)); // framed: the duck is in the middle
    QVERIFY(instance >= 0);
    const int node = static_cast<int>(
        window_->context().scene()->instances[static_cast<std::size_t>(instance)].node_id);
    QCOMPARE(window_->context().selection().current().node, node);
    QVERIFY(window_->context().selection().current().triangle >= 0);
    const QModelIndex current = window_->docks().sceneTree->view()->currentIndex();
    QCOMPARE(current.data(SceneTreeModel::NodeRole).toInt(), node);
    QCOMPARE(window_->selection().pickAt(QPointF(0.99, 0.99)),
             -1); // a corner shows only background
    QCOMPARE(window_->context().selection().current().node, -1);
}

void WindowTests::failedLoadKeepsTheScene() {
    QVERIFY(load(*window_, test::asset(QStringLiteral("Box"))));
    const scene::Scene* before = window_->context().scene();
    const int errors = window_->docks().log->errorCount();
    for (const char* broken : {"invalid_json.gltf", "truncated.glb", "missing_buffer.gltf"}) {
        const QString path = QStringLiteral(SHERPA_TEST_DATA_DIR "/") + QLatin1String(broken);
        QVERIFY(!load(*window_, path));
        QCOMPARE(window_->context().scene(), before);
        QCOMPARE(window_->context().sceneSpec(), test::asset(QStringLiteral("Box")));
    }
    QCOMPARE(window_->docks().log->errorCount(), errors + 3);
    QVERIFY(!load(*window_, QStringLiteral("/no/such/file.gltf")));
    QCOMPARE(window_->context().scene(), before);
    QVERIFY(window_->statusBar()->currentMessage().contains(
        QLatin1String("the current scene is kept")));
    // With nothing open, the failure must not claim that a scene is kept.
    window_->loads().closeScene();
    QVERIFY(!load(*window_, QStringLiteral(SHERPA_TEST_DATA_DIR "/png_renamed.gltf")));
    QVERIFY(window_->statusBar()->currentMessage().contains(QLatin1String("no scene is open")));
    bool dialog_says_so = false;
    for (const QMessageBox* box : window_->findChildren<QMessageBox*>())
        dialog_says_so |= box->text().contains(QLatin1String("No scene is open")) &&
                          box->text().contains(QLatin1String("starts with PNG image bytes")) &&
                          !box->text().contains(QLatin1String("kept"));
    QVERIFY(dialog_says_so);
}

void WindowTests::cancelKeepsTheScene() {
    QVERIFY(load(*window_, test::asset(QStringLiteral("Box"))));
    const scene::Scene* before = window_->context().scene();
    QSignalSpy loaded(&window_->loads(), &LoadController::sceneLoaded);
    QSignalSpy canceled(&window_->loads(), &LoadController::loadCanceled);
    window_->loads().openScene(test::asset(QStringLiteral("DamagedHelmet")));
    window_->loads().cancelLoad();
    QCOMPARE(canceled.count(), 1);
    QVERIFY(window_->docks().log->text().contains(QStringLiteral("cancelled")));
    QTest::qWait(1500); // the worker finishes in the background; its result must be dropped
    QCOMPARE(loaded.count(), 0);
    QCOMPARE(window_->context().scene(), before);
    // A new load after a cancel works normally.
    QVERIFY(load(*window_, QStringLiteral("builtin:grid?n=10")));
}

void WindowTests::languagesSwitchAtRuntime() {
    const auto file_menu = [this] { return window_->menuBar()->actions().at(0)->text(); };
    QVERIFY(window_->setLanguage(QStringLiteral("de")));
    QCOMPARE(file_menu(), QStringLiteral("&Datei"));
    QCOMPARE(window_->docks().sceneTree->windowTitle(), QStringLiteral("Szenenbaum"));
    // The scene tree's root item ("Scene 0") is translated too.
    const auto root = [this] {
        const QAbstractItemModel* m = window_->docks().sceneTree->model();
        return m->index(0, 0).data().toString();
    };
    QVERIFY2(root().startsWith(QStringLiteral("Szene ")), qPrintable(root()));
    QVERIFY(window_->setLanguage(QStringLiteral("zh_CN")));
    QCOMPARE(file_menu(), QStringLiteral("文件(&F)"));
    QCOMPARE(window_->docks().culling->windowTitle(), QStringLiteral("剔除统计"));
    QVERIFY2(root().startsWith(QStringLiteral("场景 ")), qPrintable(root()));
    QCOMPARE(window_->docks()
                 .textures->model()
                 ->headerData(0, Qt::Horizontal, Qt::DisplayRole)
                 .toString(),
             QStringLiteral("纹理"));
    QVERIFY(!window_->setLanguage(QStringLiteral("xx")));
    QVERIFY(window_->setLanguage(QStringLiteral("en")));
    QCOMPARE(file_menu(), QStringLiteral("&File"));
}

// View › Debug View and View › Overlays list the engine's table (sherpa/gpu/
// debug_views.h) in order, with its labels translated; each view entry selects it.
void WindowTests::viewMenuIsTheEngineTable() {
    const auto submenu = [this](const QString& title) -> QMenu* {
        for (QAction* top : window_->menuBar()->actions())
            if (top->menu())
                for (QAction* a : top->menu()->actions())
                    if (a->menu() && a->menu()->title() == title) return a->menu();
        return nullptr;
    };
    QVERIFY(window_->setLanguage(QStringLiteral("de")));
    QMenu* views = submenu(QStringLiteral("&Debug-Ansicht"));
    QVERIFY(views);
    const QList<QAction*> view_actions = views->actions();
    // The rays-only views (ao, shadow-error) are not listed; the rest in table order.
    std::vector<const render::DebugViewInfo*> raster;
    for (const render::DebugViewInfo& v : render::kDebugViews)
        if (render::raster_view(v.id)) raster.push_back(&v);
    const std::size_t raster_views = raster.size();
    QCOMPARE(view_actions.size(), qsizetype(raster_views));
    QCOMPARE(view_actions.at(0)->text(), QStringLiteral("Beleuchtet")); // "Lit", translated
    for (std::size_t i = 0; i < raster_views; ++i)
        QCOMPARE(view_actions.at(qsizetype(i))->text(),
                 QCoreApplication::translate(render::kViewLabelContext, raster[i]->label));
    QVERIFY(window_->setLanguage(QStringLiteral("en")));
    for (std::size_t i = 0; i < raster_views; ++i) {
        view_actions.at(qsizetype(i))->trigger();
        QCOMPARE(window_->views().debugView(), QString::fromLatin1(raster[i]->name.data()));
        QVERIFY(view_actions.at(qsizetype(i))->isChecked());
    }
    QVERIFY(window_->views().setDebugView(QStringLiteral("lit"), false));
    QMenu* overlays = submenu(QStringLiteral("&Overlays"));
    QVERIFY(overlays);
    QStringList expected;
    for (const render::OverlayEntry& o : render::kOverlays)
        if (o.label) expected << QString::fromLatin1(o.label);
    QStringList shown;
    for (QAction* a : overlays->actions()) shown << a->text();
    QCOMPARE(shown, expected);
}

void WindowTests::layoutIsSavedAndRestored() {
    window_->docks().culling->setFloating(true);
    window_->docks().log->hide();
    window_->close(); // saves geometry and dock state
    MainWindow second(nullptr);
    QVERIFY(second.docks().culling->isFloating());
    QVERIFY(second.docks().log->isHidden());
    QVERIFY(!EditorSettings().get(setting::kRecentFiles).isEmpty());
    // The last file loaded (built-in scenes are not files, a cancelled load is not one).
    QCOMPARE(EditorSettings().get(setting::kRecentFiles).value(0),
             test::asset(QStringLiteral("Box")));
    second.docks().culling->setFloating(false);
    second.docks().log->show();
    second.close();
}

QTEST_MAIN(WindowTests)
#include "window_tests.moc"
