#include "translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>

namespace sherpa::editor {

QStringList Translations::available() {
    return {QStringLiteral("en"), QStringLiteral("zh_CN"), QStringLiteral("de")};
}

QString Translations::nativeName(const QString& code) {
    // Each language is named in itself, so the menu is readable whatever the current one.
    if (code == QLatin1String("zh_CN")) return QStringLiteral("简体中文");
    if (code == QLatin1String("de")) return QStringLiteral("Deutsch");
    return QStringLiteral("English");
}

QString Translations::systemDefault() {
    const QLocale locale;
    if (locale.language() == QLocale::Chinese) return QStringLiteral("zh_CN");
    if (locale.language() == QLocale::German) return QStringLiteral("de");
    return QStringLiteral("en");
}

bool Translations::install(const QString& code) {
    auto sherpa = std::make_unique<QTranslator>();
    if (!sherpa->load(QStringLiteral(":/i18n/sherpa_%1.qm").arg(code)) || sherpa->isEmpty())
        return false;
    if (sherpa_) QCoreApplication::removeTranslator(sherpa_.get());
    if (qt_) QCoreApplication::removeTranslator(qt_.get());
    sherpa_ = std::move(sherpa);
    QCoreApplication::installTranslator(sherpa_.get());
    // Qt's own strings (file dialogs, message box buttons); absent catalogues are fine.
    qt_ = std::make_unique<QTranslator>();
    if (qt_->load(QStringLiteral("qtbase_%1").arg(code),
                  QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt_.get());
    else
        qt_.reset();
    current_ = code;
    return true;
}

} // namespace sherpa::editor
