#pragma once
// The loaded scene's validation messages (Scene::validation) as a tree: severity >
// code > one row per message, showing its JSON pointer (the message text is the
// tooltip and the dock's detail line). A thin model: rows index into the scene's
// messages, rebuilt when a scene is swapped in.
#include <QAbstractItemModel>
#include <QIcon>

#include <vector>

#include <sherpa/scene/validation.h>

namespace sherpa::editor {

class EditorContext;

// The marker of a severity (Severity's value; -1: none), shared with the scene tree.
QIcon severity_icon(int severity);

class ValidationModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum class Level : std::uint8_t { Severity, Code, Message };
    enum Role {
        LevelRole = Qt::UserRole + 1,
        SeverityRole, // Severity's value
        CodeRole,
        PointerRole, // messages only
        MessageRole, // messages only: the text
        FilterRole,  // what the dock's filter matches: code, pointer and text
    };

    explicit ValidationModel(const EditorContext& context, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

    // The item of the first message with `pointer`, or invalid.
    QModelIndex indexOfPointer(const QString& pointer) const;
    std::size_t messageCount() const;

private:
    struct Item {
        Level level;
        int severity;
        int message; // into the scene's messages (Level::Message), else the group's first
        int parent;  // item index, -1 for top level
        int row;
        std::vector<int> children;
    };
    void rebuild();
    const std::vector<scene::ValidationMessage>* messages() const;
    QString display(const Item& item) const;

    const EditorContext& context_;
    std::vector<Item> items_;
    std::vector<int> top_;
};

} // namespace sherpa::editor
