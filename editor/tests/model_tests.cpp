// The docks' models against the engine data they present, over every sample model,
// plus the frame pacing, command line, resolution scale and a million-vertex table.
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

// Checks every node of the displayed scene against its tree item, recursively.
void check_node(const scene::Scene& s, const SceneTreeModel& model, std::uint32_t n) {
    const QModelIndex item = model.indexOfNode(static_cast<int>(n));
    QVERIFY2(item.isValid(), qPrintable(QStringLiteral("node %1 has no item").arg(n)));
    const scene::Node& node = s.nodes[n];
    const QString name =
        node.name.empty() ? QStringLiteral("Node %1").arg(n) : QString::fromStdString(node.name);
    QCOMPARE(item.data().toString(), name);
    QCOMPARE(item.data(Qt::CheckStateRole).toInt(), static_cast<int>(Qt::Checked));
    int expected = static_cast<int>(node.children.size()) + (node.light >= 0) + (node.camera >= 0);
    if (node.mesh >= 0) {
        for (const scene::PrimitiveInfo& p : s.primitives)
            expected += p.mesh == static_cast<std::uint32_t>(node.mesh);
    }
    QCOMPARE(model.rowCount(item), expected);
    for (std::uint32_t c : node.children) check_node(s, model, c);
}

void check_vertex_rows(const scene::Mesh& mesh, const VertexTableModel& model) {
    QCOMPARE(model.rowCount(), static_cast<int>(mesh.vertices.size()));
    const std::size_t n = mesh.vertices.size();
    for (std::size_t v : {std::size_t{0}, n / 2, n - 1}) {
        const scene::Vertex& x = mesh.vertices[v];
        const int row = static_cast<int>(v);
        QCOMPARE(display(model, row, VertexTableModel::IndexColumn), QString::number(v));
        for (int c = 0; c < 3; ++c) {
            QCOMPARE(display(model, row, VertexTableModel::PosX + c),
                     format::compact(x.position[c]));
            QCOMPARE(display(model, row, VertexTableModel::NrmX + c), format::compact(x.normal[c]));
        }
        for (int c = 0; c < 4; ++c)
            QCOMPARE(display(model, row, VertexTableModel::TanX + c),
                     format::compact(x.tangent[c]));
        for (int c = 0; c < 2; ++c) {
            QCOMPARE(display(model, row, VertexTableModel::Uv0U + c), format::compact(x.uv0[c]));
            QCOMPARE(display(model, row, VertexTableModel::Uv1U + c), format::compact(x.uv1[c]));
        }
        QCOMPARE(display(model, row, VertexTableModel::ColR),
                 mesh.colors.empty() ? QStringLiteral("—") : format::compact(mesh.colors[v].r));
    }
}

} // namespace

class ModelTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QVERIFY(!test::all_assets().isEmpty()); }
    void everyAssetMatchesTheEngine_data();
    void everyAssetMatchesTheEngine();
    void materialFieldsFollowTheGpuLayout();
    void materialChainSaysTheCacheState();
    void millionVertexTableSortsByPermutation();
    void generatedTangentsAgreeWithRegeneration();
    void framePacingReducesMovingFramesOnly();
    void commandLineDocksAndCulling();
    void resolutionScaleHoldsTheTargetRate();
};

void ModelTests::everyAssetMatchesTheEngine_data() {
    QTest::addColumn<QString>("name");
    for (const QString& n : test::all_assets()) QTest::newRow(qPrintable(n)) << n;
}

void ModelTests::everyAssetMatchesTheEngine() {
    QFETCH(QString, name);
    const LoadOutcome out = SceneLoadJob::loadNow(test::asset(name));
    QVERIFY2(out.session, qPrintable(out.error));
    const scene::Scene& s = *out.session->scene;
    EditorContext context;
    SceneTreeModel tree(context);
    context.setSession(out.session);

    // Scenes, then skins and animations (scene_tree_motion.cpp).
    QCOMPARE(tree.rowCount(),
             static_cast<int>(s.scenes.size() + s.skins.size() + s.animations.size()));
    if (!s.scenes.empty())
        for (std::uint32_t r : s.scenes[static_cast<std::size_t>(s.displayed_scene)].roots)
            check_node(s, tree, r);

    AttributeModel attributes;
    VertexTableModel vertices;
    TriangleTableModel triangles;
    for (std::size_t m = 0; m < s.meshes.size(); ++m) {
        const scene::Mesh& mesh = s.meshes[m];
        const MeshRef ref{out.session->scene, static_cast<int>(m)};
        attributes.setMesh(ref);
        vertices.setMesh(ref);
        triangles.setMesh(ref);
        QCOMPARE(attributes.rowCount(), static_cast<int>(scene::kVertexAttributeCount) + 1);
        for (std::size_t a = 0; a < scene::kVertexAttributeCount; ++a) {
            const int row = static_cast<int>(a);
            QCOMPARE(display(attributes, row, AttributeModel::ProvenanceColumn),
                     format::provenance(mesh.provenance[a]));
            if (mesh.sources[a])
                QCOMPARE(display(attributes, row, AttributeModel::CountColumn),
                         QString::number(mesh.sources[a]->count));
            const std::uint64_t gpu = attributes.gpuBytes(row);
            QVERIFY(gpu == 0 ||
                    gpu == std::uint64_t{stream_stride(scene::kAllVertexAttributes[a])} *
                               mesh.vertices.size());
        }
        QCOMPARE(attributes.gpuBytes(AttributeModel::kIndexRow), mesh.indices.size() * 4);
        if (!mesh.vertices.empty()) check_vertex_rows(mesh, vertices);
        QCOMPARE(triangles.rowCount(), static_cast<int>(mesh.triangle_count()));
        if (mesh.triangle_count() > 0) {
            const int last = static_cast<int>(mesh.triangle_count()) - 1;
            for (int c = 0; c < 3; ++c)
                QCOMPARE(display(triangles, last, TriangleTableModel::V0 + c),
                         QString::number(mesh.indices[static_cast<std::size_t>(last) * 3 +
                                                      static_cast<std::size_t>(c)]));
        }
    }

    TextureTableModel textures;
    textures.setSession(out.session);
    QCOMPARE(textures.rowCount(), static_cast<int>(s.textures.size()));
    for (std::size_t t = 0; t < s.textures.size(); ++t) {
        QCOMPARE(display(textures, static_cast<int>(t), TextureTableModel::RoleColumn),
                 format::roles(s.textures[t].roles));
        const std::int32_t image = s.textures[t].image;
        if (image >= 0 && !s.images[static_cast<std::size_t>(image)].encoded.empty())
            QVERIFY2(!out.session->thumbnails[t].isNull(),
                     "every sample texture decodes to a thumbnail");
    }
}

void ModelTests::materialFieldsFollowTheGpuLayout() {
    const LoadOutcome out = SceneLoadJob::loadNow(test::asset(QStringLiteral("DamagedHelmet")));
    QVERIFY(out.session);
    const scene::MaterialInstance& m = out.session->scene->materials[0];
    MaterialFieldsModel model;
    model.setMaterial(out.session, 0, scene::to_gpu_material(m), MaterialFieldsModel::Source::Cpu);
    QCOMPARE(model.rowCount(), 14);
    // Offsets strictly increase and end at 76 (80-byte std430 record).
    int last = -1;
    for (int r = 0; r < model.rowCount(); ++r) {
        const int offset =
            model.data(model.index(r, MaterialFieldsModel::OffsetColumn), Qt::DisplayRole).toInt();
        QVERIFY(offset > last);
        last = offset;
    }
    QCOMPARE(last, 76);
    QCOMPARE(display(model, 0, MaterialFieldsModel::ValueColumn), format::vec(m.base_color_factor));
    QCOMPARE(display(model, 0, MaterialFieldsModel::FieldColumn),
             QStringLiteral("base_color_factor"));
    QCOMPARE(model.textureOfRow(6), m.base_color.texture); // base_color_tex
    QCOMPARE(model.textureOfRow(9), m.normal.texture);     // normal_tex
    QVERIFY(
        model.data(model.index(6, MaterialFieldsModel::ChainColumn), Qt::DecorationRole).isValid());
    // A GPU record maps bindless slots back through the table it comes with.
    scene::GPUMaterialData gpu = scene::to_gpu_material(m);
    gpu.base_color_tex = 7;
    std::vector<int> table(8, -1);
    table[7] = 3;
    model.setMaterial(out.session, 0, gpu, MaterialFieldsModel::Source::GpuReadback, table);
    QCOMPARE(model.textureOfRow(6), 3);
}

void ModelTests::materialChainSaysTheCacheState() {
    const LoadOutcome out = SceneLoadJob::loadNow(test::asset(QStringLiteral("BoxTextured")));
    QVERIFY(out.session);
    const scene::Scene& scene = *out.session->scene;
    const int texture = scene.materials[0].base_color.texture;
    QVERIFY(texture >= 0);
    MaterialFieldsModel model;
    const auto chain = [&](const SharedSession& session) {
        model.setMaterial(session, 0, scene::to_gpu_material(scene.materials[0]),
                          MaterialFieldsModel::Source::Cpu);
        return display(model, 6, MaterialFieldsModel::ChainColumn); // base_color_tex
    };
    // Nothing prepared (no device): the chain says nothing of a cache.
    QVERIFY(!chain(out.session).contains(QStringLiteral("cache")));
    // Prepared as the loader does for a device: the state the texture dock shows.
    auto prepared = std::make_shared<SceneSession>(*out.session);
    tex::PipelineOptions options;
    options.bc7_level = 0; // no cache directory: a miss
    prepared->textures = tex::prepare_scene_textures(scene, {true, false, "test device"}, options);
    TextureTableModel textures;
    textures.setSession(prepared);
    const QString state = display(textures, texture, TextureTableModel::CacheStateColumn);
    QCOMPARE(state, QStringLiteral("miss"));
    QVERIFY2(chain(prepared).endsWith(QStringLiteral(" → cache: miss")),
             qPrintable(chain(prepared)));
}

void ModelTests::millionVertexTableSortsByPermutation() {
    auto scene = std::make_shared<scene::Scene>();
    scene::Mesh mesh;
    constexpr std::size_t kSide = 1000;
    mesh.vertices.resize(kSide * kSide);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        // x decreases with the index so a sort must really permute.
        mesh.vertices[i].position = {static_cast<float>(kSide * kSide - i),
                                     static_cast<float>(i % kSide), 0.0f};
    }
    mesh.indices = {0, 1, 2};
    scene->meshes.push_back(std::move(mesh));
    VertexTableModel model;
    model.setMesh(MeshRef{scene, 0});
    QCOMPARE(model.rowCount(), 1000000);
    QCOMPARE(display(model, 999999, VertexTableModel::PosX), format::compact(1.0));
    model.sort(VertexTableModel::PosX, Qt::AscendingOrder);
    QCOMPARE(model.vertexOfRow(0), 999999);
    QCOMPARE(model.rowOfVertex(999999), 0);
    QCOMPARE(display(model, 0, VertexTableModel::IndexColumn), QStringLiteral("999999"));
    model.sort(VertexTableModel::PosY, Qt::DescendingOrder);
    QCOMPARE(display(model, 0, VertexTableModel::PosY), format::compact(999.0));
    for (int v : {0, 12345, 999999}) QCOMPARE(model.vertexOfRow(model.rowOfVertex(v)), v);
}

void ModelTests::generatedTangentsAgreeWithRegeneration() {
    // DamagedHelmet has no TANGENT: the importer generates MikkTSpace ones, so
    // regenerating them must agree to float precision everywhere.
    const LoadOutcome out = SceneLoadJob::loadNow(test::asset(QStringLiteral("DamagedHelmet")));
    QVERIFY(out.session);
    const scene::Mesh& mesh = out.session->scene->meshes[0];
    QCOMPARE(mesh.provenance_of(scene::VertexAttribute::Tangent), scene::Provenance::Generated);
    const TangentErrors e = tangent_errors(mesh, 0);
    QCOMPARE(e.degrees.size(), mesh.vertices.size());
    QVERIFY2(e.max < 1e-2, qPrintable(QString::number(e.max)));
    QCOMPARE(e.flips, std::uint64_t{0});
    VertexTableModel model;
    model.setMesh(MeshRef{out.session->scene, 0});
    model.setTangentErrors(std::make_shared<const TangentErrors>(e));
    model.sort(VertexTableModel::TangentErrorColumn, Qt::DescendingOrder);
    const int worst = model.vertexOfRow(0);
    QCOMPARE(display(model, 0, VertexTableModel::TangentErrorColumn),
             format::compact(e.degrees[static_cast<std::size_t>(worst)]));
}

// The render thread's pacing: a frame whose camera or pose moved is drawn reduced once
// a frame was too slow, the same camera is still (full size), a reduced frame is
// refined after kRestMs, and a path-traced still frame is drawn again at once until
// it has kPathSamples.
void ModelTests::framePacingReducesMovingFramesOnly() {
    FramePacing pacing;
    FrameOrder a;
    a.frame.request.width = 800;
    a.frame.request.height = 600;
    a.frame.request.camera.eye = {0.0f, 0.0f, 5.0f};
    QVERIFY(pacing.still(a)); // nothing drawn yet
    QVERIFY(!pacing.restWait());
    PresentOutcome shown;
    shown.shown = true;
    pacing.drawn(a, pacing.scale(true), shown, 4.0 * kTargetFrameMs); // full size, slow
    QVERIFY(!pacing.restWait());                                      // nothing to refine
    FrameOrder b = a;
    b.frame.request.camera.eye = {1.0f, 0.0f, 5.0f};
    QVERIFY(pacing.still(a));
    QVERIFY(!pacing.still(b));
    QCOMPARE(pacing.scale(true), 1.0f);
    QCOMPARE(pacing.scale(false), 0.5f); // 4x the target: half of each side
    pacing.drawn(b, 0.5f, shown, kTargetFrameMs);
    QCOMPARE(pacing.restWait().value_or(std::chrono::milliseconds(-1)),
             std::chrono::milliseconds(FramePacing::kRestMs));
    QCOMPARE(pacing.again()->frame.request.camera.eye, b.frame.request.camera.eye);
    // A new pose is motion too.
    FrameOrder posed = b;
    posed.frame.request.pose = std::make_shared<const scene::Pose>();
    QVERIFY(!pacing.still(posed));
    // Scaling off: every frame full size.
    pacing.setOptions({.interactiveScaling = false});
    QCOMPARE(pacing.scale(false), 1.0f);
    // Path traced at full size and not done: drawn again at once.
    PresentOutcome traced = shown;
    traced.path_traced = true;
    traced.path_samples = 10;
    pacing.drawn(b, 1.0f, traced, kTargetFrameMs);
    QCOMPARE(pacing.restWait().value_or(std::chrono::milliseconds(-1)),
             std::chrono::milliseconds(0));
    traced.path_samples = ViewportPresenter::kPathSamples;
    pacing.drawn(b, 1.0f, traced, kTargetFrameMs);
    QVERIFY(!pacing.restWait());
    // Forgotten (a new scene): the next frame is still whatever its camera.
    pacing.forget();
    QVERIFY(pacing.still(posed));
    QVERIFY(!pacing.again());
}

void ModelTests::commandLineDocksAndCulling() {
    CommandLine cl;
    QString error;
    const QString app = QStringLiteral("sherpa");
    QVERIFY(parse_command_line({app, QStringLiteral("--dock"), QStringLiteral("log"),
                                QStringLiteral("--dock"), QStringLiteral("culling"),
                                QStringLiteral("--gpu-culling")},
                               cl, error));
    QCOMPARE(cl.docks, QStringList({QStringLiteral("log"), QStringLiteral("culling")}));
    QVERIFY(cl.gpu_culling);
    QVERIFY(
        !parse_command_line({app, QStringLiteral("--dock"), QStringLiteral("nope")}, cl, error));
    QVERIFY(error.contains(QStringLiteral("scene-tree")));
}

void ModelTests::resolutionScaleHoldsTheTargetRate() {
    // Cost taken as proportional to the pixels: 4x the target at full size wants half
    // of each side; at the target it stays; cheap frames go back up to full size.
    QCOMPARE(next_resolution_scale(1.0f, 4.0 * kTargetFrameMs), 0.5f);
    QCOMPARE(next_resolution_scale(0.5f, kTargetFrameMs), 0.5f);
    QCOMPARE(next_resolution_scale(0.5f, kTargetFrameMs / 4.0), 1.0f);
    QCOMPARE(next_resolution_scale(1.0f, kTargetFrameMs / 2.0), 1.0f);
    // Clamped to the smallest scale however slow (the 100k grid: 2 s a frame).
    QCOMPARE(next_resolution_scale(1.0f, 2000.0), kMinResolutionScale);
    // Less than a step of change keeps the scale (no new image for jitter); steps are 1/16.
    QCOMPARE(next_resolution_scale(0.5f, kTargetFrameMs * 1.1), 0.5f);
    const float s = next_resolution_scale(1.0f, 2.0 * kTargetFrameMs);
    QCOMPARE(s, 0.6875f); // sqrt(1/2) = 0.707, to the nearest 1/16
    // Unmeasured: unchanged.
    QCOMPARE(next_resolution_scale(0.75f, 0.0), 0.75f);

    // The status bar's running frame time leaves out the first frame (pipelines).
    FrameTimes times;
    times.add(430.0);
    QCOMPARE(times.count(), std::size_t{0});
    QCOMPARE(times.meanMs(), 0.0);
    times.add(20.0);
    times.add(40.0);
    QCOMPARE(times.meanMs(), 30.0);
    QCOMPARE(times.fps(), 1000.0 / 30.0);
    for (int i = 0; i < 100; ++i) times.add(10.0);
    QCOMPARE(times.count(), FrameTimes::kWindow);
    QCOMPARE(times.meanMs(), 10.0);
}

QTEST_MAIN(ModelTests)
#include "model_tests.moc"
