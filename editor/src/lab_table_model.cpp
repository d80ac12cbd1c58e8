#include "lab_table_model.h"

#include <QLocale>

#include <sherpa/lab/report_export.h>

namespace sherpa::editor {

void LabTableModel::setTable(QStringList headers, std::vector<QVariantList> rows) {
    beginResetModel();
    headers_ = std::move(headers);
    rows_ = std::move(rows);
    endResetModel();
}

int LabTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(rows_.size());
}

int LabTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(headers_.size());
}

QVariant LabTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount() || index.column() >= columnCount()) return {};
    const QVariantList& row = rows_[std::size_t(index.row())];
    const QVariant v = index.column() < row.size() ? row[index.column()] : QVariant();
    switch (role) {
    case Qt::DisplayRole:
        if (v.typeId() == QMetaType::Double) return QString::number(v.toDouble(), 'g', 4);
        if (v.typeId() == QMetaType::ULongLong) return QLocale().toString(v.toULongLong());
        return v;
    case Qt::UserRole:
        return v;
    case Qt::TextAlignmentRole:
        if (v.typeId() == QMetaType::Double || v.typeId() == QMetaType::ULongLong)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    default:
        return {};
    }
}

QVariant LabTableModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o == Qt::Horizontal && role == Qt::DisplayRole && section < headers_.size())
        return headers_[section];
    return QAbstractTableModel::headerData(section, o, role);
}

void fill_methods(LabTableModel& model, const lab::FamilyReport& report) {
    const std::vector<std::string> figures = lab::error_figure_names(report); // the CSV's
    QStringList headers{
        LabTableModel::tr("Method"), LabTableModel::tr("Parameters"),
        LabTableModel::tr("Time (%1)").arg(QString::fromStdString(report.time_unit))};
    for (const std::string& f : figures) headers << QString::fromStdString(f);
    headers << LabTableModel::tr("Failures") << LabTableModel::tr("Note");
    std::vector<QVariantList> rows;
    for (const lab::MethodResult& m : report.methods) {
        QVariantList row{QString::fromStdString(m.method.name),
                         QString::fromStdString(m.method.parameters),
                         m.ran ? QVariant(m.time) : QVariant(LabTableModel::tr("not run"))};
        for (const std::string& f : figures)
            row << (m.error(f) ? QVariant(m.error(f)->value) : QVariant());
        row << QVariant::fromValue<qulonglong>(lab::failure_units(m))
            << QString::fromStdString(m.note);
        rows.push_back(std::move(row));
    }
    model.setTable(std::move(headers), std::move(rows));
}

void fill_failures(LabTableModel& model, const lab::FamilyReport& report) {
    std::vector<QVariantList> rows;
    for (const lab::MethodResult& m : report.methods)
        for (const lab::Failure& f : m.failures)
            rows.push_back({QString::fromStdString(m.method.name), QString::fromStdString(f.cause),
                            QString::fromStdString(f.where),
                            QVariant::fromValue<qulonglong>(f.count)});
    model.setTable({LabTableModel::tr("Method"), LabTableModel::tr("Cause"),
                    LabTableModel::tr("Where"), LabTableModel::tr("Count")},
                   std::move(rows));
}

void fill_budget_categories(LabTableModel& model, const lab::BudgetReport& report) {
    std::vector<QVariantList> rows;
    for (const lab::BudgetCategory& c : report.categories)
        rows.push_back({QString::fromStdString(c.name), QVariant::fromValue<qulonglong>(c.unified),
                        QVariant::fromValue<qulonglong>(c.stored),
                        QVariant::fromValue<qulonglong>(c.needed)});
    model.setTable({LabTableModel::tr("GPU bytes"), LabTableModel::tr("Unified"),
                    LabTableModel::tr("Stored"), LabTableModel::tr("Needed")},
                   std::move(rows));
}

void fill_budget_findings(LabTableModel& model, const lab::BudgetReport& report) {
    std::vector<QVariantList> rows;
    for (const lab::OversizedTexture& t : report.oversized)
        rows.push_back(
            {LabTableModel::tr("Oversized texture"),
             QStringLiteral("image %1 %2").arg(t.image).arg(QString::fromStdString(t.where)),
             LabTableModel::tr("%1×%2: %3 texels per pixel at best, 1/%4 per side "
                               "would look the same")
                 .arg(t.width)
                 .arg(t.height)
                 .arg(t.texels_per_pixel, 0, 'g', 3)
                 .arg(t.reduce)});
    for (const lab::UnreadAttribute& u : report.unread)
        rows.push_back({LabTableModel::tr("Unread attribute"),
                        QStringLiteral("mesh %1 primitive %2 %3")
                            .arg(u.mesh)
                            .arg(u.primitive)
                            .arg(QString::fromStdString(u.attribute)),
                        QString::fromStdString(u.reason)});
    model.setTable(
        {LabTableModel::tr("Finding"), LabTableModel::tr("Where"), LabTableModel::tr("Detail")},
        std::move(rows));
}

} // namespace sherpa::editor
