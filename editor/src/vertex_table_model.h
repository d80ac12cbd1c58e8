#pragma once
// Every vertex of one primitive, one column per component. data() reads straight
// from Mesh::vertices (no copy into Qt containers), so a million rows cost nothing
// until they scroll into view. Sorting keeps a permutation of row numbers only.
#include <QAbstractTableModel>

#include <memory>
#include <vector>

#include "mesh_models_common.h"
#include "tangent_error.h"
#include "vertex_motion_columns.h"

namespace sherpa::editor {

class VertexTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        IndexColumn,
        PosX,
        PosY,
        PosZ,
        NrmX,
        NrmY,
        NrmZ,
        Uv0U,
        Uv0V,
        TanX,
        TanY,
        TanZ,
        TanW,
        Uv1U,
        Uv1V,
        ColR,
        ColG,
        ColB,
        ColA,
        TangentErrorColumn,
        ColumnCount // then the motion columns of skinned or morphed primitives
    };
    static constexpr int VertexRole = Qt::UserRole + 1; // engine vertex index of a row

    explicit VertexTableModel(QObject* parent = nullptr);

    void setMesh(MeshRef mesh);
    void setTangentErrors(std::shared_ptr<const TangentErrors> errors);
    const MeshRef& mesh() const { return mesh_; }
    const VertexMotionColumns& motionColumns() const { return motion_; }
    // Row showing engine vertex `vertex` under the current sort (-1 if out of range).
    int rowOfVertex(int vertex) const;
    int vertexOfRow(int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;
    void sort(int column, Qt::SortOrder order) override;

private:
    double value(std::size_t vertex, int column) const;

    MeshRef mesh_;
    std::shared_ptr<const TangentErrors> errors_;
    VertexMotionColumns motion_;         // JOINTS/WEIGHTS, morph deltas, after ColumnCount
    std::vector<std::uint32_t> order_;   // row -> vertex; empty: identity
    std::vector<std::uint32_t> inverse_; // vertex -> row, built with order_
};

} // namespace sherpa::editor
