// What issue 15's files show in the docks (compressed geometry, KTX2 containers,
// specular-glossiness fields), from the test fixtures' generated files.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include "editor_context.h"
#include "format_values.h"
#include "instance_table_model.h"
#include "material_fields_model.h"
#include "mesh_dock.h"
#include "scene_load_job.h"
#include "scene_tree_model.h"
#include "test_assets.h"
#include "texture_table_model.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

QString display(const QAbstractItemModel& m, int row, int column) {
    return m.data(m.index(row, column), Qt::DisplayRole).toString();
}

// Loads material sweep `name` (tests/data/material_sweeps) and shows its material
// `index` in `fields` as the CPU builds the record; the outcome says whether it loaded.
LoadOutcome show_sweep_material(MaterialFieldsModel& fields, const char* name, int index) {
    LoadOutcome out =
        SceneLoadJob::loadNow(QStringLiteral(SHERPA_TEST_DATA_DIR "/material_sweeps/") +
                              QLatin1String(name) + QStringLiteral(".gltf"));
    if (out.session)
        fields.setMaterial(out.session, index,
                           scene::to_gpu_material(out.session->scene->materials.at(index)),
                           MaterialFieldsModel::Source::Cpu);
    return out;
}

} // namespace

class DockContentTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void docksShowCompressionContainerAndSpecGloss();
    void materialDockShowsExtensionBlocksWithOffsets();
    void instancedNodeShowsItsRowsInTheTreeAndTheTable();
};

// EXT_mesh_gpu_instancing: the scene tree shows an instanced node with its count (of
// the file's rows, where fewer are drawn), and the mesh dock's Instances tab lists the
// selected node's rows; gltfpack -mi's 2CylinderEngine and a hand-made file.
void DockContentTests::instancedNodeShowsItsRowsInTheTreeAndTheTable() {
    for (const QString& file :
         {QStringLiteral(SHERPA_TEST_DATA_DIR "/instancing_basic.gltf"),
          QStringLiteral(SHERPA_TEST_DATA_DIR "/instancing_bad_rows.gltf"),
          QStringLiteral(SHERPA_GLTF_COMPRESS_CACHE "/corpus/2CylinderEngine.instanced.glb")}) {
        const LoadOutcome out = SceneLoadJob::loadNow(file);
        QVERIFY2(out.session, qPrintable(out.error));
        const scene::Scene& s = *out.session->scene;
        EditorContext context;
        SceneTreeModel tree(context);
        MeshDock dock(context);
        context.setSession(out.session);
        int checked = 0;
        for (std::size_t n = 0; n < s.nodes.size(); ++n) {
            const auto& rows = s.nodes[n].instancing;
            const QModelIndex item = tree.indexOfNode(int(n));
            if (!item.isValid()) continue;
            const QString detail =
                item.siblingAtColumn(SceneTreeModel::DetailColumn).data().toString();
            if (!rows) {
                QVERIFY2(!detail.contains(QStringLiteral("GPU instances")), qPrintable(detail));
                continue;
            }
            const QString count = QStringLiteral("×%1 GPU instances").arg(rows->rows.size());
            QVERIFY2(detail.startsWith(count), qPrintable(detail));
            if (rows->rows.size() != rows->file_rows)
                QVERIFY2(detail.contains(QStringLiteral("of %1 rows").arg(rows->file_rows)),
                         qPrintable(detail));
            context.selection().selectNode(int(n));
            QCOMPARE(dock.instances()->rowCount(), int(rows->rows.size()));
            const scene::InstanceRow& last = rows->rows.back();
            const int r = dock.instances()->rowCount() - 1;
            QCOMPARE(display(*dock.instances(), r, InstanceTableModel::RowColumn),
                     QString::number(last.file_row));
            QCOMPARE(display(*dock.instances(), r, InstanceTableModel::TX),
                     format::number(last.translation.x));
            QCOMPARE(display(*dock.instances(), r, InstanceTableModel::RW),
                     format::number(last.rotation.w));
            QCOMPARE(display(*dock.instances(), r, InstanceTableModel::SZ),
                     format::number(last.scale.z));
            ++checked;
        }
        QVERIFY2(checked > 0, qPrintable(file));
    }
}

// What issue 15's files show in the docks: a Draco primitive's codec and sizes in the
// mesh summary (as info --json reports them), a KTX2 image's payload and
// supercompression in the texture table, and a spec-gloss material's own fields.
void DockContentTests::docksShowCompressionContainerAndSpecGloss() {
    const LoadOutcome draco = SceneLoadJob::loadNow(
        QStringLiteral(SHERPA_GLTF_COMPRESS_CACHE "/corpus/DamagedHelmet.draco.glb"));
    QVERIFY2(draco.session, qPrintable(draco.error));
    const scene::PrimitiveInfo& p = draco.session->scene->primitives.at(0);
    QVERIFY(p.compression);
    const QString text = MeshDock::compressionText(*draco.session->scene, int(p.engine_mesh));
    QVERIFY2(text.contains(QStringLiteral("KHR_draco_mesh_compression ") +
                           QString::fromStdString(p.compression->modes)),
             qPrintable(text));
    QVERIFY2(text.contains(format::bytes(p.compression->encoded_bytes)) &&
                 text.contains(format::bytes(p.compression->decoded_bytes)),
             qPrintable(text));
    const LoadOutcome plain = SceneLoadJob::loadNow(test::asset(QStringLiteral("DamagedHelmet")));
    QVERIFY(plain.session);
    QVERIFY(MeshDock::compressionText(*plain.session->scene, 0).isEmpty());

    // BoxTextured with its image replaced by a Zstandard UASTC KTX2 of the basisu corpus,
    // and its material by a spec-gloss one reading that texture.
    QTemporaryDir dir;
    QVERIFY(QFile::copy(QStringLiteral(SHERPA_BASISU_CACHE "/corpus/logo211_uastc_zstd.ktx2"),
                        dir.filePath(QStringLiteral("logo.ktx2"))));
    QVERIFY(QFile::copy(QStringLiteral(SHERPA_ASSETS_DIR "/gltf/BoxTextured/glTF/BoxTextured0.bin"),
                        dir.filePath(QStringLiteral("BoxTextured0.bin"))));
    QFile in(test::asset(QStringLiteral("BoxTextured")));
    QVERIFY(in.open(QIODevice::ReadOnly));
    QJsonObject doc = QJsonDocument::fromJson(in.readAll()).object();
    doc[QStringLiteral("images")] =
        QJsonArray{QJsonObject{{QStringLiteral("uri"), QStringLiteral("logo.ktx2")}}};
    doc[QStringLiteral("textures")] = QJsonArray{QJsonObject{
        {QStringLiteral("extensions"), QJsonObject{{QStringLiteral("KHR_texture_basisu"),
                                                    QJsonObject{{QStringLiteral("source"), 0}}}}}}};
    const QJsonObject sg{
        {QStringLiteral("diffuseFactor"), QJsonArray{0.2, 0.4, 0.6, 1.0}},
        {QStringLiteral("specularFactor"), QJsonArray{0.1, 0.2, 0.3}},
        {QStringLiteral("glossinessFactor"), 0.7},
        {QStringLiteral("specularGlossinessTexture"), QJsonObject{{QStringLiteral("index"), 0}}}};
    doc[QStringLiteral("materials")] = QJsonArray{
        QJsonObject{{QStringLiteral("extensions"),
                     QJsonObject{{QStringLiteral("KHR_materials_pbrSpecularGlossiness"), sg}}}}};
    doc[QStringLiteral("extensionsUsed")] =
        QJsonArray{QStringLiteral("KHR_texture_basisu"),
                   QStringLiteral("KHR_materials_pbrSpecularGlossiness")};
    const QString path = dir.filePath(QStringLiteral("box.gltf"));
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(doc).toJson());
    out.close();
    const LoadOutcome box = SceneLoadJob::loadNow(path);
    QVERIFY2(box.session, qPrintable(box.error));
    TextureTableModel textures;
    textures.setSession(box.session);
    QCOMPARE(display(textures, 0, TextureTableModel::ContainerColumn),
             QStringLiteral("ktx2-uastc · zstd"));

    const scene::MaterialInstance& m = box.session->scene->materials.at(0);
    QVERIFY(m.specular_glossiness);
    MaterialFieldsModel fields;
    fields.setMaterial(box.session, 0, scene::to_gpu_material(m), MaterialFieldsModel::Source::Cpu);
    QCOMPARE(fields.rowCount(), 14 + 3); // the GPUMaterialData fields, then the extension's
    QCOMPARE(display(fields, 0, MaterialFieldsModel::PropertyColumn),
             QStringLiteral("KHR_materials_pbrSpecularGlossiness.diffuseFactor"));
    QCOMPARE(display(fields, 0, MaterialFieldsModel::ValueColumn),
             format::vec(glm::vec4(0.2f, 0.4f, 0.6f, 1.0f)));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::ValueColumn),
             format::vec(glm::vec4(0.1f, 0.2f, 0.3f, 0.7f)));
    QCOMPARE(
        display(fields, 15, MaterialFieldsModel::PropertyColumn),
        QStringLiteral("KHR_materials_pbrSpecularGlossiness.specularFactor, glossinessFactor"));
    QCOMPARE(fields.textureOfRow(16), 0); // specularGlossinessTexture
}

// KHR_materials_ior / _specular: after the record's 14 fields, the material's extension
// index and blocks with their byte offsets in the extension buffer (material 1 of the
// ior sweep: the second material's index is at word 4, after material 0's three-word
// index + ior).
void DockContentTests::materialDockShowsExtensionBlocksWithOffsets() {
    MaterialFieldsModel fields;
    const LoadOutcome sweep = show_sweep_material(fields, "ior_sweep", 1);
    QVERIFY2(sweep.session, qPrintable(sweep.error));
    QCOMPARE(fields.rowCount(), 14 + 2);
    QCOMPARE(display(fields, 14, MaterialFieldsModel::FieldColumn), QStringLiteral("ext.index"));
    QCOMPARE(display(fields, 14, MaterialFieldsModel::OffsetColumn), QStringLiteral("64"));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::FieldColumn), QStringLiteral("ext.ior"));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::OffsetColumn), QStringLiteral("112"));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::ValueColumn), format::number(1.2f));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::PropertyColumn),
             QStringLiteral("KHR_materials_ior.ior"));

    const LoadOutcome spec = show_sweep_material(fields, "specular_sweep", 0);
    QVERIFY2(spec.session, qPrintable(spec.error));
    QCOMPARE(fields.rowCount(), 14 + 4); // index, colour/factor, two textures
    QCOMPARE(display(fields, 15, MaterialFieldsModel::FieldColumn),
             QStringLiteral("ext.specular.color_factor"));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::OffsetColumn), QStringLiteral("48"));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::ValueColumn),
             format::vec(glm::vec4(1.0f, 1.0f, 1.0f, 0.0f)));
    QCOMPARE(display(fields, 16, MaterialFieldsModel::OffsetColumn), QStringLiteral("64"));

    // KHR_materials_clearcoat: index, factors, three textures (material 0 of the
    // clearcoat sweep: its block right after its three-word index).
    const LoadOutcome coat = show_sweep_material(fields, "clearcoat_sweep", 2);
    QVERIFY2(coat.session, qPrintable(coat.error));
    QCOMPARE(fields.rowCount(), 14 + 5);
    QCOMPARE(display(fields, 15, MaterialFieldsModel::FieldColumn),
             QStringLiteral("ext.clearcoat.factors"));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::OffsetColumn),
             QString::number(2 * (48 + 128) + 48));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::ValueColumn),
             format::vec(glm::vec4(0.5f, 0.0f, 1.0f, 0.0f)));
    QCOMPARE(display(fields, 18, MaterialFieldsModel::FieldColumn),
             QStringLiteral("ext.clearcoat.normal_tex"));

    // KHR_materials_anisotropy: index, its third word, factors, texture (material 7 of
    // the anisotropy sweep, 60 degrees: after seven 48-byte indices and 64-byte blocks).
    const LoadOutcome aniso = show_sweep_material(fields, "anisotropy_sweep", 7);
    QVERIFY2(aniso.session, qPrintable(aniso.error));
    QCOMPARE(fields.rowCount(), 14 + 4);
    const int first = 7 * (48 + 64);
    QCOMPARE(display(fields, 15, MaterialFieldsModel::FieldColumn),
             QStringLiteral("ext.index.anisotropy"));
    QCOMPARE(display(fields, 15, MaterialFieldsModel::OffsetColumn), QString::number(first + 32));
    QCOMPARE(display(fields, 16, MaterialFieldsModel::FieldColumn),
             QStringLiteral("ext.anisotropy.factors"));
    QCOMPARE(display(fields, 16, MaterialFieldsModel::OffsetColumn), QString::number(first + 48));
    QCOMPARE(display(fields, 16, MaterialFieldsModel::ValueColumn),
             format::vec(glm::vec4(0.8f, std::cos(1.04719755f), std::sin(1.04719755f), 0.0f)));
    QCOMPARE(display(fields, 17, MaterialFieldsModel::OffsetColumn), QString::number(first + 64));

    // KHR_materials_iridescence: index, its third word, factors, two textures (material
    // 9 of the iridescence sweep, 700 nm: after nine 48-byte indices and 96-byte blocks).
    const LoadOutcome film = show_sweep_material(fields, "iridescence_sweep", 9);
    QVERIFY2(film.session, qPrintable(film.error));
    QCOMPARE(fields.rowCount(), 14 + 5);
    QCOMPARE(display(fields, 16, MaterialFieldsModel::FieldColumn),
             QStringLiteral("ext.iridescence.factors"));
    QCOMPARE(display(fields, 16, MaterialFieldsModel::OffsetColumn),
             QString::number(9 * (48 + 96) + 48));
    QCOMPARE(display(fields, 16, MaterialFieldsModel::ValueColumn),
             format::vec(glm::vec4(1.0f, 1.3f, 100.0f, 700.0f)));
}

QTEST_MAIN(DockContentTests)
#include "dock_content_tests.moc"
