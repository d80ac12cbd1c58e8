// The translation catalogues are complete: every string lupdate finds in the editor
// sources is in each .ts file, translated (not unfinished, not empty), with the same
// %N placeholders; no stale entries; and every catalogue loads at runtime.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>
#include <QtTest>

#include "translations.h"

namespace {

struct Entry {
    QString context, source, translation;
    bool unfinished = false, obsolete = false;
};

QList<Entry> read_ts(const QString& path) {
    QList<Entry> out;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return out;
    QXmlStreamReader xml(&f);
    QString context;
    Entry e;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement()) continue;
        if (xml.name() == QLatin1String("name"))
            context = xml.readElementText();
        else if (xml.name() == QLatin1String("message"))
            e = Entry{context, {}, {}, false, false};
        else if (xml.name() == QLatin1String("source"))
            e.source = xml.readElementText();
        else if (xml.name() == QLatin1String("translation")) {
            const QString type = xml.attributes().value(QLatin1String("type")).toString();
            e.unfinished = type == QLatin1String("unfinished");
            e.obsolete = type == QLatin1String("obsolete") || type == QLatin1String("vanished");
            e.translation = xml.readElementText();
            out << e;
        }
    }
    return out;
}

QSet<QString> placeholders(const QString& s) {
    QSet<QString> out;
    static const QRegularExpression re(QStringLiteral("%\\d+"));
    for (auto it = re.globalMatch(s); it.hasNext();) out.insert(it.next().captured());
    return out;
}

} // namespace

class TranslationTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void catalogueIsComplete_data();
    void catalogueIsComplete();
    void cataloguesLoad();

private:
    QSet<QString> expected_; // "context\x1fsource" from a fresh lupdate run
};

void TranslationTests::initTestCase() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString ts = dir.filePath(QStringLiteral("fresh.ts"));
    QProcess lupdate;
    // The View menu's labels live in the engine's view table, marked without Qt (the
    // same alias editor/CMakeLists.txt gives lupdate).
    lupdate.start(
        QStringLiteral(SHERPA_LUPDATE),
        {QStringLiteral("-silent"), QStringLiteral("-locations"), QStringLiteral("none"),
         QStringLiteral("-tr-function-alias"),
         QStringLiteral("QT_TRANSLATE_NOOP+=SHERPA_TRANSLATE_NOOP"),
         QStringLiteral(SHERPA_SOURCE_DIR "/editor/src"),
         QStringLiteral(SHERPA_SOURCE_DIR "/engine/render/include/sherpa/render/debug_views.h"),
         QStringLiteral("-ts"), ts});
    QVERIFY(lupdate.waitForFinished(120000));
    QCOMPARE(lupdate.exitCode(), 0);
    for (const Entry& e : read_ts(ts)) expected_.insert(e.context + QChar(0x1f) + e.source);
    QVERIFY2(expected_.size() > 100, "lupdate found the editor's strings");
}

void TranslationTests::catalogueIsComplete_data() {
    QTest::addColumn<QString>("language");
    for (const QString& code : sherpa::editor::Translations::available())
        QTest::newRow(qPrintable(code)) << code;
}

void TranslationTests::catalogueIsComplete() {
    QFETCH(QString, language);
    const QList<Entry> entries =
        read_ts(QStringLiteral(SHERPA_SOURCE_DIR "/translations/sherpa_%1.ts").arg(language));
    QSet<QString> present;
    for (const Entry& e : entries) {
        const QString key = e.context + QChar(0x1f) + e.source;
        QVERIFY2(!e.obsolete, qPrintable(QStringLiteral("stale entry: %1").arg(e.source)));
        QVERIFY2(!e.unfinished, qPrintable(QStringLiteral("unfinished: %1").arg(e.source)));
        QVERIFY2(!e.translation.trimmed().isEmpty(),
                 qPrintable(QStringLiteral("empty: %1").arg(e.source)));
        QVERIFY2(placeholders(e.source) == placeholders(e.translation),
                 qPrintable(
                     QStringLiteral("placeholders differ: %1 -> %2").arg(e.source, e.translation)));
        QVERIFY2(expected_.contains(key),
                 qPrintable(QStringLiteral("not in the sources: %1").arg(e.source)));
        present.insert(key);
    }
    for (const QString& key : expected_)
        QVERIFY2(present.contains(key),
                 qPrintable(QStringLiteral("missing: %1").arg(key.section(QChar(0x1f), 1))));
}

void TranslationTests::cataloguesLoad() {
    for (const QString& code : sherpa::editor::Translations::available()) {
        QTranslator t;
        QVERIFY2(t.load(QStringLiteral(":/i18n/sherpa_%1.qm").arg(code)), qPrintable(code));
        QVERIFY(!t.isEmpty());
    }
    QTranslator de;
    QVERIFY(de.load(QStringLiteral(":/i18n/sherpa_de.qm")));
    QCOMPARE(de.translate("sherpa::editor::SceneTreeDock", "Scene Tree"),
             QStringLiteral("Szenenbaum"));
    QTranslator zh;
    QVERIFY(zh.load(QStringLiteral(":/i18n/sherpa_zh_CN.qm")));
    QCOMPARE(zh.translate("sherpa::editor::MeshDock", "Vertices"), QStringLiteral("顶点"));
}

QTEST_MAIN(TranslationTests)
#include "translation_tests.moc"
