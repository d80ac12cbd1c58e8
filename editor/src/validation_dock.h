#pragma once
// The Validation dock: the loaded file's validation messages grouped by severity
// and code, a filter over code, pointer and text, and the selected message in full.
// Context in (the scene's messages); action out: a message's JSON pointer, which the
// main window resolves to the object it names and selects (main_window_validation.cpp).
#include <QDockWidget>

class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QSortFilterProxyModel;
class QTreeView;

namespace sherpa::editor {

class EditorContext;
class ValidationModel;

class ValidationDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ValidationDock(const EditorContext& context, QWidget* parent = nullptr);
    void retranslate();
    ValidationModel* model() const { return model_; }
    QTreeView* view() const { return view_; }
    void setFilter(const QString& text);
    // Makes the first message with `pointer` current (as a click does); false if none.
    bool activatePointer(const QString& pointer);
    // What the dock says about the current message, or why nothing is shown.
    QString detailText() const;
    // Where the current message's pointer led ("→ node 3 \"Arm\""), under its text.
    void setTargetText(const QString& text);

Q_SIGNALS:
    // The user picked a message: show the object `pointer` names. `message` is its
    // text (the Khronos validator names element indices there).
    void messageActivated(const QString& pointer, const QString& message);

private:
    // The message of `index` in full under the list; false for a group row.
    bool showDetail(const QModelIndex& index);
    void activate(const QModelIndex& index);
    void updateSummary();

    const EditorContext& context_;
    ValidationModel* model_;
    QSortFilterProxyModel* proxy_;
    QLabel* summary_;
    QLineEdit* filter_;
    QTreeView* view_;
    QPlainTextEdit* detail_; // wraps anywhere: pointers are long words
    QString message_text_;   // the current message's lines, before the target's
};

} // namespace sherpa::editor
