#pragma once
// The Lab dock: the widgets over a LabSession, which runs a method family of engine/lab
// on the loaded scene off the UI thread (LabRunner). It shows time against error (chart, Pareto
// front, the method in use ringed), the numbers and where each method failed; a Budget tab shows
// what `sherpa-cli budget` prints. Exports CSV and SVG from the engine's writers (the same bytes as
// `sherpa-cli lab --csv` / `--chart`) and the chart as shown in PNG. Context in (the scene, the
// method in use), actions out (applyRequested). The tests find the tables' models and the chart as
// children (objectName, findChild).
#include <QDockWidget>

#include <functional>

#include "lab_chart.h"

class QChart;
class QChartView;
class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QTableView;

namespace sherpa::editor {

class EditorContext;
class LabRunner;
class LabSession;
class LabTableModel;

class LabDock : public QDockWidget {
    Q_OBJECT
public:
    explicit LabDock(const EditorContext& context, QWidget* parent = nullptr);
    ~LabDock() override;

    // The viewport's method of `family` now ("pvertex"; empty where the editor has
    // no switch for that family), asked whenever the chart is drawn.
    void setMethodInUse(std::function<QString(const QString& family)> in_use);
    void refreshMethodInUse();
    // Runs `family` on the scene in the context (cancels a run in flight), as the
    // Run button does.
    void run(const QString& family);
    void runBudget();
    // The runs and their reports (the tables and the chart show them).
    LabSession& session() const { return *session_; }
    LabRunner& runner() const;
    // The chart as shown. False (and a message in the status line) when there is no
    // report or the file can't be written.
    bool exportPng(const QString& path);

Q_SIGNALS:
    // A chart point or table row asked to show `method` of `family` in the viewport.
    void applyRequested(const QString& family, const QString& method);

protected:
    void changeEvent(QEvent* e) override;

private:
    QWidget* buildMethodsTab();
    QWidget* buildBudgetTab();
    void retranslate();
    void onSceneChanged();
    void showReport(); // the session's report (none: cleared)
    void showBudget();
    // The tables of the report (and its chart) / budget, in the current language.
    void fillReport();
    void fillBudget();
    void setBusy(bool busy);
    void apply(std::size_t method);
    // Asks for a path (File dialog) and writes it with `write`.
    void exportDialog(const QString& filter, const std::function<bool(const QString&)>& write);
    // An export's answer: a failure (no report, an unwritable path) says so in the status.
    bool exported(bool ok, const QString& path);

    const EditorContext& context_;
    LabSession* session_;
    std::function<QString(const QString&)> in_use_;
    QTabWidget* tabs_ = nullptr;
    QComboBox* family_ = nullptr;
    QPushButton* run_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QPushButton* budget_run_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* status_ = nullptr;
    QLabel* budget_status_ = nullptr;
    QChart* chart_ = nullptr;
    LabChartLabels labels_;
    QChartView* chart_view_ = nullptr;
    QTabWidget* tables_ = nullptr;
    LabTableModel* methods_ = nullptr;
    LabTableModel* failures_ = nullptr;
    LabTableModel* categories_ = nullptr;
    LabTableModel* findings_ = nullptr;
    QTableView* methods_view_ = nullptr;
    QPushButton* export_csv_ = nullptr;
    QPushButton* export_svg_ = nullptr;
    QPushButton* export_png_ = nullptr;
};

} // namespace sherpa::editor
