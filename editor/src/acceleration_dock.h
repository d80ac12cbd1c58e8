#pragma once
// The acceleration-structure dock (issue 17): the loaded scene's BLAS list (one per
// glTF mesh: geometries, triangles, build time, size before and after compaction,
// scratch) and the TLAS and totals under it. Context in (the selection; the
// statistics handed over by the main window from the render thread), actions out:
// selecting a row asks to select that mesh, as the scene tree does.
#include <QDockWidget>

#include <memory>

class QLabel;
class QTableView;

namespace sherpa::render {
struct AccelerationStats;
} // namespace sherpa::render

namespace sherpa::editor {

class AccelerationModel;
class EditorContext;

class AccelerationDock : public QDockWidget {
    Q_OBJECT
public:
    explicit AccelerationDock(const EditorContext& context, QWidget* parent = nullptr);
    void retranslate();
    // The statistics of the scene on the GPU; null with `why_none` saying why there
    // are none (ray tracing off, no device support, no scene).
    void setStats(std::shared_ptr<const render::AccelerationStats> stats, const QString& why_none);
    AccelerationModel* model() const { return model_; }
    QTableView* view() const { return view_; }
    QString summaryText() const;

Q_SIGNALS:
    // A primitive of the row's glTF mesh, placed by the first node that shows it.
    void selectMeshRequested(int mesh, int node);

private:
    void onRowChanged(int row);
    void syncSelection();
    void updateSummary();

    const EditorContext& context_;
    AccelerationModel* model_;
    QTableView* view_;
    QLabel* summary_;
    QString why_none_;
    bool syncing_ = false;
};

} // namespace sherpa::editor
