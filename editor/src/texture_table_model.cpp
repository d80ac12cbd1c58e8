#include "texture_table_model.h"

#include <QFileInfo>
#include <set>

#include "format_values.h"

namespace sherpa::editor {

TextureTableModel::TextureTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void TextureTableModel::setScene(std::shared_ptr<const Scene> scene,
                                 std::shared_ptr<const SceneExtras> extras) {
    beginResetModel();
    scene_ = std::move(scene);
    extras_ = std::move(extras);
    endResetModel();
}

std::uint64_t TextureTableModel::totalDiskBytes() const {
    if (!scene_) return 0;
    std::set<std::int32_t> images;
    std::uint64_t total = 0;
    for (const TextureRecord& t : scene_->textures)
        if (t.image >= 0 && images.insert(t.image).second)
            total += scene_->images[static_cast<std::size_t>(t.image)].byte_size;
    return total;
}

int TextureTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !scene_ ? 0 : static_cast<int>(scene_->textures.size());
}

int TextureTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TextureTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !scene_) return {};
    const auto row = static_cast<std::size_t>(index.row());
    const TextureRecord& t = scene_->textures[row];
    const ImageRecord* img =
        t.image >= 0 ? &scene_->images[static_cast<std::size_t>(t.image)] : nullptr;
    if (role == Qt::DecorationRole && index.column() == NameColumn && extras_ &&
        row < extras_->thumbnails.size() && !extras_->thumbnails[row].isNull())
        return extras_->thumbnails[row];
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
    case NameColumn:
        return t.name.empty() ? tr("Texture %1").arg(index.row()) : QString::fromStdString(t.name);
    case SourceColumn:
        if (!img) return tr("no image");
        if (!img->uri.empty()) return QFileInfo(QString::fromStdString(img->uri)).fileName();
        if (img->buffer_view >= 0) return tr("bufferView %1").arg(img->buffer_view);
        return tr("generated");
    case RoleColumn:
        return Format::roles(t.roles);
    case FormatColumn:
        return img ? QString::fromStdString(img->mime_type) : QString();
    case SizeColumn: {
        if (!img || !extras_ || static_cast<std::size_t>(t.image) >= extras_->image_sizes.size())
            return QStringLiteral("—");
        const QSize s = extras_->image_sizes[static_cast<std::size_t>(t.image)];
        return s.isEmpty() ? tr("undecodable")
                           : QStringLiteral("%1 × %2").arg(s.width()).arg(s.height());
    }
    case DiskBytesColumn:
        return img ? Format::bytes(img->byte_size) : QString();
    case DecodeMsColumn:
        return QStringLiteral("—");
    default:
        return QStringLiteral("—"); // filled by the texture cache's report
    }
}

QVariant TextureTableModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case NameColumn:
        return tr("Texture");
    case SourceColumn:
        return tr("Source");
    case HashColumn:
        return tr("Content hash");
    case RoleColumn:
        return tr("Role");
    case FormatColumn:
        return tr("Format");
    case SizeColumn:
        return tr("Size");
    case MipsColumn:
        return tr("Mips");
    case DiskBytesColumn:
        return tr("Disk bytes");
    case GpuBytesColumn:
        return tr("GPU bytes");
    case CacheStateColumn:
        return tr("Cache state");
    case DecodeMsColumn:
        return tr("Decode ms");
    case EncodeMsColumn:
        return tr("Encode ms");
    case PsnrColumn:
        return tr("PSNR");
    default:
        return {};
    }
}

} // namespace sherpa::editor
