#include "validation_model.h"

#include <QApplication>
#include <QStyle>

#include <map>

#include "editor_context.h"

namespace sherpa::editor {

QIcon severity_icon(int severity) {
    static const QStyle::StandardPixmap kIcons[] = {
        QStyle::SP_MessageBoxCritical, QStyle::SP_MessageBoxWarning,
        QStyle::SP_MessageBoxInformation, QStyle::SP_MessageBoxQuestion};
    if (severity < 0 || severity > 3 || !qApp) return {};
    return QApplication::style()->standardIcon(kIcons[severity]);
}

ValidationModel::ValidationModel(const EditorContext& context, QObject* parent)
    : QAbstractItemModel(parent), context_(context) {
    connect(&context_, &EditorContext::sceneReady, this, [this] {
        beginResetModel();
        rebuild();
        endResetModel();
    });
    rebuild();
}

const std::vector<scene::ValidationMessage>* ValidationModel::messages() const {
    const scene::Scene* scene = context_.scene();
    return scene ? &scene->validation.messages : nullptr;
}

std::size_t ValidationModel::messageCount() const {
    return messages() ? messages()->size() : 0;
}

void ValidationModel::rebuild() {
    items_.clear();
    top_.clear();
    const auto* all = messages();
    if (!all) return;
    // Severity, then code (sorted), then the file's order.
    std::map<std::pair<int, std::string>, std::vector<int>> groups;
    for (std::size_t i = 0; i < all->size(); ++i)
        groups[{static_cast<int>((*all)[i].severity), (*all)[i].code}].push_back(
            static_cast<int>(i));
    auto add = [this](Level level, int severity, int message, int parent) {
        const int id = static_cast<int>(items_.size());
        std::vector<int>& siblings =
            parent < 0 ? top_ : items_[static_cast<std::size_t>(parent)].children;
        const int row = static_cast<int>(siblings.size());
        siblings.push_back(id); // before push_back: `siblings` may live in items_
        items_.push_back({level, severity, message, parent, row, {}});
        return id;
    };
    int severity_item = -1, last_severity = -1;
    for (const auto& [key, members] : groups) {
        if (key.first != last_severity) {
            severity_item = add(Level::Severity, key.first, members.front(), -1);
            last_severity = key.first;
        }
        const int code_item = add(Level::Code, key.first, members.front(), severity_item);
        for (const int m : members) add(Level::Message, key.first, m, code_item);
    }
}

QModelIndex ValidationModel::index(int row, int column, const QModelIndex& parent) const {
    if (column < 0 || column >= 1 || row < 0) return {};
    const std::vector<int>& siblings =
        parent.isValid() ? items_[parent.internalId()].children : top_;
    if (static_cast<std::size_t>(row) >= siblings.size()) return {};
    return createIndex(row, column, static_cast<quintptr>(siblings[static_cast<std::size_t>(row)]));
}

QModelIndex ValidationModel::parent(const QModelIndex& child) const {
    if (!child.isValid()) return {};
    const int p = items_[child.internalId()].parent;
    if (p < 0) return {};
    return createIndex(items_[static_cast<std::size_t>(p)].row, 0, static_cast<quintptr>(p));
}

int ValidationModel::rowCount(const QModelIndex& parent) const {
    if (parent.column() > 0) return 0;
    return static_cast<int>(parent.isValid() ? items_[parent.internalId()].children.size()
                                             : top_.size());
}

int ValidationModel::columnCount(const QModelIndex&) const {
    return 1;
}

QString ValidationModel::display(const Item& it) const {
    const scene::ValidationMessage& m = (*messages())[static_cast<std::size_t>(it.message)];
    switch (it.level) {
    case Level::Severity: {
        std::size_t n = 0;
        for (const int code : it.children)
            n += items_[static_cast<std::size_t>(code)].children.size();
        switch (it.severity) {
        case 0:
            return tr("Errors (%1)").arg(n);
        case 1:
            return tr("Warnings (%1)").arg(n);
        case 2:
            return tr("Information (%1)").arg(n);
        default:
            return tr("Hints (%1)").arg(n);
        }
    }
    case Level::Code:
        return tr("%1 (%2)").arg(QString::fromStdString(m.code)).arg(it.children.size());
    case Level::Message:
        return m.pointer.empty() ? tr("(the whole file)") : QString::fromStdString(m.pointer);
    }
    return {};
}

QVariant ValidationModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !messages()) return {};
    const Item& it = items_[index.internalId()];
    const scene::ValidationMessage& m = (*messages())[static_cast<std::size_t>(it.message)];
    switch (role) {
    case Qt::DisplayRole:
        return display(it);
    case Qt::DecorationRole:
        return it.level == Level::Severity ? severity_icon(it.severity) : QVariant();
    case Qt::ToolTipRole:
        if (it.level != Level::Message) return {};
        return QStringLiteral("%1: %2").arg(QString::fromStdString(m.code),
                                            QString::fromStdString(m.message));
    case LevelRole:
        return static_cast<int>(it.level);
    case SeverityRole:
        return it.severity;
    case CodeRole:
        return QString::fromStdString(m.code);
    case PointerRole:
        return it.level == Level::Message ? QString::fromStdString(m.pointer) : QVariant();
    case MessageRole:
        return it.level == Level::Message ? QString::fromStdString(m.message) : QVariant();
    case FilterRole:
        return it.level == Level::Message
                   ? QStringLiteral("%1 %2 %3")
                         .arg(QString::fromStdString(m.code), QString::fromStdString(m.pointer),
                              QString::fromStdString(m.message))
                   : display(it);
    default:
        return {};
    }
}

QVariant ValidationModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole || section != 0) return {};
    return tr("Message");
}

QModelIndex ValidationModel::indexOfPointer(const QString& pointer) const {
    const auto* all = messages();
    if (!all) return {};
    for (std::size_t i = 0; i < items_.size(); ++i) {
        const Item& it = items_[i];
        if (it.level == Level::Message &&
            QString::fromStdString((*all)[static_cast<std::size_t>(it.message)].pointer) == pointer)
            return createIndex(it.row, 0, static_cast<quintptr>(i));
    }
    return {};
}

} // namespace sherpa::editor
