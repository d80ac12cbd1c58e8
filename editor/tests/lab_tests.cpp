// The Lab dock under Xvfb: it reports what `sherpa-cli lab --json` / `budget --json`
// report on the same scene (error figures and failures are deterministic, times are
// not), a family runs off the UI thread (the event loop keeps turning), cancel and a
// new scene stop a run, exports write the engine's CSV/SVG, and a chart point applies
// a culling method to the viewport.
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QGraphicsTextItem>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QScatterSeries>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QVulkanInstance>
#include <QtTest>

#include <sherpa/lab/report_export.h>

#include "culling_monitor.h"
#include "lab_chart.h"
#include "lab_dock.h"
#include "lab_runner.h"
#include "lab_session.h"
#include "lab_table_model.h"
#include "main_window.h"
#include "test_assets.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

QJsonObject cli_json(const QStringList& args) {
    QProcess p;
    p.start(QStringLiteral(SHERPA_CLI), args);
    if (!p.waitForFinished(300000) || p.exitCode() != 0) {
        qWarning() << "sherpa-cli" << args << p.readAllStandardError();
        return {};
    }
    return QJsonDocument::fromJson(p.readAllStandardOutput()).object();
}

// The dock's tables and chart, found as its children.
const LabTableModel& methods_model(const LabDock& dock) {
    return *dock.findChild<LabTableModel*>(QStringLiteral("labMethods"));
}
const LabTableModel& failures_model(const LabDock& dock) {
    return *dock.findChild<LabTableModel*>(QStringLiteral("labFailures"));
}
QChart* lab_chart(const LabDock& dock) {
    return dock.findChild<QChartView*>()->chart();
}

// Runs `family` in the dock and waits for its report; null if none came.
const lab::FamilyReport* run_family(LabDock& dock, const QString& family) {
    QSignalSpy done(&dock.runner(), &LabRunner::finished);
    dock.run(family);
    if (!done.wait(300000)) return nullptr;
    return dock.session().report();
}

bool close(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
}

} // namespace

class LabTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup() {
        if (!window_) return;
        const QString fresh = test::fresh_validation_messages(*window_, seen_validation_);
        QVERIFY2(fresh.isEmpty(), qPrintable(fresh));
    }
    void cleanupTestCase() { window_.reset(); }
    void dockAgreesWithTheCli_data();
    void dockAgreesWithTheCli();
    void budgetAgreesWithTheCli();
    void runningKeepsTheUiResponsive();
    void cancelAndNewSceneStopARun();
    void closingCancelsARun();
    void exportsAreTheEngineWriters();
    void clickingAPointAppliesACullingMethod();
    void applyingAShadowSettingReachesTheViewport();
    void chartLabelsNeverOverlap();
    void lightingFamilyIsListedAndRuns();

private:
    LabDock& dock() { return *window_->docks().lab; }
    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_validation_ = 0;
};

void LabTests::initTestCase() {
    window_ = test::open_validated_window(vulkan_);
    QVERIFY(window_);
    QVERIFY(window_->docks().lab);
}

void LabTests::dockAgreesWithTheCli_data() {
    QTest::addColumn<QString>("asset");
    QTest::addColumn<QString>("family");
    QTest::newRow("tangents") << "NormalTangentMirrorTest"
                              << "tangents";
    QTest::newRow("textures") << "NormalTangentMirrorTest"
                              << "textures";
    QTest::newRow("culling") << "2CylinderEngine"
                             << "culling";
    QTest::newRow("mesh-compression") << "NormalTangentMirrorTest"
                                      << "mesh-compression";
}

void LabTests::dockAgreesWithTheCli() {
    QFETCH(QString, asset);
    QFETCH(QString, family);
    const QString spec = test::asset(asset);
    QVERIFY(test::load(*window_, spec));
    const lab::FamilyReport* report = run_family(dock(), family);
    QVERIFY(report);
    const QJsonObject cli = cli_json({QStringLiteral("lab"), spec, QStringLiteral("--family"),
                                      family, QStringLiteral("--json")});
    const QJsonArray methods = cli[QStringLiteral("methods")].toArray();
    QCOMPARE(cli[QStringLiteral("family")].toString(), QString::fromStdString(report->family));
    QCOMPARE(qsizetype(methods.size()), qsizetype(report->methods.size()));
    QCOMPARE(methods_model(dock()).rowCount(), int(report->methods.size()));
    for (qsizetype i = 0; i < methods.size(); ++i) {
        const QJsonObject m = methods[i].toObject();
        const lab::MethodResult& r = report->methods[std::size_t(i)];
        QCOMPARE(m[QStringLiteral("name")].toString(), QString::fromStdString(r.method.name));
        QCOMPARE(m[QStringLiteral("ran")].toBool(), r.ran);
        // The table shows the method in the same row.
        QCOMPARE(methods_model(dock()).index(int(i), 0).data().toString(),
                 QString::fromStdString(r.method.name));
        const QJsonObject errors = m[QStringLiteral("errors")].toObject();
        QCOMPARE(qsizetype(errors.size()), qsizetype(r.errors.size()));
        for (const lab::ErrorFigure& e : r.errors) {
            const double cli_value = errors[QString::fromStdString(e.name)].toDouble();
            QVERIFY2(close(e.value, cli_value),
                     qPrintable(QStringLiteral("%1 %2: dock %3, cli %4")
                                    .arg(r.method.name.c_str(), e.name.c_str())
                                    .arg(e.value)
                                    .arg(cli_value)));
        }
        const QJsonArray failures = m[QStringLiteral("failures")].toArray();
        QCOMPARE(qsizetype(failures.size()), qsizetype(r.failures.size()));
        for (qsizetype f = 0; f < failures.size(); ++f) {
            const QJsonObject cf = failures[f].toObject();
            QCOMPARE(cf[QStringLiteral("cause")].toString(),
                     QString::fromStdString(r.failures[std::size_t(f)].cause));
            QCOMPARE(cf[QStringLiteral("where")].toString(),
                     QString::fromStdString(r.failures[std::size_t(f)].where));
        }
    }
    std::size_t failure_rows = 0;
    for (const lab::MethodResult& r : report->methods) failure_rows += r.failures.size();
    QCOMPARE(failures_model(dock()).rowCount(), int(failure_rows));
    // The chart plots every method that ran with the chart error.
    int plotted = 0;
    for (QAbstractSeries* s : lab_chart(dock())->series())
        plotted += qobject_cast<QScatterSeries*>(s) != nullptr;
    int ran = 0;
    for (const lab::MethodResult& r : report->methods) ran += r.ran && r.error(report->chart_error);
    QCOMPARE(plotted, ran);
    // The x axis: time, or the figure the family charts instead (mesh compression: bytes).
    const QList<QAbstractAxis*> x_axes = lab_chart(dock())->axes(Qt::Horizontal);
    QCOMPARE(x_axes.size(), 1);
    if (!report->chart_x.empty())
        QCOMPARE(x_axes.front()->titleText(), QString::fromStdString(report->chart_x));
    else
        QVERIFY(x_axes.front()->titleText().startsWith(QStringLiteral("time")));
}

void LabTests::budgetAgreesWithTheCli() {
    const QString spec = test::asset(QStringLiteral("DamagedHelmet"));
    QVERIFY(test::load(*window_, spec));
    QSignalSpy done(&dock().runner(), &LabRunner::budgetFinished);
    dock().runBudget();
    QVERIFY(done.wait(300000));
    const lab::BudgetReport* budget = dock().session().budget();
    QVERIFY(budget);
    const QJsonObject cli = cli_json({QStringLiteral("budget"), spec, QStringLiteral("--json")});
    const QJsonArray categories = cli[QStringLiteral("categories")].toArray();
    QCOMPARE(qsizetype(categories.size()), qsizetype(budget->categories.size()));
    for (qsizetype i = 0; i < categories.size(); ++i) {
        const QJsonObject c = categories[i].toObject();
        const lab::BudgetCategory& b = budget->categories[std::size_t(i)];
        QCOMPARE(c[QStringLiteral("name")].toString(), QString::fromStdString(b.name));
        QCOMPARE(c[QStringLiteral("unified")].toInteger(), qint64(b.unified));
        QCOMPARE(c[QStringLiteral("stored")].toInteger(), qint64(b.stored));
        QCOMPARE(c[QStringLiteral("needed")].toInteger(), qint64(b.needed));
    }
    QCOMPARE(qsizetype(cli[QStringLiteral("oversized_textures")].toArray().size()),
             qsizetype(budget->oversized.size()));
    QCOMPARE(qsizetype(cli[QStringLiteral("unread_attributes")].toArray().size()),
             qsizetype(budget->unread.size()));
}

void LabTests::runningKeepsTheUiResponsive() {
    QVERIFY(test::load(*window_, test::asset(QStringLiteral("DamagedHelmet"))));
    QSignalSpy done(&dock().runner(), &LabRunner::finished);
    QSignalSpy progress(&dock().runner(), &LabRunner::progress);
    int ticks = 0, ticks_while_running = 0;
    QTimer timer;
    connect(&timer, &QTimer::timeout, this, [&] {
        ++ticks;
        if (dock().runner().running()) ++ticks_while_running;
    });
    timer.start(5);
    dock().run(QStringLiteral("tangents"));
    // run() returned at once: the family is still measuring on its worker...
    QVERIFY(dock().runner().running());
    QVERIFY(done.wait(300000));
    // ...while the UI thread's event loop kept turning: timers fired, progress arrived.
    QVERIFY2(ticks_while_running > 0, qPrintable(QString::number(ticks)));
    QVERIFY(progress.count() > 0);
    QVERIFY(dock().session().report());
}

void LabTests::cancelAndNewSceneStopARun() {
    QVERIFY(test::load(*window_, test::asset(QStringLiteral("DamagedHelmet"))));
    QSignalSpy finished(&dock().runner(), &LabRunner::finished);
    QSignalSpy cancelled(&dock().runner(), &LabRunner::cancelled);
    dock().run(QStringLiteral("textures"));
    QVERIFY(dock().runner().running());
    dock().session().cancel();
    QCOMPARE(cancelled.count(), 1);
    QVERIFY(!dock().runner().running());
    dock().runner().wait(); // the worker returns at its next unit of work
    QTest::qWait(50);       // anything it might still post arrives (and is dropped)
    QCOMPARE(finished.count(), 0);
    QVERIFY(!dock().session().report());

    // A new scene cancels the run of the old one.
    dock().run(QStringLiteral("textures"));
    QVERIFY(dock().runner().running());
    QVERIFY(test::load(*window_, test::asset(QStringLiteral("Box"))));
    QCOMPARE(cancelled.count(), 2);
    dock().runner().wait();
    QTest::qWait(50);
    QCOMPARE(finished.count(), 0);
    QVERIFY(!dock().session().report());
}

void LabTests::closingCancelsARun() {
    int cancelled = 0, finished = 0;
    {
        LabRunner runner; // the dock's, destroyed with the window
        connect(&runner, &LabRunner::cancelled, this, [&] { ++cancelled; });
        connect(&runner, &LabRunner::finished, this, [&] { ++finished; });
        runner.start(QStringLiteral("textures"), test::asset(QStringLiteral("DamagedHelmet")));
        QTest::qWait(200); // the worker is loading or measuring
        QVERIFY(runner.running());
    } // the destructor cancels the run and waits for its worker
    QCOMPARE(cancelled, 1);
    QCOMPARE(finished, 0);
}

void LabTests::exportsAreTheEngineWriters() {
    QVERIFY(test::load(*window_, test::asset(QStringLiteral("Box"))));
    const lab::FamilyReport* report = run_family(dock(), QStringLiteral("tangents"));
    QVERIFY(report);
    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("lab.csv")),
                  svg = dir.filePath(QStringLiteral("lab.svg")),
                  png = dir.filePath(QStringLiteral("lab.png"));
    QVERIFY(dock().session().exportCsv(csv));
    QVERIFY(dock().session().exportSvg(svg));
    QVERIFY(dock().exportPng(png));
    auto read = [](const QString& path) {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    QCOMPARE(read(csv), QByteArray::fromStdString(lab::report_csv(*report)));
    QCOMPARE(read(svg), QByteArray::fromStdString(lab::report_svg(*report)));
    QVERIFY(!QImage(png).isNull());
    // The CLI's CSV has the same header and rows (times differ run to run).
    QProcess p;
    p.start(QStringLiteral(SHERPA_CLI),
            {QStringLiteral("lab"), test::asset(QStringLiteral("Box")), QStringLiteral("--family"),
             QStringLiteral("tangents"), QStringLiteral("--csv")});
    QVERIFY(p.waitForFinished(120000));
    const QList<QByteArray> cli_lines = p.readAllStandardOutput().split('\n');
    const QList<QByteArray> dock_lines = read(csv).split('\n');
    QCOMPARE(cli_lines.size(), dock_lines.size());
    QCOMPARE(cli_lines.first(), dock_lines.first());
}

void LabTests::clickingAPointAppliesACullingMethod() {
    QVERIFY(test::load(*window_, test::asset(QStringLiteral("2CylinderEngine"))));
    const lab::FamilyReport* report = run_family(dock(), QStringLiteral("culling"));
    QVERIFY(report);
    QScatterSeries* sphere = nullptr;
    for (QAbstractSeries* s : lab_chart(dock())->series())
        if (auto* scatter = qobject_cast<QScatterSeries*>(s);
            scatter &&
            report->methods[std::size_t(scatter->property("method").toULongLong())].method.name ==
                "sphere")
            sphere = scatter;
    QVERIFY(sphere);
    QVERIFY(test::culling_monitor(*window_).method() != scene::CullMethod::Sphere);
    Q_EMIT sphere->clicked(sphere->at(0));
    QCOMPARE(test::culling_monitor(*window_).method(), scene::CullMethod::Sphere);
    // The chart rings the method now in use.
    bool ringed = false;
    for (QAbstractSeries* s : lab_chart(dock())->series())
        ringed |= s->name().startsWith(QStringLiteral("sphere")) &&
                  s->name().contains(QStringLiteral("in use"));
    QVERIFY(ringed);
}

// The shadows family's apply action (what a click on its chart emits): the cascade
// count and PCF taps reach the viewport's frames; a name that is no setting changes
// nothing.
void LabTests::applyingAShadowSettingReachesTheViewport() {
    QVERIFY(test::load(*window_, test::asset(QStringLiteral("Box"))));
    qsizetype seen = 0;
    test::fresh_validation_messages(*window_, seen);
    Q_EMIT dock().applyRequested(QStringLiteral("shadows"), QStringLiteral("4096x1 pcf16"));
    QTRY_COMPARE(window_->frames().lastFrame().request.shadow_pcf_taps, 16u);
    QCOMPARE(window_->frames().lastFrame().request.cascades, 1u);
    Q_EMIT dock().applyRequested(QStringLiteral("shadows"), QStringLiteral("4096x2"));
    QCOMPARE(window_->frames().lastFrame().request.cascades, 1u);
    Q_EMIT dock().applyRequested(QStringLiteral("shadows"), QStringLiteral("2048x3 pcf4"));
    QTRY_COMPARE(window_->frames().lastFrame().request.shadow_pcf_taps, 4u);
    QCOMPARE(window_->frames().lastFrame().request.cascades, 3u);
    const QString messages = test::fresh_validation_messages(*window_, seen);
    QVERIFY2(messages.isEmpty(), qPrintable(messages));
}

// The culling family's chart in a dock's width: the exact methods all sit at y = 0
// with nearly the same time. No label covers another, a point's marker or an axis
// label, and none leaves the plot area; a label that finds no room is hidden, never
// drawn over another.
void LabTests::chartLabelsNeverOverlap() {
    lab::FamilyReport report;
    report.family = "culling";
    report.time_unit = "ns/object";
    report.chart_error = "false_positives";
    const std::pair<const char*, double> methods[] = {
        {"exact", 328.0}, {"pvertex", 41.0}, {"gpu test=pvertex", 40.0}, {"sphere", 12.0},
        {"aabb", 30.0},   {"obb", 55.0},     {"gpu test=sphere", 11.5}};
    for (const auto& [name, time] : methods) {
        lab::MethodResult m;
        m.method.name = name;
        m.ran = true;
        m.time = time;
        const bool exact = std::string(name) == "exact" || std::string(name).ends_with("pvertex");
        m.errors.push_back({"false_positives", exact ? 0.0 : 17.0, false});
        report.methods.push_back(m);
    }
    QChart* chart = new QChart;
    chart->setMargins(QMargins(2, 2, 2, 2));
    QChartView view(chart);
    view.resize(270, 320); // a side dock at 1600×1000
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    LabChartLabels labels;
    show_lab_report(*chart, report, QStringLiteral("pvertex"), labels);
    QTest::qWait(100); // the chart's layout, then the labels' placing
    QCoreApplication::processEvents();
    QList<QRectF> label_boxes, other_texts;
    for (const QPointer<QGraphicsTextItem>& label : labels)
        if (label && label->isVisible()) label_boxes << label->sceneBoundingRect();
    for (QGraphicsItem* item : view.scene()->items())
        if (auto* text = dynamic_cast<QGraphicsTextItem*>(item);
            text && text->isVisible() && !text->toPlainText().isEmpty() &&
            std::none_of(labels.begin(), labels.end(),
                         [&](const QPointer<QGraphicsTextItem>& l) { return l.data() == text; }))
            other_texts << text->sceneBoundingRect();
    QVERIFY2(label_boxes.size() >= 4, qPrintable(QString::number(label_boxes.size())));
    QStringList overlaps;
    for (qsizetype i = 0; i < label_boxes.size(); ++i) {
        const QRectF a = label_boxes[i];
        if (!chart->mapRectToScene(chart->plotArea()).contains(a))
            overlaps << QStringLiteral("label %1 leaves the plot area").arg(i);
        for (qsizetype j = i + 1; j < label_boxes.size(); ++j)
            if (a.intersects(label_boxes[j]))
                overlaps << QStringLiteral("labels %1 and %2").arg(i).arg(j);
        for (const QRectF& t : other_texts)
            if (a.intersects(t)) overlaps << QStringLiteral("label %1 and an axis text").arg(i);
        for (QAbstractSeries* s : chart->series())
            if (auto* scatter = qobject_cast<QScatterSeries*>(s)) {
                const QPointF p = chart->mapToScene(chart->mapToPosition(scatter->at(0), scatter));
                const double r = scatter->markerSize() / 2.0;
                if (a.intersects(QRectF(p - QPointF(r, r), QSizeF(2 * r, 2 * r))))
                    overlaps << QStringLiteral("label %1 and the marker of %2")
                                    .arg(i)
                                    .arg(scatter->name());
            }
    }
    QVERIFY2(overlaps.isEmpty(), qPrintable(overlaps.join(QLatin1Char('\n'))));
    // The pure placing: ten labels on one point in a small area, none overlapping.
    const std::vector<QPointF> same(10, QPointF(100, 95));
    const std::vector<QSizeF> sizes(10, QSizeF(60, 14));
    const auto boxes = place_labels(same, sizes, QRectF(0, 0, 200, 100));
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            QVERIFY(!boxes[i] || !boxes[j] || !boxes[i]->intersects(*boxes[j]));
    QVERIFY(std::count_if(boxes.begin(), boxes.end(),
                          [](const auto& b) { return b.has_value(); }) >= 8);
}

// The lighting family comes from the engine's one list into the dock's family box and
// runs there like the others: a table row per method, a chart point per method that
// ran, the groups Box cannot show (no transmission) not run, saying why.
void LabTests::lightingFamilyIsListedAndRuns() {
    auto* box = dock().findChild<QComboBox*>();
    QVERIFY(box);
    QVERIFY(box->findData(QStringLiteral("lighting")) >= 0);
    QVERIFY(test::load(*window_, test::asset(QStringLiteral("Box"))));
    const lab::FamilyReport* report = run_family(dock(), QStringLiteral("lighting"));
    QVERIFY(report);
    QCOMPARE(QString::fromStdString(report->family), QStringLiteral("lighting"));
    QCOMPARE(methods_model(dock()).rowCount(), int(report->methods.size()));
    int ran = 0;
    for (const lab::MethodResult& r : report->methods) {
        if (r.method.group == "transmission") {
            QVERIFY(!r.ran);
            QVERIFY2(r.note.find("not applicable") != std::string::npos, r.note.c_str());
        }
        ran += r.ran && r.error(report->chart_error);
    }
    if (report->methods.back().note.find("does not ray trace") != std::string::npos)
        QSKIP("the editor's device does not ray trace");
    QVERIFY(report->methods.back().ran); // the path tracer's own convergence
    QVERIFY(report->reference.find("256 spp") != std::string::npos);
    int plotted = 0;
    for (QAbstractSeries* s : lab_chart(dock())->series())
        plotted += qobject_cast<QScatterSeries*>(s) != nullptr;
    QCOMPARE(plotted, ran);
}

QTEST_MAIN(LabTests)
#include "lab_tests.moc"
