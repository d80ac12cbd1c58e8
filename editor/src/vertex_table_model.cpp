#include "vertex_table_model.h"

#include <QBrush>
#include <QColor>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "format_values.h"

namespace sherpa::editor {

VertexTableModel::VertexTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void VertexTableModel::setMesh(MeshRef mesh) {
    beginResetModel();
    mesh_ = std::move(mesh);
    motion_.set(mesh_.scene.get(), mesh_.mesh);
    errors_.reset();
    order_.clear();
    inverse_.clear();
    endResetModel();
}

void VertexTableModel::setTangentErrors(std::shared_ptr<const TangentErrors> errors) {
    errors_ = std::move(errors);
    if (rowCount() > 0)
        Q_EMIT dataChanged(index(0, TangentErrorColumn), index(rowCount() - 1, TangentErrorColumn));
}

int VertexTableModel::rowCount(const QModelIndex& parent) const {
    const scene::Mesh* m = mesh_.get();
    return parent.isValid() || !m ? 0 : static_cast<int>(m->vertices.size());
}

int VertexTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount + motion_.count();
}

int VertexTableModel::vertexOfRow(int row) const {
    return order_.empty() ? row : static_cast<int>(order_[static_cast<std::size_t>(row)]);
}

int VertexTableModel::rowOfVertex(int vertex) const {
    if (vertex < 0 || vertex >= rowCount()) return -1;
    return inverse_.empty() ? vertex : static_cast<int>(inverse_[static_cast<std::size_t>(vertex)]);
}

double VertexTableModel::value(std::size_t v, int column) const {
    const scene::Mesh& m = *mesh_.get();
    const scene::Vertex& x = m.vertices[v];
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    switch (column) {
    case IndexColumn:
        return static_cast<double>(v);
    case PosX:
    case PosY:
    case PosZ:
        return x.position[column - PosX];
    case NrmX:
    case NrmY:
    case NrmZ:
        return x.normal[column - NrmX];
    case Uv0U:
    case Uv0V:
        return x.uv0[column - Uv0U];
    case TanX:
    case TanY:
    case TanZ:
    case TanW:
        return x.tangent[column - TanX];
    case Uv1U:
    case Uv1V:
        return x.uv1[column - Uv1U];
    case ColR:
    case ColG:
    case ColB:
    case ColA:
        return v < m.colors.size() ? m.colors[v][column - ColR] : nan;
    case TangentErrorColumn:
        return errors_ && v < errors_->degrees.size() ? errors_->degrees[v] : nan;
    default:
        return column > TangentErrorColumn ? motion_.key(v, column - ColumnCount) : nan;
    }
}

QVariant VertexTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !mesh_.get()) return {};
    const auto v = static_cast<std::size_t>(vertexOfRow(index.row()));
    if (role == VertexRole) return static_cast<int>(v);
    if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
    // Views ask for a dozen roles per cell; only these need the value. Shown at four
    // significant digits so that #, x, y and z fit a side dock; the float's exact
    // text on hover and copy.
    if (role == Qt::DisplayRole || role == Qt::ToolTipRole || role == format::kExactTextRole) {
        if (index.column() == IndexColumn) return static_cast<qulonglong>(v);
        if (index.column() >= ColumnCount) return motion_.text(v, index.column() - ColumnCount);
        const double x = value(v, index.column());
        if (std::isnan(x)) return QStringLiteral("—");
        return role == Qt::DisplayRole ? format::compact(x) : format::exact(x);
    }
    if (role == Qt::ForegroundRole && index.column() == TangentErrorColumn &&
        value(v, index.column()) > 5.0)
        return QBrush(QColor(220, 80, 60)); // large disagreement stands out when scrolling
    return {};
}

QVariant VertexTableModel::headerData(int section, Qt::Orientation o, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (o == Qt::Vertical) return section;
    static const char* const kHeaders[ColumnCount] = {
        "#",     "pos.x", "pos.y", "pos.z", "nrm.x", "nrm.y", "nrm.z", "uv0.u", "uv0.v", "tan.x",
        "tan.y", "tan.z", "tan.w", "uv1.u", "uv1.v", "col.r", "col.g", "col.b", "col.a", nullptr};
    if (section == TangentErrorColumn) return tr("tangent error (deg)");
    if (section >= 0 && section < ColumnCount) return QString::fromLatin1(kHeaders[section]);
    if (section >= ColumnCount) return motion_.header(section - ColumnCount);
    return {};
}

void VertexTableModel::sort(int column, Qt::SortOrder order) {
    if (!mesh_.get()) return;
    Q_EMIT layoutAboutToBeChanged({}, QAbstractItemModel::VerticalSortHint);
    const QModelIndexList persistent = persistentIndexList();
    std::vector<int> persistent_vertex;
    for (const QModelIndex& i : persistent) persistent_vertex.push_back(vertexOfRow(i.row()));

    const std::size_t n = mesh_.get()->vertices.size();
    // Keys first (one pass over the vertices), then an index sort on plain doubles:
    // several times faster than calling value() inside the comparator.
    std::vector<double> keys(n);
    for (std::size_t v = 0; v < n; ++v) keys[v] = value(v, column);
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    // NaN ("no value") sorts last in both directions.
    const bool ascending = order == Qt::AscendingOrder;
    std::stable_sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
        const double x = keys[a], y = keys[b];
        if (std::isnan(x) || std::isnan(y)) return !std::isnan(x) && std::isnan(y);
        return ascending ? x < y : x > y;
    });
    inverse_.resize(n);
    for (std::size_t r = 0; r < n; ++r) inverse_[order_[r]] = static_cast<std::uint32_t>(r);

    QModelIndexList moved;
    for (qsizetype i = 0; i < persistent.size(); ++i)
        moved << index(rowOfVertex(persistent_vertex[static_cast<std::size_t>(i)]),
                       persistent[i].column());
    changePersistentIndexList(persistent, moved);
    Q_EMIT layoutChanged({}, QAbstractItemModel::VerticalSortHint);
}

} // namespace sherpa::editor
