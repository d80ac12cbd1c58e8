#include "log_dock.h"

#include <QPlainTextEdit>
#include <QTime>
#include <cstdio>

namespace sherpa::editor {

LogDock::LogDock(QWidget* parent) : QDockWidget(parent) {
    setObjectName(QStringLiteral("logDock"));
    text_ = new QPlainTextEdit(this);
    text_->setReadOnly(true);
    text_->setMaximumBlockCount(5000); // bounded: scenes can warn per primitive
    setWidget(text_);
    retranslate();
}

void LogDock::retranslate() {
    setWindowTitle(tr("Log"));
}

void LogDock::append(Level level, const QString& message) {
    QString tag;
    switch (level) {
    case Level::Info:
        tag = tr("info");
        break;
    case Level::Warning:
        tag = tr("warning");
        break;
    case Level::Error:
        tag = tr("error");
        ++errors_;
        break;
    }
    // Mirrored to stderr: headless runs (--screenshot, tests) show what the dock shows.
    std::fprintf(stderr, "sherpa [%s] %s\n", qPrintable(tag), qPrintable(message));
    text_->appendPlainText(
        QStringLiteral("%1 [%2] %3")
            .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), tag, message));
}

QString LogDock::text() const {
    return text_->toPlainText();
}

} // namespace sherpa::editor
