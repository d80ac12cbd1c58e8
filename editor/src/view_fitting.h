#pragma once
// Item views whose columns follow their content, so no header or value is cut
// short ("R8G8B8…", "47.…") while space sits unused; a view narrower than its
// columns scrolls instead. Also: Ctrl+C copies a cell at full precision.
#include <vector>

class QAbstractItemView;
class QHeaderView;

namespace sherpa::editor {

// Fits every column of `view` (a QTableView or QTreeView) to its header and cells
// now and whenever the model resets, changes layout or rows, or a tree branch
// opens. Big tables measure their visible rows and a sample (resizeContentsPrecision).
void fit_columns_to_content(QAbstractItemView* view);

// Shows the model's columns `first` (logical indices, in this order) at the left of
// `header`, the others after them in model order, now and after every model reset
// (a reset forgets moved sections): a side dock's width shows the columns a user
// needs without scrolling, the rest scroll in. Columns the model lacks are skipped.
void show_columns_first(QHeaderView* header, std::vector<int> first);

// Ctrl+C on `view` copies the current cell's format::kExactTextRole (a number at
// full float precision) when the model has one, else its displayed text.
void copy_exact_on_ctrl_c(QAbstractItemView* view);

} // namespace sherpa::editor
