#pragma once
// One row per vertex attribute of the selected primitive (plus its indices): the
// source accessor as the file declares it, where the values came from, and the
// bytes the GPU holds for it (only streams the material reads are uploaded).
#include <QAbstractTableModel>

#include <array>

#include "mesh_models_common.h"

namespace sherpa::editor {

class AttributeModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        AttributeColumn,
        ProvenanceColumn,
        AccessorColumn,
        ComponentTypeColumn,
        NormalizedColumn,
        CountColumn,
        MinColumn,
        MaxColumn,
        SparseColumn,
        BufferViewColumn,
        GpuBytesColumn,
        ColumnCount
    };
    static constexpr int kIndexRow = static_cast<int>(scene::kVertexAttributeCount);

    explicit AttributeModel(QObject* parent = nullptr);
    void setMesh(MeshRef mesh);
    // Bytes on the GPU for a row (0 when the stream is not uploaded).
    std::uint64_t gpuBytes(int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    MeshRef mesh_;
    std::array<bool, scene::kVertexAttributeCount> used_{};
};

} // namespace sherpa::editor
