#include "lab_session.h"

#include <QFile>

#include <sherpa/lab/report_export.h>

#include "editor_context.h"
#include "lab_runner.h"

namespace sherpa::editor {
namespace {

bool write_text(const QString& path, const std::string& text) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
           f.write(text.data(), qint64(text.size())) == qint64(text.size());
}

} // namespace

LabSession::LabSession(const EditorContext& context, QObject* parent)
    : QObject(parent), context_(context), runner_(new LabRunner(this)) {
    connect(runner_, &LabRunner::finished, this,
            [this](std::shared_ptr<const lab::FamilyReport> report) {
                report_ = std::move(report);
                Q_EMIT reportChanged();
            });
    connect(runner_, &LabRunner::budgetFinished, this,
            [this](std::shared_ptr<const lab::BudgetReport> report) {
                budget_ = std::move(report);
                Q_EMIT budgetChanged();
            });
    connect(&context_, &EditorContext::sceneReady, this, [this] {
        cancel();
        report_.reset();
        budget_.reset();
        Q_EMIT reportChanged();
        Q_EMIT budgetChanged();
    });
}

LabSession::~LabSession() = default;

bool LabSession::run(const QString& family) {
    if (!context_.scene()) return false;
    runner_->start(family, context_.sceneSpec());
    return true;
}

bool LabSession::runBudget() {
    if (!context_.scene()) return false;
    runner_->startBudget(context_.sharedScene());
    return true;
}

void LabSession::cancel() {
    runner_->cancel();
}

bool LabSession::exportCsv(const QString& path) const {
    return report_ && write_text(path, lab::report_csv(*report_));
}

bool LabSession::exportSvg(const QString& path) const {
    return report_ && write_text(path, lab::report_svg(*report_));
}

} // namespace sherpa::editor
