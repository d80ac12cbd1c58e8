#include "scene_tree_dock.h"

#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QTreeView>
#include <QVBoxLayout>

#include "editor_context.h"
#include "scene_tree_model.h"
#include "view_fitting.h"

namespace sherpa::editor {

SceneTreeDock::SceneTreeDock(const EditorContext& context, QWidget* parent)
    : QDockWidget(parent), context_(context) {
    setObjectName(QStringLiteral("sceneTreeDock"));
    model_ = new SceneTreeModel(context, this);
    proxy_ = new QSortFilterProxyModel(this);
    proxy_->setSourceModel(model_);
    proxy_->setRecursiveFilteringEnabled(true); // a match keeps its ancestors visible
    proxy_->setFilterCaseSensitivity(Qt::CaseInsensitive);
    proxy_->setFilterKeyColumn(SceneTreeModel::NameColumn);

    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    filter_ = new QLineEdit(body);
    filter_->setClearButtonEnabled(true);
    view_ = new QTreeView(body);
    view_->setModel(proxy_);
    view_->setUniformRowHeights(true);
    view_->header()->setSectionResizeMode(SceneTreeModel::NameColumn,
                                          QHeaderView::ResizeToContents);
    // Details before Type: what a node holds matters more than the word "node".
    show_columns_first(view_->header(), {SceneTreeModel::NameColumn, SceneTreeModel::DetailColumn});
    details_ = new QLabel(body);
    details_->setObjectName(QStringLiteral("sceneTreeDetails"));
    details_->setWordWrap(true);
    details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    details_->setTextFormat(Qt::PlainText);
    layout->addWidget(filter_);
    layout->addWidget(view_, 1);
    layout->addWidget(details_);
    setWidget(body);

    connect(filter_, &QLineEdit::textChanged, this, [this](const QString& text) {
        proxy_->setFilterFixedString(text);
        if (!text.isEmpty()) view_->expandAll();
    });
    connect(view_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& current) {
                showDetails(current);
                onCurrentChanged(current);
            });
    connect(view_, &QTreeView::doubleClicked, this, [this](const QModelIndex& index) {
        if (index.data(SceneTreeModel::KindRole).toInt() ==
            static_cast<int>(SceneTreeModel::Kind::Camera))
            Q_EMIT jumpToCameraRequested(index.data(SceneTreeModel::NodeRole).toInt());
    });
    connect(model_, &SceneTreeModel::visibilityRequested, this,
            &SceneTreeDock::visibilityRequested);
    connect(model_, &QAbstractItemModel::modelReset, this, [this] { view_->expandToDepth(1); });
    connect(&context_.selection(), &SceneSelection::changed, this, &SceneTreeDock::syncFromContext);
    retranslate();
}

void SceneTreeDock::retranslate() {
    setWindowTitle(tr("Scene Tree"));
    filter_->setPlaceholderText(tr("Filter by name…"));
    // The pane's text is composed from the model's translated cells: compose it again.
    showDetails(view_->currentIndex());
}

void SceneTreeDock::setFilter(const QString& text) {
    filter_->setText(text);
}

void SceneTreeDock::showDetails(const QModelIndex& current) {
    if (!current.isValid()) {
        details_->clear();
        return;
    }
    const QString name = current.siblingAtColumn(SceneTreeModel::NameColumn).data().toString();
    const QString type = current.siblingAtColumn(SceneTreeModel::TypeColumn).data().toString();
    const QModelIndex detail = current.siblingAtColumn(SceneTreeModel::DetailColumn);
    QString text = detail.data(Qt::ToolTipRole).toString();
    if (text.isEmpty()) text = detail.data().toString();
    details_->setText(tr("%1 (%2)").arg(name, type) +
                      (text.isEmpty() ? QString() : QLatin1Char('\n') + text));
}

void SceneTreeDock::onCurrentChanged(const QModelIndex& current) {
    if (syncing_ || !current.isValid()) return;
    const auto kind =
        static_cast<SceneTreeModel::Kind>(current.data(SceneTreeModel::KindRole).toInt());
    const int index = current.data(SceneTreeModel::IndexRole).toInt();
    const int node = current.data(SceneTreeModel::NodeRole).toInt();
    switch (kind) {
    case SceneTreeModel::Kind::Node:
    case SceneTreeModel::Kind::Light:
    case SceneTreeModel::Kind::Camera:
        Q_EMIT selectNodeRequested(node);
        break;
    case SceneTreeModel::Kind::Primitive: {
        const int mesh = context_.scene()->primitives[static_cast<std::size_t>(index)].engine_mesh;
        if (mesh >= 0) Q_EMIT selectMeshRequested(mesh, node);
        break;
    }
    case SceneTreeModel::Kind::Material:
        Q_EMIT selectMaterialRequested(index);
        break;
    case SceneTreeModel::Kind::Joint:   // the joint's node (skeleton highlight, joint influence)
    case SceneTreeModel::Kind::Channel: // its target node
        if (node >= 0) Q_EMIT selectNodeRequested(node);
        break;
    case SceneTreeModel::Kind::SceneRoot:
    case SceneTreeModel::Kind::Skin:
    case SceneTreeModel::Kind::Animation:
    case SceneTreeModel::Kind::Sampler:
        break;
    }
}

void SceneTreeDock::syncFromContext() {
    const Selection& s = context_.selection().current();
    // Already on an item of the selected node (its material, light...): stay there.
    const QModelIndex current = view_->currentIndex();
    if (current.isValid() && s.node >= 0 &&
        current.data(SceneTreeModel::NodeRole).toInt() == s.node &&
        current.data(SceneTreeModel::KindRole).toInt() !=
            static_cast<int>(SceneTreeModel::Kind::Node))
        return;
    const QModelIndex source =
        s.mesh >= 0 ? model_->indexOfPrimitive(s.node, s.mesh) : model_->indexOfNode(s.node);
    const QModelIndex target = proxy_->mapFromSource(source);
    if (!target.isValid() || target == view_->currentIndex()) return;
    // Selecting in the viewport must not echo back as a new action.
    syncing_ = true;
    view_->setCurrentIndex(target);
    view_->scrollTo(target);
    syncing_ = false;
}

} // namespace sherpa::editor
