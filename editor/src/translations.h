#pragma once
// Switching the UI language at runtime: Sherpa's own catalogue (embedded .qm
// under :/i18n) plus Qt's (standard dialogs), if installed.
#include <QString>
#include <QStringList>
#include <QTranslator>

#include <memory>

namespace sherpa::editor {

class Translations {
public:
    // Language codes with a catalogue: "en", "zh_CN", "de".
    static QStringList available();
    // The language's own name for the menu ("English", "简体中文", "Deutsch").
    static QString nativeName(const QString& code);
    // Best available match for the system locale; "en" when none.
    static QString systemDefault();

    // Installs `code` (replacing the current catalogue); emits LanguageChange to every
    // widget. Returns false when the catalogue is missing or empty.
    bool install(const QString& code);
    const QString& current() const { return current_; }

private:
    std::unique_ptr<QTranslator> sherpa_, qt_;
    QString current_;
};

} // namespace sherpa::editor
