#pragma once
// The Lab's runs on the scene in the context and what they found: the last family
// report and budget report, dropped (and a run in flight cancelled) when the scene
// changes, since numbers of another scene would lie about this one. No widgets: the
// Lab dock shows it; the engine's writers export it (the same bytes as
// `sherpa-cli lab --csv` / `--chart`).
#include <QObject>
#include <QString>

#include <memory>

#include <sherpa/lab/budget.h>
#include <sherpa/lab/family.h>

namespace sherpa::editor {

class EditorContext;
class LabRunner;

class LabSession : public QObject {
    Q_OBJECT
public:
    explicit LabSession(const EditorContext& context, QObject* parent = nullptr);
    ~LabSession() override; // the runner cancels and waits for its worker

    // Its progress, failures and cancellations (and the worker's wait, for tests).
    LabRunner& runner() const { return *runner_; }
    // Runs `family` on the scene in the context (cancels a run in flight); false
    // without a scene.
    bool run(const QString& family);
    bool runBudget();
    void cancel();

    const lab::FamilyReport* report() const { return report_.get(); }
    const lab::BudgetReport* budget() const { return budget_.get(); }
    // The engine's CSV / SVG of the report; false without one or when the file can't
    // be written.
    bool exportCsv(const QString& path) const;
    bool exportSvg(const QString& path) const;

Q_SIGNALS:
    // A new report, or none (another scene).
    void reportChanged();
    void budgetChanged();

private:
    const EditorContext& context_;
    LabRunner* runner_;
    std::shared_ptr<const lab::FamilyReport> report_;
    std::shared_ptr<const lab::BudgetReport> budget_;
};

} // namespace sherpa::editor
