#pragma once
// The glTF hierarchy as a tree: scenes > nodes > (child nodes, primitives >
// material, light, camera); after the scenes, skins > joints and animations >
// channels, samplers (scene_tree_motion.cpp). Only a small index of items is built per scene (a
// few ints per node); names and values are read from the engine's Scene.
#include <QAbstractItemModel>

#include <vector>

#include <sherpa/scene/pointer_target.h>

#include "editor_context.h"

namespace sherpa::editor {

class SceneTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum class Kind : std::uint8_t {
        SceneRoot,
        Node,
        Primitive,
        Material,
        Light,
        Camera,
        Skin,      // index: Scene::skins
        Joint,     // index and node: the joint's node
        Animation, // index: Scene::animations
        Channel,   // index: in its animation (the parent item); node: its target
        Sampler,   // index: in its animation (the parent item)
    };
    enum Column { NameColumn, TypeColumn, DetailColumn, ColumnCount };
    enum Role { KindRole = Qt::UserRole + 1, IndexRole, NodeRole };

    explicit SceneTreeModel(const EditorContext& context, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

    // The item showing `node` in the displayed scene (first occurrence), or invalid.
    QModelIndex indexOfNode(int node) const;
    QModelIndex indexOfPrimitive(int node, int mesh) const;

Q_SIGNALS:
    // Action out: the user ticked a node's visibility box.
    void visibilityRequested(int node, bool visible);

private:
    struct Item {
        Kind kind;
        int index;  // scene, node, PrimitiveInfo, material, light or camera index
        int node;   // owning node (-1 for scenes)
        int parent; // item index, -1 for top level
        int row;
        std::vector<int> children;
    };
    void rebuild();
    int addItem(Kind kind, int index, int node, int parent);
    QString name(const Item& item) const;
    // `full`: every value (the tooltip); else short enough for a narrow dock.
    QString detail(const Item& item, bool full = false) const;
    QString nodeTransform(const scene::Node& node, bool full) const;
    // scene_tree_motion.cpp: skins, joints and animations.
    void addMotion(const scene::Scene& scene);
    QString motionName(const Item& item) const;
    QString motionType(const Item& item) const;
    QString motionDetail(const Item& item, bool full) const;
    std::vector<char> joint_; // per node: a joint of some skin
    // scene_tree_marks.cpp: the worst validation severity per object (-1: none),
    // shown as a marker on its item.
    void rebuildMarks();
    int mark(const Item& item) const;
    scene::ObjectMarks marks_;

    const EditorContext& context_;
    std::vector<Item> items_;
    std::vector<int> top_;
    std::vector<int> node_item_; // first item per node in the displayed scene
};

} // namespace sherpa::editor
