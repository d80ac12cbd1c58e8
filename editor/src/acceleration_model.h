#pragma once
// The loaded scene's bottom-level acceleration structures, one row per BLAS (one
// per glTF mesh): what sherpa-cli rt prints, from the engine's AccelerationStats
// gathered on the render thread after the upload. Read-only; the mesh of a row
// (MeshRole) is how the dock turns a row into a selection.
#include <QAbstractTableModel>

#include <memory>

namespace sherpa::render {
struct AccelerationStats;
} // namespace sherpa::render

namespace sherpa::editor {

class AccelerationModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        MeshColumn,
        GeometriesColumn,
        TrianglesColumn,
        BuildMsColumn,
        BuiltBytesColumn,
        CompactedBytesColumn,
        ScratchBytesColumn,
        ColumnCount
    };
    enum Role { MeshRole = Qt::UserRole + 1 }; // the glTF mesh (Mesh::group_id)

    explicit AccelerationModel(QObject* parent = nullptr);
    // Null: no structures (ray tracing off, no scene).
    void setStats(std::shared_ptr<const render::AccelerationStats> stats);
    const render::AccelerationStats* stats() const { return stats_.get(); }
    // The row of glTF mesh `mesh`, or -1.
    int rowOfMesh(int mesh) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    std::shared_ptr<const render::AccelerationStats> stats_;
};

} // namespace sherpa::editor
