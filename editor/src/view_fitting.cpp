#include "view_fitting.h"

#include <QApplication>
#include <QClipboard>
#include <QHeaderView>
#include <QKeyEvent>
#include <QTableView>
#include <QTimer>
#include <QTreeView>

#include "format_values.h"

namespace sherpa::editor {

namespace {
void fit_now(QAbstractItemView* view) {
    if (auto* table = qobject_cast<QTableView*>(view)) {
        table->resizeColumnsToContents();
        return;
    }
    if (auto* tree = qobject_cast<QTreeView*>(view))
        for (int c = 0; c < tree->header()->count(); ++c) tree->resizeColumnToContents(c);
}
} // namespace

void fit_columns_to_content(QAbstractItemView* view) {
    QHeaderView* header = nullptr;
    if (auto* table = qobject_cast<QTableView*>(view)) header = table->horizontalHeader();
    if (auto* tree = qobject_cast<QTreeView*>(view)) header = tree->header();
    if (!header || !view->model()) return;
    // A stretched last section would take the unused width ("Texture chain" took half
    // the dock) and, narrower than its content, elide it: sections keep their fit.
    header->setStretchLastSection(false);
    for (int c = 0; c < header->count(); ++c)
        if (header->sectionResizeMode(c) != QHeaderView::Interactive)
            header->setSectionResizeMode(c, QHeaderView::Interactive);
    // Coalesced: a reset followed by data changes refits once, after the view updated.
    auto* pending = new QTimer(view);
    pending->setSingleShot(true);
    pending->setInterval(0);
    QObject::connect(pending, &QTimer::timeout, view, [view] { fit_now(view); });
    const auto refit = [pending] { pending->start(); };
    QAbstractItemModel* model = view->model();
    QObject::connect(model, &QAbstractItemModel::modelReset, pending, refit);
    QObject::connect(model, &QAbstractItemModel::layoutChanged, pending, refit);
    QObject::connect(model, &QAbstractItemModel::rowsInserted, pending, refit);
    QObject::connect(model, &QAbstractItemModel::dataChanged, pending, refit);
    QObject::connect(model, &QAbstractItemModel::headerDataChanged, pending, refit);
    if (auto* tree = qobject_cast<QTreeView*>(view)) {
        QObject::connect(tree, &QTreeView::expanded, pending, refit);
        QObject::connect(tree, &QTreeView::collapsed, pending, refit);
    }
    fit_now(view);
}

void show_columns_first(QHeaderView* header, std::vector<int> first) {
    const auto apply = [header, first] {
        int visual = 0;
        for (const int logical : first) {
            if (logical < 0 || logical >= header->count()) continue;
            header->moveSection(header->visualIndex(logical), visual++);
        }
    };
    apply();
    if (QAbstractItemModel* model = header->model()) {
        QObject::connect(model, &QAbstractItemModel::modelReset, header, apply);
        QObject::connect(model, &QAbstractItemModel::columnsInserted, header, apply);
        QObject::connect(model, &QAbstractItemModel::headerDataChanged, header, apply);
    }
}

void copy_exact_on_ctrl_c(QAbstractItemView* view) {
    // An event filter, not a QAction shortcut: QAbstractItemView takes Ctrl+C itself
    // (a shortcut override) and copies the rounded display text.
    struct ExactCopy : QObject {
        using QObject::QObject;
        bool eventFilter(QObject* watched, QEvent* e) override {
            if (e->type() != QEvent::KeyPress ||
                !static_cast<QKeyEvent*>(e)->matches(QKeySequence::Copy))
                return false;
            const QModelIndex index = static_cast<QAbstractItemView*>(watched)->currentIndex();
            if (!index.isValid()) return false;
            QVariant text = index.data(format::kExactTextRole);
            if (!text.isValid()) text = index.data(Qt::DisplayRole);
            QApplication::clipboard()->setText(text.toString());
            return true;
        }
    };
    view->installEventFilter(new ExactCopy(view));
}

} // namespace sherpa::editor
