// The Validation dock (context in: the scene's messages; action out: a JSON pointer)
// and what a message selects: the object it names, highlighted in the viewport, with
// the dock that shows it in front; markers in the scene tree; the material dock's
// word on extensions that are not drawn.
#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QTreeView>
#include <QVulkanInstance>
#include <QtTest>

#include "log_dock.h"
#include "main_window.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "scene_tree_dock.h"
#include "scene_tree_model.h"
#include "test_assets.h"
#include "texture_dock.h"
#include "validation_dock.h"
#include "validation_model.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

const QString kGlass = QStringLiteral(SHERPA_TEST_DATA_DIR "/unsupported_material_extensions.gltf");

// Whether `dock` is the one shown of its tab group (raised), not behind another tab.
bool in_front(QDockWidget* dock) {
    return dock->isVisible() && !dock->visibleRegion().isEmpty();
}

// Every row of a tree model, depth-first, as its display text.
void collect(const QAbstractItemModel& m, const QModelIndex& parent, QStringList& out) {
    for (int r = 0; r < m.rowCount(parent); ++r) {
        const QModelIndex i = m.index(r, 0, parent);
        out << i.data().toString();
        collect(m, i, out);
    }
}

} // namespace

class ValidationTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void messagesAreGroupedBySeverityAndCode();
    void filterMatchesCodePointerAndText();
    void unsupportedExtensionSelectsTheMaterial();
    void pointersSelectNodesPrimitivesVerticesAndTextures();
    void sceneTreeMarksObjectsWithMessages();
    void dockHidesForFilesWithoutMessages();

private:
    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> w_;
    qsizetype validation_seen_ = 0;
};

void ValidationTests::initTestCase() {
    test::isolate_settings();
    qputenv("SHERPA_VALIDATION", "1");
    GpuViewport::configureInstance(vulkan_);
    vulkan_.create();
}

void ValidationTests::init() {
    w_ = test::open_validated_window(vulkan_);
    QVERIFY(w_);
    validation_seen_ = 0;
}

void ValidationTests::cleanup() {
    if (w_) {
        const QString messages = test::fresh_validation_messages(*w_, validation_seen_);
        QVERIFY2(messages.isEmpty(), qPrintable(messages));
    }
    w_.reset();
}

void ValidationTests::messagesAreGroupedBySeverityAndCode() {
    QVERIFY(test::load(*w_, kGlass));
    const ValidationModel& m = *w_->docks().validation->model();
    QCOMPARE(m.messageCount(), std::size_t(6));
    QStringList rows;
    collect(m, {}, rows);
    // The vendor extensions also carry the Khronos validator's information that it
    // cannot check them.
    const QStringList expected = {
        QStringLiteral("Warnings (4)"),
        QStringLiteral("SHERPA_EXTENSION_NOT_DRAWN (2)"),
        QStringLiteral("/extensionsUsed/1"),
        QStringLiteral("/extensionsUsed/2"),
        QStringLiteral("SHERPA_MATERIAL_EXTENSION_NOT_DRAWN (2)"),
        QStringLiteral("/materials/0/extensions/ADOBE_materials_clearcoat_specular"),
        QStringLiteral("/materials/0/extensions/ADOBE_materials_thin_transparency"),
        QStringLiteral("Information (2)"),
        QStringLiteral("UNSUPPORTED_EXTENSION (2)"),
        QStringLiteral("/extensionsUsed/1"),
        QStringLiteral("/extensionsUsed/2"),
    };
    QCOMPARE(rows, expected);
    const QModelIndex first = m.indexOfPointer(QStringLiteral("/extensionsUsed/1"));
    QVERIFY(first.data(ValidationModel::MessageRole)
                .toString()
                .contains(QStringLiteral("ADOBE_materials_thin_transparency")));
    // The severity group carries the severity's marker.
    QVERIFY(!m.index(0, 0).data(Qt::DecorationRole).value<QIcon>().isNull());
    // The editor's log has the same warnings as info and render.
    QVERIFY(w_->docks().log->text().contains(
        QStringLiteral("ADOBE_materials_thin_transparency is not implemented by Sherpa")));
}

void ValidationTests::filterMatchesCodePointerAndText() {
    QVERIFY(test::load(*w_, kGlass));
    ValidationDock& dock = *w_->docks().validation;
    auto* proxy = qobject_cast<QAbstractItemModel*>(dock.view()->model());
    QVERIFY(proxy);
    auto leaves = [proxy] {
        QStringList rows;
        collect(*proxy, {}, rows);
        return rows.filter(QStringLiteral("/"));
    };
    // The text of two (its warning and its information), the pointer of another.
    dock.setFilter(QStringLiteral("clearcoat_specular"));
    QCOMPARE(
        leaves(),
        (QStringList{QStringLiteral("/extensionsUsed/2"),
                     QStringLiteral("/materials/0/extensions/ADOBE_materials_clearcoat_specular"),
                     QStringLiteral("/extensionsUsed/2")}));
    dock.setFilter(QStringLiteral("sherpa_material")); // a code: all of its messages
    QCOMPARE(leaves().size(), 2);
    dock.setFilter(QStringLiteral("no such thing"));
    QVERIFY(leaves().isEmpty());
    dock.setFilter({});
    QCOMPARE(leaves().size(), 6); // four warnings and two of the validator's information
}

void ValidationTests::unsupportedExtensionSelectsTheMaterial() {
    QVERIFY(test::load(*w_, kGlass));
    ValidationDock& dock = *w_->docks().validation;
    QVERIFY(dock.isVisible());
    QSignalSpy activated(&dock, &ValidationDock::messageActivated);
    QVERIFY(dock.activatePointer(
        QStringLiteral("/materials/0/extensions/ADOBE_materials_thin_transparency")));
    QCOMPARE(activated.count(), 1);
    const scene::Scene& scene = *w_->context().scene();
    QCOMPARE(w_->context().selection().current().material, 0);
    // The primitive drawn with it is selected: the viewport highlights its instance.
    QCOMPARE(w_->context().selection().current().mesh, scene.mesh_primitives[0][0]);
    QVERIFY(w_->selection().selectedInstance() >= 0);
    QVERIFY(in_front(w_->docks().material));
    QVERIFY2(in_front(&dock),
             qPrintable(
                 QStringLiteral("the list stays in view: visible %1 %2x%3 region %4 tabbed with %5")
                     .arg(dock.isVisible())
                     .arg(dock.width())
                     .arg(dock.height())
                     .arg(dock.visibleRegion().isEmpty())
                     .arg(w_->tabifiedDockWidgets(&dock).size())));
    const QString warning = w_->docks().material->notDrawnText();
    QVERIFY2(warning.contains(QStringLiteral("ADOBE_materials_clearcoat_specular")) &&
                 warning.contains(QStringLiteral("ADOBE_materials_thin_transparency")),
             qPrintable(warning));
    QVERIFY(dock.detailText().contains(QStringLiteral("material 0")));
    // The extension's name in extensionsUsed leads to a material that uses it too.
    QVERIFY(w_->selection().showPointer(QStringLiteral("/extensionsUsed/1")));
    QCOMPARE(w_->context().selection().current().material, 0);
    // The plain material (emissive strength, drawn) says nothing.
    QVERIFY(w_->selection().showPointer(QStringLiteral("/materials/1")));
    QCOMPARE(w_->context().selection().current().material, 1);
    QVERIFY(w_->docks().material->notDrawnText().isEmpty());
}

void ValidationTests::pointersSelectNodesPrimitivesVerticesAndTextures() {
    QVERIFY(test::load(*w_, test::asset(QStringLiteral("RiggedSimple"))));
    // A skin joint: its node, with the scene tree in front.
    QVERIFY(w_->selection().showPointer(QStringLiteral("/skins/0/joints/1")));
    QCOMPARE(w_->context().selection().current().node, 3);
    QVERIFY(in_front(w_->docks().sceneTree));
    // An animation channel: its target node.
    QVERIFY(w_->selection().showPointer(QStringLiteral("/animations/0/channels/1/target")));
    QCOMPARE(w_->context().selection().current().node, 2);
    // An accessor with an element named in the text (as the Khronos validator words
    // data errors): the primitive that reads it, that vertex's row, the mesh dock.
    QVERIFY(w_->selection().showPointer(
        QStringLiteral("/accessors/3"),
        QStringLiteral("Accessor element at index 7 is NaN or Infinity.")));
    const scene::Scene& rigged = *w_->context().scene();
    QCOMPARE(w_->context().selection().current().mesh, rigged.mesh_primitives[0][0]);
    QCOMPARE(w_->context().selection().current().node, 1);
    QCOMPARE(w_->context().selection().current().vertex, 7);
    QVERIFY(in_front(w_->docks().mesh));
    QVERIFY(w_->selection().selectedInstance() >= 0);
    // Indices: element 7 is in triangle 2.
    QVERIFY(w_->selection().showPointer(
        QStringLiteral("/accessors/0"),
        QStringLiteral("Indices accessor element at index 7 has vertex index "
                       "99 that exceeds number of available vertices 3.")));
    QCOMPARE(w_->context().selection().current().triangle, 2);
    // What the scene lacks selects nothing and says so.
    QVERIFY(!w_->selection().showPointer(QStringLiteral("/nodes/99")));
    QVERIFY(!w_->selection().showPointer(QStringLiteral("not a pointer")));

    QVERIFY(test::load(*w_, test::asset(QStringLiteral("BoxTextured"))));
    QVERIFY(w_->selection().showPointer(QStringLiteral("/images/0")));
    QCOMPARE(w_->context().selection().current().texture, 0);
    QVERIFY(in_front(w_->docks().textures));
    QVERIFY(w_->selection().showPointer(QStringLiteral("/meshes/0/primitives/0/indices")));
    QCOMPARE(w_->context().selection().current().mesh,
             w_->context().scene()->mesh_primitives[0][0]);
    QVERIFY(in_front(w_->docks().mesh));
}

void ValidationTests::sceneTreeMarksObjectsWithMessages() {
    QVERIFY(test::load(*w_, kGlass));
    SceneTreeModel& tree = *w_->docks().sceneTree->model();
    auto marked = [&tree](const QModelIndex& i) {
        return !i.siblingAtColumn(SceneTreeModel::NameColumn)
                    .data(Qt::DecorationRole)
                    .value<QIcon>()
                    .isNull();
    };
    const QModelIndex glass = tree.indexOfNode(0), plain = tree.indexOfNode(1);
    QVERIFY(glass.isValid() && plain.isValid());
    QVERIFY2(marked(glass), "the node draws a material with messages");
    QVERIFY(!marked(plain));
    // Under the Glass node: its primitive, then the material (marked).
    const QModelIndex primitive = tree.index(0, 0, glass);
    const QModelIndex material = tree.index(0, 0, primitive);
    QCOMPARE(material.data(SceneTreeModel::KindRole).toInt(), int(SceneTreeModel::Kind::Material));
    QVERIFY(marked(material));
    QVERIFY(!marked(primitive));
    QVERIFY(!marked(tree.index(0, 0, tree.index(0, 0, plain))));
}

void ValidationTests::dockHidesForFilesWithoutMessages() {
    QVERIFY(test::load(*w_, kGlass));
    QVERIFY(w_->docks().validation->isVisible());
    QVERIFY(test::load(*w_, test::asset(QStringLiteral("Box"))));
    QVERIFY(!w_->docks().validation->isVisible());
    QCOMPARE(w_->docks().validation->model()->rowCount(), 0);
}

QTEST_MAIN(ValidationTests)
#include "validation_tests.moc"
