#pragma once
// Every texture of the scene with its thumbnail, source, role and sizes. Columns
// that only the texture pipeline can fill (hash, GPU format, mips, bytes on disk and
// GPU, cache state, decode/encode time, PSNR) come from the session's prepared set
// (the textures the viewport uploads) and show "—" without one.
#include <QAbstractTableModel>

#include <memory>

#include <sherpa/scene/scene.h>

#include "scene_session.h"

namespace sherpa::editor {

class TextureTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        NameColumn,
        SourceColumn,
        HashColumn,
        RoleColumn,
        FormatColumn,
        SizeColumn,
        MipsColumn,
        DiskBytesColumn,
        GpuBytesColumn,
        CacheStateColumn,
        DecodeMsColumn,
        EncodeMsColumn,
        PsnrColumn,
        ContainerColumn, // png, jpeg, webp, ktx2-etc1s / ktx2-uastc with supercompression
        ColumnCount
    };
    explicit TextureTableModel(QObject* parent = nullptr);
    // The scene's textures, thumbnails and the texture pipeline's records (null: none).
    void setSession(SharedSession session);
    // Encoded bytes of every image referenced by a texture (each image once).
    std::uint64_t totalDiskBytes() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

    // The pipeline record of glTF texture `texture` in `session` (its first prepared
    // role), or null (no prepared textures: no device).
    static const tex::PreparedTexture* preparedRecord(const SceneSession& session, int texture);
    // The record's cache state as the dock's column says it ("hit", "missing: FILE"...).
    static QString cacheStateText(const tex::PreparedTexture& r);

private:
    QVariant cacheData(std::size_t row, int column) const; // "—" without a record

    const scene::Scene* scene() const;               // null without a session
    const tex::PreparedTextureSet* prepared() const; // null without prepared textures

    SharedSession session_;
};

} // namespace sherpa::editor
