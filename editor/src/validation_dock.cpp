#include "validation_dock.h"

#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSortFilterProxyModel>
#include <QTreeView>
#include <QVBoxLayout>

#include "editor_context.h"
#include "validation_model.h"

namespace sherpa::editor {

ValidationDock::ValidationDock(const EditorContext& context, QWidget* parent)
    : QDockWidget(parent), context_(context) {
    setObjectName(QStringLiteral("validationDock"));
    model_ = new ValidationModel(context, this);
    proxy_ = new QSortFilterProxyModel(this);
    proxy_->setSourceModel(model_);
    proxy_->setRecursiveFilteringEnabled(true); // a matching message keeps its groups
    proxy_->setAutoAcceptChildRows(true);       // a matching code keeps its messages
    proxy_->setFilterCaseSensitivity(Qt::CaseInsensitive);
    proxy_->setFilterRole(ValidationModel::FilterRole);

    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    summary_ = new QLabel(body);
    summary_->setObjectName(QStringLiteral("validationSummary"));
    summary_->setWordWrap(true);
    filter_ = new QLineEdit(body);
    filter_->setClearButtonEnabled(true);
    view_ = new QTreeView(body);
    view_->setModel(proxy_);
    view_->setUniformRowHeights(true);
    view_->setHeaderHidden(true);
    // Long codes and pointers scroll sideways rather than being cut.
    view_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    view_->header()->setStretchLastSection(false);
    detail_ = new QPlainTextEdit(body);
    detail_->setObjectName(QStringLiteral("validationDetail"));
    detail_->setReadOnly(true);
    detail_->setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    detail_->setMaximumHeight(6 * detail_->fontMetrics().lineSpacing());
    layout->addWidget(summary_);
    layout->addWidget(filter_);
    layout->addWidget(view_, 1);
    layout->addWidget(detail_);
    setWidget(body);

    connect(filter_, &QLineEdit::textChanged, this, [this](const QString& text) {
        proxy_->setFilterFixedString(text);
        view_->expandAll();
    });
    // Moving through the list shows each message in full; a click (or Enter) goes to
    // its object, again on a second click after the user selected something else.
    connect(view_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& current) { showDetail(current); });
    connect(view_, &QTreeView::clicked, this, &ValidationDock::activate);
    connect(view_, &QTreeView::activated, this, &ValidationDock::activate);
    connect(model_, &QAbstractItemModel::modelReset, this, [this] {
        view_->expandAll();
        updateSummary();
        detail_->clear();
    });
    retranslate();
}

void ValidationDock::retranslate() {
    setWindowTitle(tr("Validation"));
    filter_->setPlaceholderText(tr("Filter by code, pointer or text…"));
    updateSummary();
}

void ValidationDock::setFilter(const QString& text) {
    filter_->setText(text);
}

void ValidationDock::updateSummary() {
    const scene::Scene* scene = context_.scene();
    if (!scene) {
        summary_->setText(tr("No scene."));
        return;
    }
    const scene::ValidationReport& r = scene->validation;
    if (r.messages.empty()) {
        summary_->setText(tr("No messages: nothing to report about this file."));
        return;
    }
    QString text = tr("%1 errors, %2 warnings, %3 information, %4 hints. Click a message to "
                      "select what it names.")
                       .arg(r.count(scene::Severity::Error))
                       .arg(r.count(scene::Severity::Warning))
                       .arg(r.count(scene::Severity::Information))
                       .arg(r.count(scene::Severity::Hint));
    if (r.truncated) text += QLatin1Char(' ') + tr("The list is truncated.");
    summary_->setText(text);
}

bool ValidationDock::showDetail(const QModelIndex& current) {
    if (!current.isValid() || current.data(ValidationModel::LevelRole).toInt() !=
                                  static_cast<int>(ValidationModel::Level::Message)) {
        detail_->clear();
        message_text_.clear();
        return false;
    }
    message_text_ = QStringLiteral("%1 %2\n%3")
                        .arg(current.data(ValidationModel::CodeRole).toString(),
                             current.data(ValidationModel::PointerRole).toString(),
                             current.data(ValidationModel::MessageRole).toString());
    detail_->setPlainText(message_text_);
    return true;
}

void ValidationDock::activate(const QModelIndex& index) {
    if (!showDetail(index)) return;
    Q_EMIT messageActivated(index.data(ValidationModel::PointerRole).toString(),
                            index.data(ValidationModel::MessageRole).toString());
}

bool ValidationDock::activatePointer(const QString& pointer) {
    const QModelIndex source = model_->indexOfPointer(pointer);
    QModelIndex target = proxy_->mapFromSource(source);
    if (!target.isValid()) {
        filter_->clear(); // filtered out: show every message again
        target = proxy_->mapFromSource(source);
    }
    if (!target.isValid()) return false;
    view_->setCurrentIndex(target);
    view_->scrollTo(target);
    activate(target);
    return true;
}

void ValidationDock::setTargetText(const QString& text) {
    detail_->setPlainText(message_text_ + QLatin1Char('\n') + text);
}

QString ValidationDock::detailText() const {
    return detail_->toPlainText();
}

} // namespace sherpa::editor
