#include "attribute_model.h"

#include <QStringList>

#include <sherpa/scene/usage_report.h>

#include "format_values.h"

namespace sherpa::editor {

namespace {
QString list(const std::vector<double>& values) {
    if (values.empty()) return QStringLiteral("—");
    QStringList parts;
    for (double v : values) parts << format::number(v);
    return QStringLiteral("[") + parts.join(QStringLiteral(", ")) + QStringLiteral("]");
}
} // namespace

AttributeModel::AttributeModel(QObject* parent) : QAbstractTableModel(parent) {}

void AttributeModel::setMesh(MeshRef mesh) {
    beginResetModel();
    mesh_ = std::move(mesh);
    used_ = {};
    if (const scene::Mesh* m = mesh_.get())
        // The renderer's default upload policy: the streams the material's shading reads.
        used_ = scene::attributes_used(mesh_.scene->materials[m->material_id], *m);
    endResetModel();
}

std::uint64_t AttributeModel::gpuBytes(int row) const {
    const scene::Mesh* m = mesh_.get();
    if (!m) return 0;
    if (row == kIndexRow) return m->indices.size() * sizeof(std::uint32_t);
    const auto a = static_cast<std::size_t>(row);
    if (!used_[a]) return 0;
    return static_cast<std::uint64_t>(stream_stride(scene::kAllVertexAttributes[a])) *
           m->vertices.size();
}

int AttributeModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !mesh_.get() ? 0 : kIndexRow + 1;
}

int AttributeModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant AttributeModel::data(const QModelIndex& index, int role) const {
    const scene::Mesh* m = mesh_.get();
    if (!index.isValid() || !m) return {};
    if (role == Qt::ToolTipRole && index.column() == ComponentTypeColumn) {
        const std::optional<scene::AccessorSource>& s =
            index.row() == kIndexRow ? m->index_source
                                     : m->sources[static_cast<std::size_t>(index.row())];
        return s ? QStringLiteral("%1 x%2%3")
                       .arg(format::componentType(s->component_type))
                       .arg(s->components)
                       .arg(s->normalized ? tr(", normalized") : QString())
                 : QVariant();
    }
    if (role != Qt::DisplayRole) return {};
    const int row = index.row();
    const bool is_index = row == kIndexRow;
    const std::optional<scene::AccessorSource>& src =
        is_index ? m->index_source : m->sources[static_cast<std::size_t>(row)];
    switch (index.column()) {
    case AttributeColumn:
        return is_index
                   ? tr("indices")
                   : format::attribute(scene::kAllVertexAttributes[static_cast<std::size_t>(row)]);
    case ProvenanceColumn:
        if (is_index) return src ? tr("authored") : tr("generated");
        return format::provenance(m->provenance[static_cast<std::size_t>(row)]);
    case GpuBytesColumn: {
        const std::uint64_t b = gpuBytes(row);
        return b ? format::bytes(b) : tr("not uploaded");
    }
    default:
        break;
    }
    if (!src) return QStringLiteral("—");
    switch (index.column()) {
    case AccessorColumn:
        return src->accessor;
    case ComponentTypeColumn:
        // Compact (f32×3): the column must fit a side dock; the glTF name on hover.
        return QStringLiteral("%1×%2")
            .arg(format::componentTypeShort(src->component_type))
            .arg(src->components);
    case NormalizedColumn:
        return format::yesNo(src->normalized);
    case CountColumn:
        return src->count;
    case MinColumn:
        return list(src->min);
    case MaxColumn:
        return list(src->max);
    case SparseColumn:
        return src->sparse ? tr("yes (%1 values)").arg(src->sparse_count) : format::yesNo(false);
    case BufferViewColumn:
        return src->buffer_view < 0
                   ? tr("none")
                   : tr("%1 (stride %2)").arg(src->buffer_view).arg(src->byte_stride);
    default:
        return {};
    }
}

QVariant AttributeModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case AttributeColumn:
        return tr("Attribute");
    case ProvenanceColumn:
        return tr("Provenance");
    case AccessorColumn:
        return tr("Accessor");
    case ComponentTypeColumn:
        return tr("Component");
    case NormalizedColumn:
        return tr("Normalized");
    case CountColumn:
        return tr("Count");
    case MinColumn:
        return tr("Min");
    case MaxColumn:
        return tr("Max");
    case SparseColumn:
        return tr("Sparse");
    case BufferViewColumn:
        return tr("Buffer view");
    case GpuBytesColumn:
        return tr("GPU bytes");
    default:
        return {};
    }
}

} // namespace sherpa::editor
