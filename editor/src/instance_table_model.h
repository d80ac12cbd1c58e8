#pragma once
// The EXT_mesh_gpu_instancing rows of one node, one column per component: what each
// of its instances is placed by (node world x T x R x S). data() reads straight from
// Node::instancing, like the vertex table.
#include <QAbstractTableModel>

#include <memory>

#include <sherpa/scene/scene.h>

namespace sherpa::editor {

class InstanceTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { RowColumn, TX, TY, TZ, RX, RY, RZ, RW, SX, SY, SZ, ColumnCount };

    explicit InstanceTableModel(QObject* parent = nullptr);

    // The rows of `node` (none when it is not instanced); `scene` is kept alive.
    void setNode(std::shared_ptr<const scene::Scene> scene, int node);
    const scene::NodeInstancing* instancing() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    std::shared_ptr<const scene::Scene> scene_;
    int node_ = -1;
};

} // namespace sherpa::editor
