#include "acceleration_dock.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableView>
#include <QVBoxLayout>

#include <sherpa/render/acceleration_structures.h>

#include "acceleration_model.h"
#include "editor_context.h"
#include "format_values.h"

namespace sherpa::editor {

AccelerationDock::AccelerationDock(const EditorContext& context, QWidget* parent)
    : QDockWidget(parent), context_(context) {
    setObjectName(QStringLiteral("accelerationDock"));
    model_ = new AccelerationModel(this);
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    view_ = new QTableView(body);
    view_->setModel(model_);
    view_->verticalHeader()->hide();
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    view_->setWordWrap(false);
    summary_ = new QLabel(body);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(view_);
    layout->addWidget(summary_);
    setWidget(body);
    connect(view_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                if (current.isValid()) onRowChanged(current.row());
            });
    connect(&context_.selection(), &SceneSelection::changed, this,
            &AccelerationDock::syncSelection);
    retranslate();
}

void AccelerationDock::retranslate() {
    setWindowTitle(tr("Acceleration Structures"));
    updateSummary();
}

void AccelerationDock::setStats(std::shared_ptr<const render::AccelerationStats> stats,
                                const QString& why_none) {
    why_none_ = why_none;
    model_->setStats(std::move(stats));
    view_->resizeColumnsToContents();
    updateSummary();
    syncSelection();
}

QString AccelerationDock::summaryText() const {
    return summary_->text();
}

void AccelerationDock::onRowChanged(int row) {
    const scene::Scene* scene = context_.scene();
    if (syncing_ || !scene) return;
    const int gltf_mesh = model_->index(row, 0).data(AccelerationModel::MeshRole).toInt();
    // The BLAS is the glTF mesh: its first primitive, as placed by the first node.
    for (const scene::MeshInstance& inst : scene->instances)
        if (static_cast<int>(scene->meshes[inst.mesh_id].group_id) == gltf_mesh) {
            Q_EMIT selectMeshRequested(static_cast<int>(inst.mesh_id),
                                       static_cast<int>(inst.node_id));
            return;
        }
}

void AccelerationDock::syncSelection() {
    const scene::Scene* scene = context_.scene();
    const int mesh = context_.selection().current().mesh;
    if (!scene || mesh < 0 || static_cast<std::size_t>(mesh) >= scene->meshes.size()) return;
    const int row =
        model_->rowOfMesh(static_cast<int>(scene->meshes[static_cast<std::size_t>(mesh)].group_id));
    if (row < 0 || view_->currentIndex().row() == row) return;
    // The selection made elsewhere must not echo back as a new action.
    syncing_ = true;
    view_->setCurrentIndex(model_->index(row, 0));
    view_->scrollTo(model_->index(row, 0));
    syncing_ = false;
}

void AccelerationDock::updateSummary() {
    const render::AccelerationStats* s = model_->stats();
    if (!s) {
        summary_->setText(why_none_);
        return;
    }
    const render::TlasStats& t = s->tlas;
    const double ratio = s->blas_build_bytes() > 0
                             ? double(s->blas_compacted_bytes()) / double(s->blas_build_bytes())
                             : 1.0;
    QString text =
        tr("%1 BLAS, %2 triangles, %3 built, %4 compacted (%5%), %6 batches, built in %7 ms")
            .arg(s->blas.size())
            .arg(s->blas_triangles())
            .arg(format::bytes(s->blas_build_bytes()))
            .arg(format::bytes(s->blas_compacted_bytes()))
            .arg(qRound(ratio * 100.0))
            .arg(s->batches)
            .arg(s->build_wall_ms, 0, 'f', 1);
    text += QLatin1Char('\n') +
            tr("TLAS: %1 instances of %2 node/mesh pairs, %3 deduplicated, %4 mirrored, %5 "
               "hidden, %6 non-finite; %7")
                .arg(t.instances)
                .arg(t.node_mesh_pairs)
                .arg(t.deduplicated)
                .arg(t.mirrored)
                .arg(t.hidden)
                .arg(t.non_finite)
                .arg(format::bytes(t.bytes));
    text += QLatin1Char('\n') + tr("Total on the GPU: %1 (scratch buffer %2)")
                                    .arg(format::bytes(s->total_bytes()))
                                    .arg(format::bytes(s->scratch_buffer_bytes));
    summary_->setText(text);
}

} // namespace sherpa::editor
