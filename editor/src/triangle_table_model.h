#pragma once
// Elements of one primitive straight from Mesh::indices: triangles (three vertices
// and the area), line segments (two vertices and the length) or points (one vertex).
#include <QAbstractTableModel>

#include "mesh_models_common.h"

namespace sherpa::editor {

class TriangleTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { IndexColumn, V0, V1, V2, AreaColumn, ColumnCount };
    explicit TriangleTableModel(QObject* parent = nullptr);
    void setMesh(MeshRef mesh);
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    MeshRef mesh_;
};

} // namespace sherpa::editor
