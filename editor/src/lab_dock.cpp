#include "lab_dock.h"

#include <QBoxLayout>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>

#include "editor_context.h"
#include "lab_chart.h"
#include "lab_runner.h"
#include "lab_session.h"
#include "lab_table_model.h"
#include "view_fitting.h"

namespace sherpa::editor {
namespace {

QTableView* make_table(LabTableModel* model, QWidget* parent) {
    auto* view = new QTableView(parent);
    view->setModel(model);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    view->verticalHeader()->hide();
    view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    return view;
}

} // namespace

LabDock::LabDock(const EditorContext& context, QWidget* parent)
    : QDockWidget(parent), context_(context), session_(new LabSession(context, this)) {
    setObjectName(QStringLiteral("labDock"));
    methods_ = new LabTableModel(this);
    methods_->setObjectName(QStringLiteral("labMethods"));
    failures_ = new LabTableModel(this);
    failures_->setObjectName(QStringLiteral("labFailures"));
    categories_ = new LabTableModel(this);
    findings_ = new LabTableModel(this);
    tabs_ = new QTabWidget(this);
    tabs_->addTab(buildMethodsTab(), QString());
    tabs_->addTab(buildBudgetTab(), QString());
    setWidget(tabs_);

    LabRunner* runner = &session_->runner();
    connect(runner, &LabRunner::progress, this, [this](int done, int total) {
        progress_->setRange(0, std::max(total, 1));
        progress_->setValue(done);
    });
    connect(session_, &LabSession::reportChanged, this, &LabDock::showReport);
    connect(session_, &LabSession::budgetChanged, this, &LabDock::showBudget);
    connect(runner, &LabRunner::failed, this, [this](const QString& error) {
        setBusy(false);
        status_->setText(tr("The Lab could not run: %1").arg(error));
        budget_status_->setText(status_->text());
    });
    connect(runner, &LabRunner::cancelled, this, [this] {
        setBusy(false);
        status_->setText(tr("Cancelled."));
    });
    connect(&context_, &EditorContext::sceneReady, this, &LabDock::onSceneChanged);
    retranslate();
    onSceneChanged();
}

LabDock::~LabDock() = default; // the session's runner cancels and waits for its worker

LabRunner& LabDock::runner() const {
    return session_->runner();
}

QWidget* LabDock::buildMethodsTab() {
    auto* page = new QWidget(this);
    family_ = new QComboBox(page);
    for (std::string_view name : lab::family_names())
        family_->addItem(QString::fromLatin1(name.data(), qsizetype(name.size())),
                         QString::fromLatin1(name.data(), qsizetype(name.size())));
    run_ = new QPushButton(page);
    cancel_ = new QPushButton(page);
    progress_ = new QProgressBar(page);
    status_ = new QLabel(page);
    status_->setWordWrap(true);
    chart_ = new QChart;
    chart_->legend()->setAlignment(Qt::AlignBottom);
    chart_->setMargins(QMargins(2, 2, 2, 2));
    chart_view_ = new QChartView(chart_, page);
    chart_view_->setRenderHint(QPainter::Antialiasing);
    chart_view_->setMinimumHeight(300);
    tables_ = new QTabWidget(page);
    methods_view_ = make_table(methods_, tables_);
    methods_view_->setObjectName(QStringLiteral("labMethodsView"));
    // Method, time and the chart's error (the first figure) before the parameters.
    show_columns_first(methods_view_->horizontalHeader(), {0, 2, 3});
    tables_->addTab(methods_view_, QString());
    tables_->addTab(make_table(failures_, tables_), QString());
    auto* split = new QSplitter(Qt::Vertical, page);
    split->addWidget(chart_view_);
    split->addWidget(tables_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    export_csv_ = new QPushButton(page);
    export_svg_ = new QPushButton(page);
    export_png_ = new QPushButton(page);

    auto* top = new QHBoxLayout;
    top->addWidget(family_, 1);
    top->addWidget(run_);
    top->addWidget(cancel_);
    auto* exports = new QHBoxLayout;
    exports->addWidget(export_csv_);
    exports->addWidget(export_svg_);
    exports->addWidget(export_png_);
    exports->addStretch(1);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(top);
    layout->addWidget(progress_);
    layout->addWidget(status_);
    layout->addWidget(split, 1);
    layout->addLayout(exports);

    connect(run_, &QPushButton::clicked, this, [this] { run(family_->currentData().toString()); });
    connect(cancel_, &QPushButton::clicked, session_, &LabSession::cancel);
    connect(methods_view_, &QTableView::doubleClicked, this,
            [this](const QModelIndex& index) { apply(std::size_t(index.row())); });
    connect(export_csv_, &QPushButton::clicked, this, [this] {
        exportDialog(tr("CSV (*.csv)"), [this](const QString& path) {
            return exported(session_->exportCsv(path), path);
        });
    });
    connect(export_svg_, &QPushButton::clicked, this, [this] {
        exportDialog(tr("SVG (*.svg)"), [this](const QString& path) {
            return exported(session_->exportSvg(path), path);
        });
    });
    connect(export_png_, &QPushButton::clicked, this, [this] {
        exportDialog(tr("PNG (*.png)"), [this](const QString& path) { return exportPng(path); });
    });
    return page;
}

QWidget* LabDock::buildBudgetTab() {
    auto* page = new QWidget(this);
    budget_run_ = new QPushButton(page);
    budget_status_ = new QLabel(page);
    budget_status_->setWordWrap(true);
    auto* layout = new QVBoxLayout(page);
    auto* top = new QHBoxLayout;
    top->addWidget(budget_run_);
    top->addStretch(1);
    layout->addLayout(top);
    layout->addWidget(budget_status_);
    layout->addWidget(make_table(categories_, page), 1);
    layout->addWidget(make_table(findings_, page), 1);
    connect(budget_run_, &QPushButton::clicked, this, &LabDock::runBudget);
    return page;
}

void LabDock::retranslate() {
    setWindowTitle(tr("Lab"));
    tabs_->setTabText(0, tr("Methods"));
    tabs_->setTabText(1, tr("Budget"));
    run_->setText(tr("Run"));
    cancel_->setText(tr("Cancel"));
    budget_run_->setText(tr("Compute budget"));
    tables_->setTabText(0, tr("Numbers"));
    tables_->setTabText(1, tr("Failures"));
    export_csv_->setText(tr("CSV…"));
    export_svg_->setText(tr("SVG…"));
    export_png_->setText(tr("PNG…"));
    family_->setToolTip(tr("The family of methods to measure on the loaded scene"));
    run_->setToolTip(tr("Measure every method of the family on this scene, off the UI thread"));
    export_csv_->setToolTip(tr("The numbers, as sherpa-cli lab --csv writes them"));
    export_svg_->setToolTip(tr("The chart, as sherpa-cli lab --chart writes it"));
    export_png_->setToolTip(tr("The chart as shown"));
    const QString apply_tip =
        tr("Click a point (or double-click a row) to use that method in the viewport: culling "
           "methods, and the cascade count and PCF taps of a shadow setting (the viewport's "
           "shadow maps keep their resolution, fixed when its renderer is made). Tangent and "
           "texture methods are measured here but the viewport has no switch for them, so "
           "clicking them changes nothing.");
    chart_view_->setToolTip(apply_tip);
    methods_view_->setToolTip(apply_tip);
    if (session_->report()) fillReport();
    if (session_->budget()) fillBudget();
}

void LabDock::fillReport() {
    fill_methods(*methods_, *session_->report());
    fill_failures(*failures_, *session_->report());
    refreshMethodInUse();
}

void LabDock::fillBudget() {
    fill_budget_categories(*categories_, *session_->budget());
    fill_budget_findings(*findings_, *session_->budget());
}

void LabDock::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QDockWidget::changeEvent(e);
}

void LabDock::setMethodInUse(std::function<QString(const QString&)> in_use) {
    in_use_ = std::move(in_use);
    refreshMethodInUse();
}

void LabDock::setBusy(bool busy) {
    run_->setEnabled(!busy && context_.scene());
    budget_run_->setEnabled(!busy && context_.scene());
    cancel_->setEnabled(busy);
    progress_->setVisible(busy);
}

void LabDock::onSceneChanged() {
    // The session dropped the reports (showReport(), showBudget() cleared the tables).
    const bool scene = context_.scene() != nullptr;
    status_->setText(scene ? tr("Pick a family and run it on %1.").arg(context_.sceneSpec())
                           : tr("Open a scene to measure its methods."));
    budget_status_->setText(scene ? tr("Compute the budget of %1.").arg(context_.sceneSpec())
                                  : tr("Open a scene to compute its budget."));
    setBusy(false);
}

void LabDock::run(const QString& family) {
    if (!context_.scene()) return;
    const int index = family_->findData(family);
    if (index >= 0) family_->setCurrentIndex(index);
    status_->setText(tr("Running %1 on %2…").arg(family, context_.sceneSpec()));
    progress_->setRange(0, 0);
    setBusy(true);
    session_->run(family);
}

void LabDock::runBudget() {
    if (!context_.scene()) return;
    budget_status_->setText(tr("Computing the budget of %1…").arg(context_.sceneSpec()));
    setBusy(true);
    progress_->setRange(0, 0);
    session_->runBudget();
}

void LabDock::showReport() {
    setBusy(false);
    const lab::FamilyReport* report = session_->report();
    if (!report) {
        methods_->clear();
        failures_->clear();
        clear_lab_chart(*chart_, labels_);
        chart_->setTitle(QString());
        return;
    }
    QStringList lines{tr("%1 against %2; time in %3")
                          .arg(QString::fromStdString(report->family),
                               QString::fromStdString(report->reference),
                               QString::fromStdString(report->time_unit))};
    for (const std::string& n : report->notes) lines << QString::fromStdString(n);
    for (const std::string& w : report->warnings)
        lines << tr("Warning: %1").arg(QString::fromStdString(w));
    lines << tr("The line joins the Pareto front; the method in use is ringed.");
    status_->setText(lines.join(QLatin1Char('\n')));
    fillReport();
}

void LabDock::showBudget() {
    setBusy(false);
    const lab::BudgetReport* budget = session_->budget();
    if (!budget) {
        categories_->clear();
        findings_->clear();
        return;
    }
    fillBudget();
    QStringList lines;
    for (const std::string& n : budget->notes) lines << QString::fromStdString(n);
    budget_status_->setText(lines.join(QLatin1Char('\n')));
}

void LabDock::refreshMethodInUse() {
    const lab::FamilyReport* report = session_->report();
    if (!report) return;
    const QString family = QString::fromStdString(report->family);
    const QString in_use = in_use_ ? in_use_(family) : QString();
    for (QScatterSeries* s : show_lab_report(*chart_, *report, in_use, labels_))
        connect(s, &QScatterSeries::clicked, this,
                [this, s] { apply(std::size_t(s->property("method").toULongLong())); });
}

void LabDock::apply(std::size_t method) {
    const lab::FamilyReport* report = session_->report();
    if (!report || method >= report->methods.size()) return;
    Q_EMIT applyRequested(QString::fromStdString(report->family),
                          QString::fromStdString(report->methods[method].method.name));
    refreshMethodInUse();
}

bool LabDock::exportPng(const QString& path) {
    return exported(session_->report() && chart_view_->grab().save(path, "PNG"), path);
}

bool LabDock::exported(bool ok, const QString& path) {
    if (!ok) status_->setText(tr("Could not write %1.").arg(path));
    return ok;
}

void LabDock::exportDialog(const QString& filter,
                           const std::function<bool(const QString&)>& write) {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export the Lab report"), {}, filter);
    if (!path.isEmpty()) write(path);
}

} // namespace sherpa::editor
