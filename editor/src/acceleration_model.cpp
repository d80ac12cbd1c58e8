#include "acceleration_model.h"

#include <sherpa/render/acceleration_structures.h>

#include "format_values.h"

namespace sherpa::editor {

AccelerationModel::AccelerationModel(QObject* parent) : QAbstractTableModel(parent) {}

void AccelerationModel::setStats(std::shared_ptr<const render::AccelerationStats> stats) {
    beginResetModel();
    stats_ = std::move(stats);
    endResetModel();
}

int AccelerationModel::rowOfMesh(int mesh) const {
    if (!stats_) return -1;
    for (std::size_t i = 0; i < stats_->blas.size(); ++i)
        if (static_cast<int>(stats_->blas[i].mesh) == mesh) return static_cast<int>(i);
    return -1;
}

int AccelerationModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !stats_ ? 0 : static_cast<int>(stats_->blas.size());
}

int AccelerationModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant AccelerationModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !stats_) return {};
    const render::BlasStats& b = stats_->blas[static_cast<std::size_t>(index.row())];
    if (role == MeshRole) return static_cast<int>(b.mesh);
    if (role == Qt::TextAlignmentRole && index.column() != MeshColumn)
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole && index.column() == GeometriesColumn)
        return tr("%1 geometries (one per triangle primitive), %2 of them opaque (no any-hit)")
            .arg(b.geometries)
            .arg(b.opaque_geometries);
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
    case MeshColumn:
        return b.name.empty() ? tr("mesh %1").arg(b.mesh) : QString::fromStdString(b.name);
    case GeometriesColumn:
        return QStringLiteral("%1 (%2)").arg(b.geometries).arg(b.opaque_geometries);
    case TrianglesColumn:
        return QString::number(b.triangles);
    case BuildMsColumn:
        return b.build_ms < 0.0 ? QStringLiteral("—") : QString::number(b.build_ms, 'f', 2);
    case BuiltBytesColumn:
        return format::bytes(b.build_bytes);
    case CompactedBytesColumn:
        return format::bytes(b.compacted_bytes);
    case ScratchBytesColumn:
        return format::bytes(b.scratch_bytes);
    }
    return {};
}

QVariant AccelerationModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal) return {};
    if (role == Qt::ToolTipRole && section == GeometriesColumn) return tr("Geometries (opaque)");
    if (role != Qt::DisplayRole) return {};
    switch (section) {
    case MeshColumn:
        return tr("Mesh");
    case GeometriesColumn:
        return tr("Geometries");
    case TrianglesColumn:
        return tr("Triangles");
    case BuildMsColumn:
        return tr("Build ms");
    case BuiltBytesColumn:
        return tr("Built");
    case CompactedBytesColumn:
        return tr("Compacted");
    case ScratchBytesColumn:
        return tr("Scratch");
    }
    return {};
}

} // namespace sherpa::editor
