#pragma once
// The log dock: warnings and errors from loading (and anything else the editor
// reports), newest last.
#include <QDockWidget>

class QPlainTextEdit;

namespace sherpa::editor {

class LogDock : public QDockWidget {
    Q_OBJECT
public:
    enum class Level { Info, Warning, Error };
    explicit LogDock(QWidget* parent = nullptr);
    void retranslate();
    void append(Level level, const QString& message);
    QString text() const;
    int errorCount() const { return errors_; }

private:
    QPlainTextEdit* text_;
    int errors_ = 0;
};

} // namespace sherpa::editor
