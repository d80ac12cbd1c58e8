#pragma once
// What the layout tests check on a window: texts that do not fit their column, the
// columns a user needs, chart labels, the toolbar. Each returns one line per problem
// ("dock: text (needed > width)"), empty when nothing is cut off.
#include <QAbstractItemView>
#include <QChartView>
#include <QDockWidget>
#include <QGraphicsTextItem>
#include <QHeaderView>
#include <QMainWindow>
#include <QTabBar>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

#include <initializer_list>

#include "attribute_model.h"
#include "lab_dock.h"
#include "main_window.h"
#include "material_dock.h"
#include "material_fields_model.h"
#include "mesh_dock.h"
#include "scene_tree_dock.h"
#include "scene_tree_model.h"
#include "texture_dock.h"
#include "texture_table_model.h"
#include "vertex_table_model.h"
#include "window_test_support.h"

namespace sherpa::editor::test {

// Every header section and every visible cell of the shown item views whose text
// does not fit its section, as "dock: text (needed > width)".
inline QStringList cut_texts(QWidget& root) {
    QStringList cut;
    for (QAbstractItemView* view : root.findChildren<QAbstractItemView*>()) {
        if (!view->isVisible() || !view->model() || qobject_cast<QHeaderView*>(view)) continue;
        QWidget* dock = view;
        while (dock && !qobject_cast<QDockWidget*>(dock)) dock = dock->parentWidget();
        const QString where = dock ? dock->objectName() : QStringLiteral("window");
        QAbstractItemModel* m = view->model();
        // Qt's item text margin (QCommonStyle): PM_FocusFrameHMargin + 1 on each side.
        const int margin = 2 * (view->style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 1);
        QHeaderView* header = nullptr;
        if (auto* t = qobject_cast<QTableView*>(view)) header = t->horizontalHeader();
        if (auto* t = qobject_cast<QTreeView*>(view)) header = t->header();
        if (header && header->isVisible())
            for (int c = 0; c < m->columnCount(); ++c) {
                if (header->isSectionHidden(c)) continue;
                const QString text = m->headerData(c, Qt::Horizontal).toString();
                const int needed = header->fontMetrics().horizontalAdvance(text) +
                                   2 * header->style()->pixelMetric(QStyle::PM_HeaderMargin);
                if (needed > header->sectionSize(c))
                    cut << QStringLiteral("%1 header: %2 (%3 > %4)")
                               .arg(where, text)
                               .arg(needed)
                               .arg(header->sectionSize(c));
            }
        // Visible cells: rows from the top of the viewport down (trees: as expanded).
        const QRect area = view->viewport()->rect();
        for (QModelIndex row = view->indexAt(QPoint(1, 1)); row.isValid();) {
            const QRect row_rect = view->visualRect(row);
            if (row_rect.top() > area.bottom()) break;
            for (int c = 0; c < m->columnCount(row.parent()); ++c) {
                if (header && header->isSectionHidden(c)) continue;
                const QModelIndex cell = row.siblingAtColumn(c);
                const QString text = cell.data(Qt::DisplayRole).toString();
                const QRect r = view->visualRect(cell);
                if (text.isEmpty() || r.width() <= 0) continue;
                QFont font = view->font();
                if (const QVariant f = cell.data(Qt::FontRole); f.isValid())
                    font = f.value<QFont>();
                int needed = QFontMetrics(font).horizontalAdvance(text) + margin;
                if (cell.data(Qt::DecorationRole).isValid())
                    needed += view->iconSize().width() + margin;
                if (cell.data(Qt::CheckStateRole).isValid())
                    needed += view->style()->pixelMetric(QStyle::PM_IndicatorWidth) + margin;
                if (needed > r.width())
                    cut << QStringLiteral("%1 cell: %2 (%3 > %4)")
                               .arg(where, text)
                               .arg(needed)
                               .arg(r.width());
            }
            if (auto* tree = qobject_cast<QTreeView*>(view))
                row = tree->indexBelow(row);
            else
                row = row.siblingAtRow(row.row() + 1);
        }
    }
    return cut;
}

// Cells of `columns` in `view` (a table of dock `where`) that reach past its
// visible width (so hidden behind the horizontal scroll bar) or are not shown at all,
// as "where column C: text".
inline QStringList cut_off_columns(QTableView* view, const QString& where,
                                   std::initializer_list<int> columns) {
    QStringList cut;
    if (!view || !view->model()) return {QStringLiteral("%1: no table").arg(where)};
    if (view->model()->rowCount() == 0) return {QStringLiteral("%1: empty table").arg(where)};
    const QRect area = view->viewport()->rect();
    for (int row = 0; row < view->model()->rowCount(); ++row)
        for (int c : columns) {
            const QModelIndex cell = view->model()->index(row, c);
            const QRect r = view->visualRect(cell);
            if (r.top() > area.bottom()) continue; // below: rows scroll
            if (r.isEmpty() || r.left() < area.left() || r.right() > area.right())
                cut << QStringLiteral("%1 column %2: %3 (%4..%5 outside 0..%6)")
                           .arg(where)
                           .arg(c)
                           .arg(cell.data().toString())
                           .arg(r.left())
                           .arg(r.right())
                           .arg(area.right());
        }
    return cut;
}

inline QStringList cut_off_columns(QDockWidget& dock, std::initializer_list<int> columns) {
    return cut_off_columns(dock.findChild<QTableView*>(), dock.objectName(), columns);
}

// The columns a user needs of every dock, shown whole without scrolling sideways
// (each dock raised in turn): the texture's State ("missing"), the attribute's
// Accessor and Component, the vertex's position (x, y, z), the Lab's time and chart
// error, the material field's value and SSBO offset; the scene tree's selected item
// with its whole details in the pane under the tree.
inline void wait_settled(MainWindow& w);

inline QStringList cut_needed_columns(MainWindow& w) {
    QStringList cut;
    w.docks().textures->raise();
    wait_settled(w);
    cut << cut_off_columns(w.docks().textures->view(), QStringLiteral("textureDock"),
                           {TextureTableModel::NameColumn, TextureTableModel::CacheStateColumn});
    w.docks().mesh->raise();
    wait_settled(w);
    cut << cut_off_columns(w.docks().mesh->findChild<QTableView*>(), QStringLiteral("meshDock"),
                           {AttributeModel::AttributeColumn, AttributeModel::AccessorColumn,
                            AttributeModel::ComponentTypeColumn});
    cut << cut_off_columns(w.docks().mesh->vertexView(), QStringLiteral("meshDock vertices"),
                           {VertexTableModel::IndexColumn, VertexTableModel::PosX,
                            VertexTableModel::PosY, VertexTableModel::PosZ});
    w.docks().material->raise();
    wait_settled(w);
    cut << cut_off_columns(*w.docks().material,
                           {MaterialFieldsModel::FieldColumn, MaterialFieldsModel::ValueColumn});
    // Its byte offsets head the rows.
    if (auto* table = w.docks().material->findChild<QTableView*>();
        !table->verticalHeader()->isVisible() || table->verticalHeader()->width() <= 0 ||
        table->model()->headerData(1, Qt::Vertical).toString() !=
            table->model()->index(1, MaterialFieldsModel::OffsetColumn).data().toString())
        cut << QStringLiteral("materialDock: no offsets heading the rows");
    w.docks().lab->raise();
    wait_settled(w);
    cut << cut_off_columns(w.docks().lab->findChild<QTableView*>(QStringLiteral("labMethodsView")),
                           QStringLiteral("labDock"), {0, 2, 3}); // method, time, chart error
    w.docks().sceneTree->raise();
    wait_settled(w);
    QLabel* pane = w.docks().sceneTree->detailsPane();
    const QModelIndex current = w.docks().sceneTree->view()->currentIndex();
    const QString details =
        current.siblingAtColumn(SceneTreeModel::DetailColumn).data(Qt::ToolTipRole).toString();
    if (!pane->isVisible() || details.isEmpty() || !pane->text().contains(details) ||
        pane->heightForWidth(pane->width()) > pane->height())
        cut << QStringLiteral("sceneTreeDock details: '%1' in '%2' (%3 > %4)")
                   .arg(details, pane->text())
                   .arg(pane->heightForWidth(pane->width()))
                   .arg(pane->height());
    return cut;
}

// Axis labels of every chart shown, that Qt Charts cut to "…".
inline QStringList cut_chart_labels(QWidget& root) {
    QStringList cut;
    for (QChartView* chart : root.findChildren<QChartView*>()) {
        if (!chart->isVisible()) continue;
        for (QGraphicsItem* item : chart->scene()->items())
            if (auto* text = dynamic_cast<QGraphicsTextItem*>(item))
                if (text->isVisible() && text->toPlainText().contains(QChar(0x2026)))
                    cut << text->toPlainText();
    }
    return cut;
}

// The toolbar overflowing into its extension menu (a button hidden there, as
// "Freeze Culling Camera" was), and two buttons that read alike ("Ansicht:" twice).
inline QStringList toolbar_problems(MainWindow& w) {
    QStringList problems;
    for (auto* bar : w.findChildren<QToolBar*>()) {
        if (!bar->isVisible()) continue;
        if (auto* ext = bar->findChild<QToolButton*>(QStringLiteral("qt_toolbar_ext_button"));
            ext && ext->isVisible())
            problems
                << QStringLiteral("toolbar overflows into its menu (%1 px wide)").arg(bar->width());
        QStringList prefixes;
        for (auto* button : bar->findChildren<QToolButton*>()) {
            if (!button->isVisible() || !button->text().contains(QLatin1Char(':'))) continue;
            const QString prefix = button->text().section(QLatin1Char(':'), 0, 0);
            if (prefixes.contains(prefix))
                problems << QStringLiteral("two toolbar buttons read '%1:'").arg(prefix);
            prefixes << prefix;
        }
    }
    return problems;
}

inline void wait_settled(MainWindow& w) {
    bool settled = false;
    when_layout_settles(w, [&settled] { settled = true; });
    QTRY_VERIFY_WITH_TIMEOUT(settled, 20000);
}

// Each tab of each dock group in front in turn: what is cut off anywhere. With
// SHERPA_SHOTS_DIR set, each is also saved there as DIR/TAG-LANGUAGE-DOCK.png (the
// screenshots a reviewer looks at; not part of the check).
inline QStringList cut_in_every_dock(MainWindow& w,
                                     const QString& tag = QStringLiteral("default")) {
    QStringList cut;
    const QString shots = qEnvironmentVariable("SHERPA_SHOTS_DIR");
    for (QDockWidget* dock : w.findChildren<QDockWidget*>()) {
        if (dock->isHidden()) continue; // the timeline of a scene that does not move
        dock->raise();
        wait_settled(w);
        QTest::qWait(200); // the raised tab's own layout (the viewport does not change)
        cut << cut_texts(w) << cut_chart_labels(w);
        if (!shots.isEmpty())
            w.screenshot().save(QStringLiteral("%1/%2-%3-%4.png")
                                    .arg(shots, tag, w.language(), dock->objectName()));
    }
    cut.removeDuplicates();
    return cut;
}

} // namespace sherpa::editor::test
