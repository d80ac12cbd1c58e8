#include "instance_table_model.h"

#include "format_values.h"

namespace sherpa::editor {

InstanceTableModel::InstanceTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void InstanceTableModel::setNode(std::shared_ptr<const scene::Scene> scene, int node) {
    beginResetModel();
    scene_ = std::move(scene);
    node_ = node;
    endResetModel();
}

const scene::NodeInstancing* InstanceTableModel::instancing() const {
    if (!scene_ || node_ < 0 || static_cast<std::size_t>(node_) >= scene_->nodes.size())
        return nullptr;
    const auto& g = scene_->nodes[static_cast<std::size_t>(node_)].instancing;
    return g ? &*g : nullptr;
}

int InstanceTableModel::rowCount(const QModelIndex& parent) const {
    const scene::NodeInstancing* g = instancing();
    return parent.isValid() || !g ? 0 : static_cast<int>(g->rows.size());
}

int InstanceTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant InstanceTableModel::data(const QModelIndex& index, int role) const {
    const scene::NodeInstancing* g = instancing();
    if (!g || !index.isValid() || index.row() >= rowCount()) return {};
    const scene::InstanceRow& r = g->rows[static_cast<std::size_t>(index.row())];
    const int c = index.column();
    // glTF order for the quaternion: x, y, z, w.
    const double value =
        c == RowColumn ? double(r.file_row)
        : c <= TZ      ? double(r.translation[c - TX])
        : c <= RW
            ? double(glm::vec4(r.rotation.x, r.rotation.y, r.rotation.z, r.rotation.w)[c - RX])
            : double(r.scale[c - SX]);
    if (role == Qt::DisplayRole)
        return c == RowColumn ? QString::number(r.file_row) : format::number(value);
    if (role == Qt::ToolTipRole && c != RowColumn) return format::exact(value);
    if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant InstanceTableModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case RowColumn:
        return tr("Row");
    case TX:
        return tr("T.x");
    case TY:
        return tr("T.y");
    case TZ:
        return tr("T.z");
    case RX:
        return tr("R.x");
    case RY:
        return tr("R.y");
    case RZ:
        return tr("R.z");
    case RW:
        return tr("R.w");
    case SX:
        return tr("S.x");
    case SY:
        return tr("S.y");
    case SZ:
        return tr("S.z");
    default:
        return {};
    }
}

} // namespace sherpa::editor
