#include "triangle_table_model.h"

#include "format_values.h"

namespace sherpa::editor {

TriangleTableModel::TriangleTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void TriangleTableModel::setMesh(MeshRef mesh) {
    beginResetModel();
    mesh_ = std::move(mesh);
    endResetModel();
}

int TriangleTableModel::rowCount(const QModelIndex& parent) const {
    const scene::Mesh* m = mesh_.get();
    return parent.isValid() || !m ? 0 : static_cast<int>(m->element_count());
}

int TriangleTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TriangleTableModel::data(const QModelIndex& index, int role) const {
    const scene::Mesh* m = mesh_.get();
    if (!index.isValid() || !m) return {};
    if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
    const bool exact = role == Qt::ToolTipRole || role == format::kExactTextRole;
    if (role != Qt::DisplayRole && !(exact && index.column() == AreaColumn)) return {};
    const std::size_t per = scene::indices_per_element(m->topology());
    const std::size_t t = static_cast<std::size_t>(index.row()) * per;
    switch (index.column()) {
    case IndexColumn:
        return index.row();
    case V0:
    case V1:
    case V2:
        if (std::size_t(index.column() - V0) >= per) return {};
        return m->indices[t + static_cast<std::size_t>(index.column() - V0)];
    case AreaColumn: {
        if (m->topology() == scene::Topology::Points) return {};
        if (m->topology() == scene::Topology::Lines) {
            const double length = static_cast<double>(glm::length(
                m->vertices[m->indices[t + 1]].position - m->vertices[m->indices[t]].position));
            return exact ? format::exact(length) : format::number(length);
        }
        // Degenerate (zero-area) triangles are what breaks tangent generation: show them.
        const glm::vec3 a = m->vertices[m->indices[t]].position;
        const glm::vec3 b = m->vertices[m->indices[t + 1]].position;
        const glm::vec3 c = m->vertices[m->indices[t + 2]].position;
        const double area = 0.5 * static_cast<double>(glm::length(glm::cross(b - a, c - a)));
        return exact ? format::exact(area) : format::number(area);
    }
    default:
        return {};
    }
}

QVariant TriangleTableModel::headerData(int section, Qt::Orientation o, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (o == Qt::Vertical) return section;
    switch (section) {
    case IndexColumn:
        return QStringLiteral("#");
    case V0:
        return tr("vertex 0");
    case V1:
        return tr("vertex 1");
    case V2:
        return tr("vertex 2");
    case AreaColumn: {
        const scene::Mesh* m = mesh_.get();
        return m && m->topology() == scene::Topology::Lines ? tr("length") : tr("area");
    }
    default:
        return {};
    }
}

} // namespace sherpa::editor
