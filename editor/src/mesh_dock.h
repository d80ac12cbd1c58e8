#pragma once
// Dock 2: the selected primitive's attributes (source accessor, provenance, GPU
// bytes) and virtual tables of its vertices and triangles (and of the selected
// node's GPU instancing rows), with jump-to-vertex and
// the per-vertex authored-vs-regenerated tangent error (computed on request, off
// the UI thread).
#include <QDockWidget>
#include <QFutureWatcher>

#include <memory>

#include "tangent_error.h"

class QLabel;
class QPushButton;
class QSpinBox;
class QTableView;
class QTabWidget;

namespace sherpa::editor {

class AttributeModel;
class EditorContext;
class InstanceTableModel;
class TriangleTableModel;
class VertexTableModel;

class MeshDock : public QDockWidget {
    Q_OBJECT
public:
    explicit MeshDock(const EditorContext& context, QWidget* parent = nullptr);
    ~MeshDock() override;
    void retranslate();
    AttributeModel* attributes() const { return attributes_; }
    VertexTableModel* vertices() const { return vertices_; }
    TriangleTableModel* triangles() const { return triangles_; }
    // The selected node's EXT_mesh_gpu_instancing rows (the Instances tab).
    InstanceTableModel* instances() const { return instances_; }
    QTableView* vertexView() const { return vertex_view_; }
    // Starts the tangent comparison for the shown mesh; `tangentErrorsReady` follows.
    void computeTangentErrors();
    // Scrolls the vertex table to a vertex and selects it (what "jump to vertex" does).
    void jumpToVertex(int vertex);
    // The summary's compression clause for engine mesh `mesh` ("; codec modes: encoded
    // -> decoded in N ms"), empty for a primitive the file does not compress.
    static QString compressionText(const scene::Scene& scene, int mesh);

Q_SIGNALS:
    void selectVertexRequested(int vertex);
    void selectTriangleRequested(int triangle);
    void tangentErrorsReady();

private:
    void showMesh();
    void updateSummary();

    const EditorContext& context_;
    int shown_mesh_ = -1;
    int shown_node_ = -1;
    const void* shown_scene_ = nullptr;
    AttributeModel* attributes_;
    VertexTableModel* vertices_;
    TriangleTableModel* triangles_;
    InstanceTableModel* instances_;
    QLabel* summary_;
    QTableView* attribute_view_;
    QTableView* vertex_view_;
    QTableView* triangle_view_;
    QTableView* instance_view_;
    QTabWidget* tabs_;
    QSpinBox* jump_;
    QPushButton* jump_button_;
    QPushButton* tangent_button_;
    QLabel* tangent_summary_;
    QFutureWatcher<std::shared_ptr<const TangentErrors>> tangent_job_;
};

} // namespace sherpa::editor
