// The editor's motion tools (issue 16) against the engine's evaluation: the timeline
// lists the file's animations, scrubbing and the play loop (advance, wrap, stop)
// change the pose it posts, morph weight sliders override the pose's weights, the
// scene tree shows skins, joints and animations, the vertex table JOINTS/WEIGHTS and
// morph deltas; in the window, the frame handed to the renderer carries the pose and
// the selected joint.
#include <QComboBox>
#include <QLabel>
#include <QSortFilterProxyModel>
#include <QTreeView>
#include <QtTest>

#include <sherpa/scene/scene_loader.h>

#include "culling_monitor.h"
#include "editor_context.h"
#include "format_values.h"
#include "main_window.h"
#include "morph_weights_panel.h"
#include "scene_tree_dock.h"
#include "scene_tree_model.h"
#include "test_assets.h"
#include "timeline_dock.h"
#include "vertex_table_model.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

// `name` loaded into `context` (the engine's loader: no textures needed here).
std::shared_ptr<const scene::Scene> load_into(EditorContext& context, const QString& name) {
    scene::LoadResult r = scene::load_scene(test::asset(name).toStdString());
    if (!r) return nullptr;
    std::shared_ptr<const scene::Scene> scene(std::move(r.scene));
    auto session = std::make_shared<SceneSession>();
    session->spec = test::asset(name);
    session->scene = scene;
    context.setSession(std::move(session));
    return scene;
}

bool same_matrix(const glm::mat4& a, const glm::mat4& b) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(a[c][r] - b[c][r]) > 1e-5f) return false;
    return true;
}

} // namespace

class MotionTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void timelineListsTheFilesAnimations();
    void scrubbingChangesThePose();
    void playLoopAdvancesAndWraps();
    void morphSlidersOverrideThePoseWeights();
    void sceneTreeShowsSkinsJointsAndAnimations();
    void vertexTableHasJointsWeightsAndMorphDeltas();
    void windowPostsThePoseAndSelectedJoint();
};

void MotionTests::sceneTreeShowsSkinsJointsAndAnimations() {
    EditorContext context;
    SceneTreeDock dock(context);
    const SceneTreeModel& tree = *dock.model();
    auto scene = load_into(context, QStringLiteral("RiggedSimple"));
    QVERIFY(scene);
    QCOMPARE(scene->skins.size(), 1u);
    QCOMPARE(scene->animations.size(), 1u);
    // Scenes first, then the skin, then the animation.
    const int scenes = static_cast<int>(scene->scenes.size());
    QCOMPARE(tree.rowCount(), scenes + 2);
    auto cell = [&](const QModelIndex& i, int column) {
        return i.siblingAtColumn(column).data().toString();
    };
    const QModelIndex skin = tree.index(scenes, 0);
    QCOMPARE(cell(skin, SceneTreeModel::NameColumn),
             QStringLiteral("Skin 0: %1").arg(QString::fromStdString(scene->skins[0].name)));
    QCOMPARE(cell(skin, SceneTreeModel::TypeColumn), QStringLiteral("skin"));
    QVERIFY(cell(skin, SceneTreeModel::DetailColumn).startsWith(QStringLiteral("2 joints")));
    QCOMPARE(tree.rowCount(skin), static_cast<int>(scene->skins[0].joints.size()));
    for (int r = 0; r < tree.rowCount(skin); ++r) {
        const QModelIndex joint = tree.index(r, 0, skin);
        const std::uint32_t node = scene->skins[0].joints[std::size_t(r)];
        QCOMPARE(cell(joint, SceneTreeModel::TypeColumn), QStringLiteral("joint"));
        QCOMPARE(joint.data(SceneTreeModel::NodeRole).toInt(), static_cast<int>(node));
        // The node's own row in the hierarchy is marked as a joint too.
        QCOMPARE(cell(tree.indexOfNode(static_cast<int>(node)), SceneTreeModel::TypeColumn),
                 QStringLiteral("joint"));
    }
    QCOMPARE(cell(tree.indexOfNode(0), SceneTreeModel::TypeColumn), QStringLiteral("node"));

    const scene::Animation& anim = scene->animations[0];
    const QModelIndex a = tree.index(scenes + 1, 0);
    QCOMPARE(cell(a, SceneTreeModel::TypeColumn), QStringLiteral("animation"));
    QCOMPARE(cell(a, SceneTreeModel::DetailColumn),
             QStringLiteral("%1 s, %2 channels")
                 .arg(double(anim.end - anim.start), 0, 'f', 3)
                 .arg(anim.channels.size()));
    QCOMPARE(tree.rowCount(a), static_cast<int>(anim.channels.size() + anim.samplers.size()));
    const QModelIndex channel = tree.index(1, 0, a);
    QCOMPARE(cell(channel, SceneTreeModel::TypeColumn), QStringLiteral("channel"));
    QVERIFY2(cell(channel, SceneTreeModel::DetailColumn).contains(QStringLiteral("rotation")),
             qPrintable(cell(channel, SceneTreeModel::DetailColumn)));
    const QModelIndex sampler = tree.index(static_cast<int>(anim.channels.size()), 0, a);
    QCOMPARE(cell(sampler, SceneTreeModel::TypeColumn), QStringLiteral("sampler"));
    QCOMPARE(cell(sampler, SceneTreeModel::DetailColumn),
             QStringLiteral("LINEAR, %1 keys").arg(anim.samplers[0].times.size()));
    QVERIFY(sampler.siblingAtColumn(SceneTreeModel::DetailColumn)
                .data(Qt::ToolTipRole)
                .toString()
                .contains(QStringLiteral(" s")));

    // Choosing a joint row selects the joint's node.
    QSignalSpy select(&dock, &SceneTreeDock::selectNodeRequested);
    dock.view()->setCurrentIndex(static_cast<QSortFilterProxyModel*>(dock.view()->model())
                                     ->mapFromSource(tree.index(1, 0, skin)));
    QCOMPARE(select.count(), 1);
    QCOMPARE(select.front().front().toInt(), static_cast<int>(scene->skins[0].joints[1]));
}

void MotionTests::vertexTableHasJointsWeightsAndMorphDeltas() {
    EditorContext context;
    auto rigged = load_into(context, QStringLiteral("RiggedSimple"));
    QVERIFY(rigged);
    VertexTableModel table;
    QCOMPARE(table.columnCount(), static_cast<int>(VertexTableModel::ColumnCount));
    const scene::PrimitiveInfo* skinned = nullptr;
    for (const scene::PrimitiveInfo& p : rigged->primitives)
        if (p.motion >= 0) skinned = &p;
    QVERIFY(skinned);
    table.setMesh({rigged, skinned->engine_mesh});
    QCOMPARE(table.columnCount(), VertexTableModel::ColumnCount + 2);
    QCOMPARE(
        table.headerData(VertexTableModel::ColumnCount, Qt::Horizontal, Qt::DisplayRole).toString(),
        QStringLiteral("JOINTS"));
    QCOMPARE(table.headerData(VertexTableModel::ColumnCount + 1, Qt::Horizontal, Qt::DisplayRole)
                 .toString(),
             QStringLiteral("WEIGHTS"));
    const scene::PrimitiveMotion& motion = rigged->motions[std::size_t(skinned->motion)];
    const scene::Mesh& mesh = rigged->meshes[std::size_t(skinned->engine_mesh)];
    for (int row : {0, table.rowCount() / 2, table.rowCount() - 1}) {
        const auto v = static_cast<std::size_t>(table.vertexOfRow(row));
        const std::int64_t f = table.motionColumns().sourceVertex(v);
        QVERIFY(f >= 0);
        // The file vertex shown is one at the engine vertex's position.
        QCOMPARE(motion.base_positions[std::size_t(f)], mesh.vertices[v].position);
        QStringList joints, weights;
        for (std::uint32_t k = 0; k < motion.influences; ++k) {
            joints << QString::number(motion.joints[std::size_t(f) * motion.influences + k]);
            weights << format::number(motion.weights[std::size_t(f) * motion.influences + k]);
        }
        QCOMPARE(table.index(row, VertexTableModel::ColumnCount).data().toString(),
                 joints.join(QLatin1Char(' ')));
        QCOMPARE(table.index(row, VertexTableModel::ColumnCount + 1).data().toString(),
                 weights.join(QLatin1Char(' ')));
    }
    // Sorting by WEIGHTS orders by the first weight.
    table.sort(VertexTableModel::ColumnCount + 1, Qt::AscendingOrder);
    const double first = table.motionColumns().key(std::size_t(table.vertexOfRow(0)), 1);
    const double last =
        table.motionColumns().key(std::size_t(table.vertexOfRow(table.rowCount() - 1)), 1);
    QVERIFY(first <= last);

    // Morph deltas: one column per target attribute.
    auto morph = load_into(context, QStringLiteral("SimpleMorph"));
    QVERIFY(morph);
    const scene::PrimitiveInfo& p = morph->primitives[0];
    QVERIFY(p.motion >= 0);
    const scene::PrimitiveMotion& m = morph->motions[std::size_t(p.motion)];
    table.setMesh({morph, p.engine_mesh});
    QCOMPARE(table.columnCount(),
             VertexTableModel::ColumnCount + static_cast<int>(m.targets.size()));
    QCOMPARE(table.headerData(VertexTableModel::ColumnCount + 1, Qt::Horizontal, Qt::DisplayRole)
                 .toString(),
             QStringLiteral("Δpos 1"));
    const auto v = static_cast<std::size_t>(table.vertexOfRow(2));
    const auto f = static_cast<std::size_t>(table.motionColumns().sourceVertex(v));
    QCOMPARE(table.index(2, VertexTableModel::ColumnCount + 1).data().toString(),
             format::vec(m.targets[1].position[f]));
    // A static mesh has none.
    auto box = load_into(context, QStringLiteral("Box"));
    table.setMesh({box, 0});
    QCOMPARE(table.columnCount(), static_cast<int>(VertexTableModel::ColumnCount));
}

void MotionTests::timelineListsTheFilesAnimations() {
    EditorContext context;
    TimelineDock dock(context);
    QCOMPARE(dock.findChild<QComboBox*>()->count(), 1); // "No animation"
    QVERIFY(!dock.playback().pose());
    auto scene = load_into(context, QStringLiteral("BoxAnimated"));
    QVERIFY(scene);
    QCOMPARE(dock.findChild<QComboBox*>()->count(), static_cast<int>(scene->animations.size()) + 1);
    QCOMPARE(dock.playback().animation(), 0); // the first, paused at its start
    QCOMPARE(dock.playback().clock().time, static_cast<double>(scene->animations[0].start));
    QVERIFY(dock.playback().pose());
    // Ticks: every key time of the animation's samplers, once.
    std::vector<double> keys;
    for (const scene::AnimationSampler& s : scene->animations[0].samplers)
        keys.insert(keys.end(), s.times.begin(), s.times.end());
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    QCOMPARE(dock.findChild<TimelineSlider*>()->ticks().size(), keys.size());
    QCOMPARE(dock.findChild<TimelineSlider*>()->ticks().front(), 0.0);
    QCOMPARE(dock.findChild<TimelineSlider*>()->ticks().back(), 1.0);
    // No animation selected, nothing overridden: no pose (the scene as loaded).
    dock.setAnimation(-1);
    QVERIFY(!dock.playback().pose());
    QVERIFY(!dock.findChild<TimelineSlider*>()->isEnabled());
    // A file without animations lists none.
    load_into(context, QStringLiteral("Box"));
    QCOMPARE(dock.findChild<QComboBox*>()->count(), 1);
    QVERIFY(!dock.playback().pose());
}

void MotionTests::scrubbingChangesThePose() {
    EditorContext context;
    TimelineDock dock(context);
    auto scene = load_into(context, QStringLiteral("BoxAnimated"));
    QVERIFY(scene);
    QSignalSpy changed(&dock, &TimelineDock::poseChanged);
    const scene::Animation& anim = scene->animations[0];
    const std::uint32_t node = anim.channels[0].node;
    const double t1 = anim.start + 0.25 * (anim.end - anim.start);
    const double t2 = anim.start + 0.6 * (anim.end - anim.start);
    dock.scrubTo(t1);
    QVERIFY(!changed.isEmpty());
    const glm::mat4 at1 = dock.playback().pose()->world[node];
    // The same pose is not made and announced again: retranslating, play then pause
    // before a tick, scrubbing to the same time.
    const qsizetype announced = changed.count();
    const std::shared_ptr<const scene::Pose> same = dock.playback().pose();
    dock.retranslate();
    dock.setPlaying(true);
    dock.setPlaying(false);
    dock.scrubTo(t1);
    QCOMPARE(changed.count(), announced);
    QCOMPARE(dock.playback().pose(), same);
    QVERIFY(same_matrix(at1, scene::evaluate_pose(*scene, 0, t1).world[node]));
    dock.scrubTo(t2);
    QVERIFY(same_matrix(dock.playback().pose()->world[node],
                        scene::evaluate_pose(*scene, 0, t2).world[node]));
    QVERIFY(!same_matrix(dock.playback().pose()->world[node], at1));
    QVERIFY(dock.findChild<QLabel*>(QStringLiteral("timelineTime"))
                ->text()
                .contains(QString::number(t2, 'f', 3)));
    // The slider scrubs too (its range is the animation's).
    dock.findChild<TimelineSlider*>()->setValue(TimelineDock::kSliderSteps / 2);
    QCOMPARE(dock.playback().clock().time, 0.5 * (anim.start + anim.end));
    QVERIFY(same_matrix(dock.playback().pose()->world[node],
                        scene::evaluate_pose(*scene, 0, dock.playback().clock().time).world[node]));
    // Beyond the range: clamped to the last key.
    dock.scrubTo(anim.end + 100.0);
    QCOMPARE(dock.playback().clock().time, static_cast<double>(anim.end));
}

void MotionTests::playLoopAdvancesAndWraps() {
    EditorContext context;
    TimelineDock dock(context);
    auto scene = load_into(context, QStringLiteral("AnimatedCube"));
    QVERIFY(scene);
    const scene::Animation& anim = scene->animations[0];
    const double duration = anim.end - anim.start;
    QVERIFY(duration > 0.0);
    dock.advance(0.1); // paused: nothing moves
    QCOMPARE(dock.playback().clock().time, static_cast<double>(anim.start));
    dock.setPlaying(true);
    dock.advance(0.25 * duration);
    QCOMPARE(dock.playback().clock().time, anim.start + 0.25 * duration);
    dock.setSpeed(2.0);
    dock.advance(0.25 * duration); // twice as fast: at three quarters
    QVERIFY(std::abs(dock.playback().clock().time - (anim.start + 0.75 * duration)) < 1e-9);
    dock.advance(0.25 * duration); // past the end: wraps to a quarter
    QVERIFY(std::abs(dock.playback().clock().time - (anim.start + 0.25 * duration)) < 1e-6);
    QVERIFY(dock.playback().clock().playing);
    QVERIFY(same_matrix(dock.playback().pose()->world[anim.channels[0].node],
                        scene::evaluate_pose(*scene, 0, dock.playback().clock().time)
                            .world[anim.channels[0].node]));
    // Without loop the run stops on the last key.
    dock.setLoop(false);
    dock.advance(10.0 * duration);
    QCOMPARE(dock.playback().clock().time, static_cast<double>(anim.end));
    QVERIFY(!dock.playback().clock().playing);
    // The timer drives it while playing (wall clock; not asserted on how far).
    dock.setLoop(true);
    dock.setSpeed(1.0);
    dock.setPlaying(true);
    const double before = dock.playback().clock().time;
    QTRY_VERIFY(dock.playback().clock().time != before);
    dock.setPlaying(false);
}

void MotionTests::morphSlidersOverrideThePoseWeights() {
    EditorContext context;
    TimelineDock dock(context);
    auto scene = load_into(context, QStringLiteral("SimpleMorph"));
    QVERIFY(scene);
    int node = -1;
    for (std::size_t n = 0; n < scene->nodes.size(); ++n)
        if (scene->nodes[n].mesh >= 0 && !scene->nodes[n].weights.empty()) node = int(n);
    QVERIFY(node >= 0);
    const auto mesh = scene->nodes[std::size_t(node)].mesh;
    dock.scrubTo(1.0);
    const std::vector<float> animated =
        scene::evaluate_pose(*scene, 0, 1.0).weights[std::size_t(node)];
    QCOMPARE(dock.playback().pose()->weights[std::size_t(node)], animated);
    QVERIFY(!dock.findChild<MorphWeightsPanel*>()->setOverride(mesh, 7, 0.5f)); // no such target
    QVERIFY(dock.findChild<MorphWeightsPanel*>()->setOverride(mesh, 1, 0.75f));
    QCOMPARE(dock.playback().pose()->weights[std::size_t(node)][1], 0.75f);
    // The other target keeps the slider's value (which followed the animation).
    QVERIFY(std::abs(dock.playback().pose()->weights[std::size_t(node)][0] - animated[0]) < 1e-3f);
    // Overrides hold while the time changes, and without an animation.
    dock.scrubTo(3.0);
    QCOMPARE(dock.playback().pose()->weights[std::size_t(node)][1], 0.75f);
    dock.setAnimation(-1);
    QVERIFY(dock.playback().pose());
    QCOMPARE(dock.playback().pose()->weights[std::size_t(node)][1], 0.75f);
}

void MotionTests::windowPostsThePoseAndSelectedJoint() {
    QVulkanInstance vulkan;
    std::unique_ptr<MainWindow> w = test::open_validated_window(vulkan);
    QVERIFY(w);
    if (!w->frames().renderer()) QSKIP("no Vulkan device: no frames are asked for");
    QVERIFY(!w->docks().timeline->isVisible()); // builtin:default does not move
    QVERIFY(!w->frames().lastFrame().request.pose);
    QVERIFY(test::load(*w, test::asset(QStringLiteral("BoxAnimated"))));
    QVERIFY(w->docks().timeline->isVisible());
    const scene::Scene& scene = *w->context().scene();
    const scene::Animation& anim = scene.animations[0];
    const std::uint32_t node = anim.channels[0].node;
    for (const double t : {anim.start + 0.3 * (anim.end - anim.start), double(anim.end)}) {
        w->docks().timeline->scrubTo(t);
        const glm::mat4 expected = scene::evaluate_pose(scene, 0, t).world[node];
        QTRY_VERIFY(w->frames().lastFrame().request.pose &&
                    same_matrix(w->frames().lastFrame().request.pose->world[node], expected));
        // The culling dock culls the instances where the pose puts them.
        const scene::Pose pose = scene::evaluate_pose(scene, 0, t);
        test::culling_monitor(*w).pacing().flush();
        for (std::size_t i = 0; i < scene.instances.size(); ++i) {
            const scene::MeshInstance& inst = scene.instances[i];
            const auto prim = std::find_if(
                scene.primitives.begin(), scene.primitives.end(),
                [&](const scene::PrimitiveInfo& p) { return p.engine_mesh == int(inst.mesh_id); });
            const core::Aabb expected_box = scene::culling_bounds(scene, pose, inst.node_id, *prim);
            const core::Aabb box = test::culling_monitor(*w).input().boxes.box(i);
            QVERIFY(
                glm::all(glm::lessThan(glm::abs(box.min - expected_box.min), glm::vec3(1e-5f))));
            QVERIFY(
                glm::all(glm::lessThan(glm::abs(box.max - expected_box.max), glm::vec3(1e-5f))));
        }
    }
    // Selecting a joint puts it in the frame; other nodes do not.
    QVERIFY(test::load(*w, test::asset(QStringLiteral("RiggedSimple"))));
    const std::uint32_t joint = w->context().scene()->skins[0].joints[1];
    QVERIFY(w->selection().selectNodeNamed(QString::number(joint)));
    QTRY_COMPARE(w->frames().lastFrame().request.selected_joint.value_or(~0u), joint);
    QVERIFY(w->selection().selectNodeNamed(QStringLiteral("0")));
    QTRY_VERIFY(!w->frames().lastFrame().request.selected_joint);
    qsizetype seen = 0;
    QCOMPARE(test::fresh_validation_messages(*w, seen), QString());
}

QTEST_MAIN(MotionTests)
#include "motion_tests.moc"
