// Framing, picking and the selection without a window: the camera framed on a scene,
// rays picked against the engine's scene (triangles, lines and points), the
// selection's rules and the order in which a new scene clears it.
#include <QSignalSpy>
#include <QtTest>

#include <sherpa/scene/animation.h>
#include <sherpa/scene/culling_passes.h>

#include "attribute_model.h"
#include "command_line.h"
#include "editor_context.h"
#include "format_values.h"
#include "frame_pacing.h"
#include "material_fields_model.h"
#include "orbit_camera.h"
#include "picking.h"
#include "resolution_scale.h"
#include "scene_load_job.h"
#include "scene_tree_model.h"
#include "tangent_error.h"
#include "test_assets.h"
#include "texture_table_model.h"
#include "triangle_table_model.h"
#include "vertex_table_model.h"
#include "viewport_presenter.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

QString display(const QAbstractItemModel& m, int row, int column, const QModelIndex& parent = {}) {
    return m.data(m.index(row, column, parent), Qt::DisplayRole).toString();
}

} // namespace

class SelectionTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QVERIFY(!test::all_assets().isEmpty()); }
    void frameKeepsTheBoxInView();
    void pickHitsTheInstanceUnderTheRay();
    void pickHitsLinesAndPointsWithinACone();
    void selectionFollowsActions();
    void newSceneClearsSelectionBeforeSayingSo();
};

void SelectionTests::frameKeepsTheBoxInView() {
    OrbitCamera cam;
    cam.setAspect(1.5f);
    const core::Aabb box = core::Aabb::from_min_max({-3, -1, -2}, {5, 4, 1});
    cam.orbit(40, -25);
    cam.frame(box);
    const glm::mat4 vp = cam.pose().spec().view_projection();
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 p((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                          (c & 4) ? box.max.z : box.min.z);
        const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
        QVERIFY(clip.w > 0.0f);
        QVERIFY(std::abs(clip.x / clip.w) <= 1.0001f);
        QVERIFY(std::abs(clip.y / clip.w) <= 1.0001f);
    }
    scene::CameraSpec spec;
    std::string error;
    QVERIFY2(parse_camera_spec(cam.pose().toString(), spec, error), error.c_str());
}

void SelectionTests::pickHitsTheInstanceUnderTheRay() {
    const LoadOutcome out = SceneLoadJob::loadNow(QStringLiteral("builtin:default"));
    QVERIFY(out.session);
    const scene::Scene& s = *out.session->scene;
    OrbitCamera cam;
    cam.frame(s.bounds);
    // Aim at the centre of a solid instance from outside the scene: it (or something in
    // front of it) must be hit, and the hit must lie on the ray inside that instance's box.
    for (std::size_t i = 0; i < s.instances.size(); i += 7) {
        const core::Aabb& box = s.instances[i].world_bounds;
        const glm::vec3 dir = glm::normalize(box.center() - cam.pose().eye());
        const PickHit hit = pick(s, cam.pose().eye(), dir, [](std::size_t) { return true; });
        QVERIFY(hit);
        const glm::vec3 p = cam.pose().eye() + dir * hit.distance;
        const core::Aabb& hit_box =
            s.instances[static_cast<std::size_t>(hit.instance)].world_bounds;
        QVERIFY(glm::all(glm::greaterThanEqual(p, hit_box.min - 1e-3f)) &&
                glm::all(glm::lessThanEqual(p, hit_box.max + 1e-3f)));
    }
    // Hidden instances are not pickable.
    const PickHit none =
        pick(s, cam.pose().eye(), cam.pose().forward(), [](std::size_t) { return false; });
    QVERIFY(!none);
}

// A line strip along x and a point above it: rays passing within the pick cone hit
// them (segment / point index in `triangle`), rays further off do not.
void SelectionTests::pickHitsLinesAndPointsWithinACone() {
    scene::Scene s;
    auto add = [&](scene::PrimitiveMode mode, std::vector<glm::vec3> positions,
                   std::vector<std::uint32_t> indices) {
        scene::Mesh m;
        m.source_mode = mode;
        for (glm::vec3 p : positions) {
            m.vertices.push_back(scene::Vertex{});
            m.vertices.back().position = p;
            m.local_bounds.expand(p);
        }
        m.indices = std::move(indices);
        scene::MeshInstance inst;
        inst.mesh_id = static_cast<std::uint32_t>(s.meshes.size());
        inst.world_bounds = m.local_bounds;
        s.meshes.push_back(std::move(m));
        s.instances.push_back(inst);
    };
    add(scene::PrimitiveMode::LineStrip, {{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}}, {0, 1, 1, 2});
    add(scene::PrimitiveMode::Points, {{0, 2, 0}}, {0});
    const glm::vec3 down(0, 0, -1);
    auto all = [](std::size_t) { return true; };
    const PickHit line = pick(s, {0.5f, 0.02f, 5.0f}, down, all);
    QCOMPARE(line.instance, std::int64_t{0});
    QCOMPARE(line.triangle, std::int64_t{1}); // the second segment
    QVERIFY(std::abs(line.distance - 5.0f) < 1e-3f);
    QVERIFY(!pick(s, {0.5f, 0.2f, 5.0f}, down, all)); // 0.2 off at distance 5: outside
    const PickHit point = pick(s, {0.03f, 2.0f, 5.0f}, down, all);
    QCOMPARE(point.instance, std::int64_t{1});
    QCOMPARE(point.triangle, std::int64_t{0});
    QVERIFY(!pick(s, {0.3f, 2.0f, 5.0f}, down, all));
    // The mesh dock's element table lists them as what they are: segments (two
    // vertices, a length) and points (one vertex, no area).
    auto shared = std::make_shared<const scene::Scene>(std::move(s));
    TriangleTableModel elements;
    elements.setMesh(MeshRef{shared, 0});
    QCOMPARE(elements.rowCount(), 2);
    QCOMPARE(display(elements, 1, TriangleTableModel::V0), QStringLiteral("1"));
    QCOMPARE(display(elements, 1, TriangleTableModel::V1), QStringLiteral("2"));
    QVERIFY(display(elements, 1, TriangleTableModel::V2).isEmpty());
    QCOMPARE(display(elements, 1, TriangleTableModel::AreaColumn), format::number(1.0));
    elements.setMesh(MeshRef{shared, 1});
    QCOMPARE(elements.rowCount(), 1);
    QVERIFY(display(elements, 0, TriangleTableModel::V1).isEmpty());
    QVERIFY(display(elements, 0, TriangleTableModel::AreaColumn).isEmpty());
}

void SelectionTests::selectionFollowsActions() {
    const LoadOutcome out = SceneLoadJob::loadNow(test::asset(QStringLiteral("Duck")));
    EditorContext context;
    SceneTreeModel tree(context);
    context.setSession(out.session);
    QSignalSpy selection(&context.selection(), &SceneSelection::changed);
    int mesh_node = -1;
    for (std::size_t n = 0; n < out.session->scene->nodes.size(); ++n)
        if (out.session->scene->nodes[n].mesh >= 0) mesh_node = static_cast<int>(n);
    QVERIFY(mesh_node >= 0);
    context.selection().selectNode(mesh_node);
    QCOMPARE(selection.count(), 1);
    QCOMPARE(context.selection().current().node, mesh_node);
    QVERIFY(context.selection().current().mesh >= 0);
    QCOMPARE(
        context.selection().current().material,
        static_cast<int>(
            out.session->scene->meshes[static_cast<std::size_t>(context.selection().current().mesh)]
                .material_id));
    // Unticking a node is an action out of the model, applied by the owner of the context.
    QSignalSpy requested(&tree, &SceneTreeModel::visibilityRequested);
    QVERIFY(tree.setData(tree.indexOfNode(mesh_node), Qt::Unchecked, Qt::CheckStateRole));
    QCOMPARE(requested.count(), 1);
    QVERIFY(context.visibility().nodeVisible(mesh_node));
    context.visibility().setNodeVisible(mesh_node, false);
    QCOMPARE(tree.indexOfNode(mesh_node).data(Qt::CheckStateRole).toInt(),
             static_cast<int>(Qt::Unchecked));
    for (std::size_t i = 0; i < out.session->scene->instances.size(); ++i)
        if (static_cast<int>(out.session->scene->instances[i].node_id) == mesh_node)
            QVERIFY(!context.visibility().instanceVisible(i));
}

// A new scene: while the docks hear sceneReady nothing of the old scene is selected or
// hidden, and the selection's changed() comes after it, once.
void SelectionTests::newSceneClearsSelectionBeforeSayingSo() {
    const LoadOutcome duck = SceneLoadJob::loadNow(test::asset(QStringLiteral("Duck")));
    EditorContext context;
    context.setSession(duck.session);
    context.selection().selectNode(0);
    context.visibility().setNodeVisible(0, false);
    QVERIFY(context.visibility().hidden());
    QStringList heard;
    connect(&context, &EditorContext::sceneReady, &context, [&] {
        heard << QStringLiteral("scene");
        QVERIFY(context.selection().current() == Selection{});
        QVERIFY(!context.visibility().hidden());
        QVERIFY(context.visibility().nodeVisible(0));
    });
    connect(&context.selection(), &SceneSelection::changed, &context,
            [&] { heard << QStringLiteral("selection"); });
    QSignalSpy visibility(&context.visibility(), &NodeVisibility::changed);
    context.setSession(nullptr);
    QCOMPARE(heard, QStringList({QStringLiteral("scene"), QStringLiteral("selection")}));
    QCOMPARE(visibility.count(), 0); // the new scene says it
    // Without a scene, selecting a node selects nothing and hiding hides nothing.
    context.selection().selectNode(0);
    QVERIFY(context.selection().current() == Selection{});
    context.visibility().setNodeVisible(0, false);
    QVERIFY(!context.visibility().hidden());
}

QTEST_MAIN(SelectionTests)
#include "selection_tests.moc"
