#pragma once
// Dock 1: the glTF node hierarchy with a filter box and per-node visibility.
// Context in (scene, selection, visibility); actions out as signals.
#include <QDockWidget>

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

Q_SIGNALS:
    void selectNodeRequested(int node);
    void selectMeshRequested(int mesh, int node);
    void selectMaterialRequested(int material);
    void visibilityRequested(int node, bool visible);
    void jumpToCameraRequested(int node);

private:
    void onCurrentChanged(const QModelIndex& current);
    void syncFromContext();

    const EditorContext& context_;
    SceneTreeModel* model_;
    QSortFilterProxyModel* proxy_;
    QTreeView* view_;
    QLineEdit* filter_;
    bool syncing_ = false;
};

} // namespace sherpa::editor
