#include "mesh_dock.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "attribute_model.h"
#include "editor_context.h"
#include "format_values.h"
#include "instance_table_model.h"
#include "triangle_table_model.h"
#include "vertex_table_model.h"
#include "view_fitting.h"

namespace sherpa::editor {

namespace {
// Million-row tables stay smooth only with fixed row heights (no per-row measuring).
QTableView* make_big_table(QWidget* parent, QAbstractItemModel* model) {
    auto* view = new QTableView(parent);
    view->setModel(model);
    view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 4);
    view->verticalHeader()->hide();
    view->horizontalHeader()->setDefaultSectionSize(84);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setSelectionMode(QAbstractItemView::SingleSelection);
    view->setWordWrap(false);
    return view;
}
} // namespace

MeshDock::MeshDock(const EditorContext& context, QWidget* parent)
    : QDockWidget(parent), context_(context) {
    setObjectName(QStringLiteral("meshDock"));
    attributes_ = new AttributeModel(this);
    vertices_ = new VertexTableModel(this);
    triangles_ = new TriangleTableModel(this);
    instances_ = new InstanceTableModel(this);

    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    summary_ = new QLabel(body);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    attribute_view_ = new QTableView(body);
    attribute_view_->setModel(attributes_);
    attribute_view_->verticalHeader()->hide();
    attribute_view_->setWordWrap(false);
    // Which accessor and component type hold each attribute before where they came from.
    show_columns_first(attribute_view_->horizontalHeader(),
                       {AttributeModel::AttributeColumn, AttributeModel::AccessorColumn,
                        AttributeModel::ComponentTypeColumn, AttributeModel::CountColumn});

    tabs_ = new QTabWidget(body);
    auto* vertex_page = new QWidget(tabs_);
    auto* vertex_layout = new QVBoxLayout(vertex_page);
    vertex_layout->setContentsMargins(0, 0, 0, 0);
    // Two rows: in one, German labels need more than the dock's default width.
    auto* tools = new QGridLayout;
    jump_ = new QSpinBox(vertex_page);
    jump_->setRange(0, 0);
    jump_button_ = new QPushButton(vertex_page);
    tangent_button_ = new QPushButton(vertex_page);
    tangent_summary_ = new QLabel(vertex_page);
    tools->addWidget(jump_, 0, 0);
    tools->addWidget(jump_button_, 0, 1);
    tools->addWidget(tangent_button_, 1, 0, 1, 2);
    tools->addWidget(tangent_summary_, 1, 2);
    tools->setColumnStretch(2, 1);
    vertex_view_ = make_big_table(vertex_page, vertices_);
    vertex_view_->setSortingEnabled(true);
    vertex_view_->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder);
    vertex_layout->addLayout(tools);
    vertex_layout->addWidget(vertex_view_);
    triangle_view_ = make_big_table(tabs_, triangles_);
    tabs_->addTab(vertex_page, QString());
    tabs_->addTab(triangle_view_, QString());
    instance_view_ = make_big_table(tabs_, instances_);
    tabs_->addTab(instance_view_, QString());

    auto* split = new QSplitter(Qt::Vertical, body);
    split->addWidget(attribute_view_);
    split->addWidget(tabs_);
    split->setStretchFactor(1, 3);
    layout->addWidget(summary_);
    layout->addWidget(split);
    setWidget(body);

    connect(jump_button_, &QPushButton::clicked, this, [this] { jumpToVertex(jump_->value()); });
    connect(jump_, &QSpinBox::editingFinished, this, [this] { jumpToVertex(jump_->value()); });
    connect(tangent_button_, &QPushButton::clicked, this, &MeshDock::computeTangentErrors);
    connect(vertex_view_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                if (current.isValid())
                    Q_EMIT selectVertexRequested(vertices_->vertexOfRow(current.row()));
            });
    connect(triangle_view_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                if (current.isValid()) Q_EMIT selectTriangleRequested(current.row());
            });
    connect(&tangent_job_, &QFutureWatcher<std::shared_ptr<const TangentErrors>>::finished, this,
            [this] {
                const auto errors = tangent_job_.result();
                tangent_button_->setEnabled(true);
                if (!errors) return;
                vertices_->setTangentErrors(errors);
                tangent_summary_->setText(tr("max %1°, mean %2°, %3 handedness flips")
                                              .arg(errors->max, 0, 'f', 3)
                                              .arg(errors->mean, 0, 'f', 3)
                                              .arg(errors->flips));
                Q_EMIT tangentErrorsReady();
            });
    connect(&context_.selection(), &SceneSelection::changed, this, &MeshDock::showMesh);
    connect(&context_, &EditorContext::sceneReady, this, &MeshDock::showMesh);
    retranslate();
}

MeshDock::~MeshDock() {
    tangent_job_.waitForFinished();
}

void MeshDock::retranslate() {
    setWindowTitle(tr("Mesh Attributes"));
    tabs_->setTabText(0, tr("Vertices"));
    const scene::Mesh* shown = MeshRef{context_.sharedScene(), shown_mesh_}.get();
    const scene::Topology topology = shown ? shown->topology() : scene::Topology::Triangles;
    tabs_->setTabText(1, topology == scene::Topology::Lines    ? tr("Segments")
                         : topology == scene::Topology::Points ? tr("Points")
                                                               : tr("Triangles"));
    const scene::NodeInstancing* rows = instances_->instancing();
    tabs_->setTabText(2, rows ? tr("Instances (%1)").arg(rows->rows.size()) : tr("Instances"));
    jump_button_->setText(tr("Jump to vertex"));
    tangent_button_->setText(tr("Compare tangents"));
    tangent_button_->setToolTip(tr("Regenerate MikkTSpace tangents and show the angle to the "
                                   "mesh's tangents per vertex (sortable column)"));
    updateSummary();
}

void MeshDock::showMesh() {
    const int mesh = context_.selection().current().mesh,
              node = context_.selection().current().node;
    if (mesh == shown_mesh_ && node == shown_node_ && context_.scene() == shown_scene_)
        return; // vertex/triangle picks
    shown_mesh_ = mesh;
    shown_node_ = node;
    instances_->setNode(node >= 0 ? context_.sharedScene() : nullptr, node);
    tabs_->setTabEnabled(2, instances_->rowCount() > 0);
    shown_scene_ = context_.scene();
    MeshRef ref{mesh >= 0 ? context_.sharedScene() : nullptr, mesh};
    attributes_->setMesh(ref);
    vertices_->setMesh(ref);
    triangles_->setMesh(ref);
    vertex_view_->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder);
    jump_->setRange(0, std::max(0, vertices_->rowCount() - 1));
    tangent_summary_->clear();
    attribute_view_->resizeColumnsToContents();
    retranslate(); // the element tab is named after the topology
}

void MeshDock::updateSummary() {
    const scene::Mesh* m = MeshRef{context_.sharedScene(), shown_mesh_}.get();
    tangent_button_->setEnabled(m != nullptr && m->triangle_count() > 0 &&
                                !tangent_job_.isRunning());
    jump_button_->setEnabled(m != nullptr);
    if (!m) {
        summary_->setText(tr("No primitive selected. Select a node or primitive in the scene tree "
                             "or click an object in the viewport."));
        return;
    }
    std::uint64_t gpu = 0;
    for (int r = 0; r < attributes_->rowCount(); ++r) gpu += attributes_->gpuBytes(r);
    const QString elements =
        m->topology() == scene::Topology::Lines    ? tr("%1 line segments").arg(m->element_count())
        : m->topology() == scene::Topology::Points ? tr("%1 points").arg(m->element_count())
                                                   : tr("%1 triangles").arg(m->triangle_count());
    summary_->setText(tr("Mesh %1 primitive %2 \"%3\": %4 vertices (file: %5), %6, "
                         "material %7, %8 on the GPU%9")
                          .arg(m->group_id)
                          .arg(m->primitive_index)
                          .arg(QString::fromStdString(m->name))
                          .arg(m->vertices.size())
                          .arg(m->source_vertex_count)
                          .arg(elements)
                          .arg(m->material_id)
                          .arg(format::bytes(gpu))
                          .arg(m->unwelded ? tr(" (unwelded for flat normals)") : QString()) +
                      compressionText(*context_.sharedScene(), shown_mesh_));
}

// "; EXT_meshopt_compression ATTRIBUTES/OCTAHEDRAL, TRIANGLES: 12 KB -> 48 KB in
// 0.21 ms" for a primitive the file stores compressed, else empty.
QString MeshDock::compressionText(const scene::Scene& scene, int mesh) {
    for (const scene::PrimitiveInfo& p : scene.primitives) {
        if (p.engine_mesh != mesh || !p.compression) continue;
        const scene::PrimitiveCompression& c = *p.compression;
        return tr("; %1 %2: %3 → %4 decoded in %5 ms")
            .arg(QString::fromStdString(c.codec), QString::fromStdString(c.modes),
                 format::bytes(c.encoded_bytes), format::bytes(c.decoded_bytes))
            .arg(c.decode_ms, 0, 'f', 2);
    }
    return {};
}

void MeshDock::computeTangentErrors() {
    const std::shared_ptr<const scene::Scene> scene = context_.sharedScene();
    const int mesh = shown_mesh_;
    if (!scene || mesh < 0 || tangent_job_.isRunning()) return;
    tangent_button_->setEnabled(false);
    tangent_summary_->setText(tr("Comparing…"));
    tangent_job_.setFuture(
        QtConcurrent::run([scene, mesh]() -> std::shared_ptr<const TangentErrors> {
            const scene::Mesh& m = scene->meshes[static_cast<std::size_t>(mesh)];
            const scene::MaterialInstance& mat = scene->materials[m.material_id];
            // The uv set the normal texture samples decides the tangent frame.
            const std::uint32_t set = mat.normal.present() ? mat.normal.tex_coord : 0;
            return std::make_shared<const TangentErrors>(tangent_errors(m, set));
        }));
}

void MeshDock::jumpToVertex(int vertex) {
    const int row = vertices_->rowOfVertex(vertex);
    if (row < 0) return;
    tabs_->setCurrentIndex(0);
    const QModelIndex index = vertices_->index(row, 0);
    vertex_view_->setCurrentIndex(index);
    vertex_view_->scrollTo(index, QAbstractItemView::PositionAtCenter);
}

} // namespace sherpa::editor
