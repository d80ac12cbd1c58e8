#pragma once
// Dock 1: the glTF node hierarchy with a filter box and per-node visibility.
// Context in (scene, selection, visibility); actions out as signals.
#include <QDockWidget>

class QLabel;
class QLineEdit;
class QSortFilterProxyModel;
class QTreeView;

namespace sherpa::editor {

class EditorContext;
class SceneTreeModel;

class SceneTreeDock : public QDockWidget {
    Q_OBJECT
public:
    explicit SceneTreeDock(const EditorContext& context, QWidget* parent = nullptr);
    void retranslate();
    SceneTreeModel* model() const { return model_; }
    QTreeView* view() const { return view_; }
    void setFilter(const QString& text);
    // The pane under the tree: the current item's type and whole details, wrapped
    // (the Details column of a side dock shows their start only).
    QLabel* detailsPane() const { return details_; }

Q_SIGNALS:
    void selectNodeRequested(int node);
    void selectMeshRequested(int mesh, int node);
    void selectMaterialRequested(int material);
    void visibilityRequested(int node, bool visible);
    void jumpToCameraRequested(int node);

private:
    void onCurrentChanged(const QModelIndex& current);
    void syncFromContext();
    void showDetails(const QModelIndex& current);

    const EditorContext& context_;
    SceneTreeModel* model_;
    QSortFilterProxyModel* proxy_;
    QTreeView* view_;
    QLineEdit* filter_;
    QLabel* details_;
    bool syncing_ = false;
};

} // namespace sherpa::editor
