#include "texture_table_model.h"

#include <QFileInfo>
#include <bit>
#include <cmath>
#include <set>

#include <sherpa/scene/image_sources.h>
#include <sherpa/texture/image_container.h>
#include <sherpa/texture/texture_pipeline.h>

#include "format_values.h"

namespace sherpa::editor {

TextureTableModel::TextureTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void TextureTableModel::setSession(SharedSession session) {
    beginResetModel();
    session_ = std::move(session);
    endResetModel();
}

const scene::Scene* TextureTableModel::scene() const {
    return session_ ? session_->scene.get() : nullptr;
}

const tex::PreparedTextureSet* TextureTableModel::prepared() const {
    return session_ ? session_->textures.get() : nullptr;
}

const tex::PreparedTexture* TextureTableModel::preparedRecord(const SceneSession& session,
                                                              int texture) {
    const tex::PreparedTextureSet* set = session.textures.get();
    if (!set) return nullptr;
    // The first role this texture is prepared in (a texture used as colour and as
    // data has two records; the dock shows one row per glTF texture).
    for (scene::TextureRole role : {scene::kRoleColor, scene::kRoleLinear, scene::kRoleNormal})
        if (const std::int32_t i = set->find(texture, role); i >= 0)
            return &set->textures[static_cast<std::size_t>(i)];
    return nullptr;
}

QString TextureTableModel::cacheStateText(const tex::PreparedTexture& r) {
    // What failed, not a cache state: "missing: FILE" or "undecodable".
    if (r.state == tex::CacheState::Missing)
        return tr("missing: %1").arg(QFileInfo(QString::fromStdString(r.location)).fileName());
    if (r.state == tex::CacheState::Undecodable) return tr("undecodable");
    if (r.failed) return tr("failed");
    switch (r.state) {
    case tex::CacheState::Hit:
        return tr("hit");
    case tex::CacheState::Miss:
        return tr("miss");
    case tex::CacheState::Stale:
        return tr("stale");
    case tex::CacheState::Recompressed:
        return tr("recompressed");
    case tex::CacheState::Fallback:
        return tr("fallback");
    case tex::CacheState::Missing:
    case tex::CacheState::Undecodable:
        break; // answered above
    }
    return QStringLiteral("—");
}

QVariant TextureTableModel::cacheData(std::size_t row, int column) const {
    const QString none = QStringLiteral("—");
    if (!prepared() || !scene()) return none;
    const tex::PreparedTexture* r = preparedRecord(*session_, static_cast<int>(row));
    if (!r) return none;
    switch (column) {
    case HashColumn: {
        // Both ends of the 32 digits, the middle elided; all of them on hover and copy.
        const QString hex = QString::fromStdString(r->source_hash.hex());
        return hex.left(8) + QChar(0x2026) + hex.right(8);
    }
    case FormatColumn: {
        QString f =
            QString::fromLatin1(tex::vk_format_name(r->format).data(),
                                static_cast<qsizetype>(tex::vk_format_name(r->format).size()));
        return f.remove(QStringLiteral("VK_FORMAT_")).remove(QStringLiteral("_BLOCK"));
    }
    case MipsColumn: {
        if (!r->levels.empty()) return static_cast<int>(r->levels.size());
        return r->width ? static_cast<int>(std::bit_width(std::max(r->width, r->height))) : 0;
    }
    case DiskBytesColumn:
        return r->bytes_on_disk ? format::bytes(r->bytes_on_disk) : none;
    case GpuBytesColumn:
        return format::bytes(r->bytes_gpu);
    case CacheStateColumn:
        return cacheStateText(*r);
    case DecodeMsColumn:
        return QString::number(r->decode_ms, 'f', 1);
    case EncodeMsColumn:
        return QString::number(r->mip_ms + r->encode_ms, 'f', 1);
    case PsnrColumn:
        if (!r->psnr) return none;
        return std::isinf(*r->psnr) ? QStringLiteral("∞") : QString::number(*r->psnr, 'f', 2);
    default:
        return none;
    }
}

std::uint64_t TextureTableModel::totalDiskBytes() const {
    if (!scene()) return 0;
    std::set<std::int32_t> images;
    std::uint64_t total = 0;
    for (const scene::TextureRecord& t : scene()->textures)
        if (t.image >= 0 && images.insert(t.image).second)
            total += scene()->images[static_cast<std::size_t>(t.image)].byte_size;
    return total;
}

int TextureTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || !scene() ? 0 : static_cast<int>(scene()->textures.size());
}

int TextureTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TextureTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !scene()) return {};
    const auto row = static_cast<std::size_t>(index.row());
    const scene::TextureRecord& t = scene()->textures[row];
    const scene::ImageRecord* img =
        t.image >= 0 ? &scene()->images[static_cast<std::size_t>(t.image)] : nullptr;
    if (role == Qt::DecorationRole && index.column() == NameColumn && session_ &&
        row < session_->thumbnails.size() && !session_->thumbnails[row].isNull())
        return session_->thumbnails[row];
    if ((role == Qt::ToolTipRole || role == format::kExactTextRole) &&
        index.column() == HashColumn) {
        const tex::PreparedTexture* r = preparedRecord(*session_, static_cast<int>(row));
        return r ? QVariant(QString::fromStdString(r->source_hash.hex())) : QVariant();
    }
    // A failed texture's whole story (file, reason, the slots that read it) on hover.
    if (role == Qt::ToolTipRole && img &&
        (index.column() == SizeColumn || index.column() == CacheStateColumn)) {
        if (const tex::PreparedTexture* r = preparedRecord(*session_, static_cast<int>(row));
            r && r->failed) {
            QString tip = QString::fromStdString(r->note);
            for (const std::string& use : r->uses)
                tip += QStringLiteral("\n") + QString::fromStdString(use);
            return tip;
        }
        return {};
    }
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
        return format::roles(t.roles);
    case SizeColumn: {
        if (!img || !session_ || static_cast<std::size_t>(t.image) >= session_->image_sizes.size())
            return QStringLiteral("—");
        const QSize s = session_->image_sizes[static_cast<std::size_t>(t.image)];
        if (scene::image_is_missing(*img))
            return tr("missing: %1").arg(QFileInfo(QString::fromStdString(img->uri)).fileName());
        return s.isEmpty() ? tr("undecodable")
                           : QStringLiteral("%1 × %2").arg(s.width()).arg(s.height());
    }
    case FormatColumn:
        if (prepared()) return cacheData(row, index.column()); // what the GPU samples
        return img ? QString::fromStdString(img->mime_type) : QString();
    case ContainerColumn: {
        // Decode ms is the transcode for KTX2 sources (the pipeline's decode step).
        if (!img || img->encoded.empty()) return img ? tr("generated") : QString();
        const tex::ImageContainer c = tex::image_container(img->encoded);
        return c.supercompression.empty()
                   ? QString::fromStdString(c.name)
                   : QStringLiteral("%1 · %2").arg(QString::fromStdString(c.name),
                                                   QString::fromStdString(c.supercompression));
    }
    case DiskBytesColumn:
        // The cache's KTX2 file once there is one, else the encoded source.
        if (QVariant v = cacheData(row, DiskBytesColumn); v != QStringLiteral("—")) return v;
        return img ? format::bytes(img->byte_size) : QString();
    default:
        return cacheData(row, index.column());
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
    case CacheStateColumn: // short: the dock's first column, beside the texture
        return tr("State");
    case DecodeMsColumn:
        return tr("Decode ms");
    case EncodeMsColumn:
        return tr("Encode ms");
    case PsnrColumn:
        return tr("PSNR");
    case ContainerColumn:
        return tr("Container");
    default:
        return {};
    }
}

} // namespace sherpa::editor
