#pragma once
// The Lab dock's tables (methods, failures, budget) as one read-only model filled
// from the engine's reports: numbers keep their value under Qt::UserRole (sorting,
// tests) and show with four significant digits, as `sherpa-cli lab` prints them.
#include <QAbstractTableModel>
#include <QStringList>
#include <QVariant>

#include <vector>

#include <sherpa/lab/budget.h>
#include <sherpa/lab/family.h>

namespace sherpa::editor {

class LabTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    using QAbstractTableModel::QAbstractTableModel;
    void setTable(QStringList headers, std::vector<QVariantList> rows);
    void clear() { setTable({}, {}); }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    QStringList headers_;
    std::vector<QVariantList> rows_;
};

// One row per method: method, parameters, time, each error figure any method has
// (by its engine name, as in the CSV and JSON), failures (units), note.
void fill_methods(LabTableModel& model, const lab::FamilyReport& report);
// One row per failure: method, cause, where, count.
void fill_failures(LabTableModel& model, const lab::FamilyReport& report);
// GPU bytes per category: unified, stored, needed.
void fill_budget_categories(LabTableModel& model, const lab::BudgetReport& report);
// Oversized textures and unread attributes: what, where, detail.
void fill_budget_findings(LabTableModel& model, const lab::BudgetReport& report);

} // namespace sherpa::editor
