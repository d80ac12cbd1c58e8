#include "editor_context.h"

#include <sherpa/scene/visibility.h>

#include <algorithm>

namespace sherpa::editor {

EditorContext::EditorContext(QObject* parent) : QObject(parent) {}
EditorContext::~EditorContext() = default;

bool EditorContext::nodeVisible(int node) const {
    return node < 0 || !hidden_ || static_cast<std::size_t>(node) >= hidden_->size() ||
           !(*hidden_)[static_cast<std::size_t>(node)];
}

bool EditorContext::instanceVisible(std::size_t instance) const {
    if (!scene() || instance >= scene()->instances.size()) return false;
    // Hiding a node hides its subtree, as in every DCC tool.
    const std::uint32_t node = scene()->instances[instance].node_id;
    return node >= hidden_subtrees_.size() || !hidden_subtrees_[node];
}

void EditorContext::setSession(SharedSession session) {
    session_ = std::move(session);
    selection_ = {};
    hidden_.reset();
    hidden_subtrees_.clear();
    Q_EMIT sceneReady();
    Q_EMIT selectionChanged();
}

void EditorContext::setSelection(const Selection& selection) {
    if (selection == selection_) return;
    selection_ = selection;
    Q_EMIT selectionChanged();
}

void EditorContext::selectNode(int node) {
    Selection s;
    if (!scene() || node < 0 || static_cast<std::size_t>(node) >= scene()->nodes.size())
        return setSelection(s);
    s.node = node;
    const Node& n = scene()->nodes[static_cast<std::size_t>(node)];
    if (n.mesh >= 0 && static_cast<std::size_t>(n.mesh) < scene()->mesh_primitives.size())
        for (std::int32_t m : scene()->mesh_primitives[static_cast<std::size_t>(n.mesh)])
            if (m >= 0) {
                s.mesh = m;
                s.material =
                    static_cast<int>(scene()->meshes[static_cast<std::size_t>(m)].material_id);
                break;
            }
    setSelection(s);
}

void EditorContext::selectMesh(int mesh, int node) {
    if (!scene() || mesh < 0 || static_cast<std::size_t>(mesh) >= scene()->meshes.size()) return;
    Selection s;
    s.node = node;
    s.mesh = mesh;
    s.material = static_cast<int>(scene()->meshes[static_cast<std::size_t>(mesh)].material_id);
    setSelection(s);
}

void EditorContext::setSelectionField(int Selection::*field, int value) {
    Selection s = selection_;
    s.*field = value;
    setSelection(s);
}

void EditorContext::setNodeVisible(int node, bool visible) {
    if (!scene() || node < 0 || static_cast<std::size_t>(node) >= scene()->nodes.size()) return;
    if (nodeVisible(node) == visible) return;
    auto mask = hidden_ ? std::make_shared<std::vector<bool>>(*hidden_)
                        : std::make_shared<std::vector<bool>>(scene()->nodes.size(), false);
    (*mask)[static_cast<std::size_t>(node)] = !visible;
    hidden_subtrees_ = hidden_subtrees(scene()->nodes, *mask);
    if (std::find(mask->begin(), mask->end(), true) == mask->end())
        hidden_.reset(); // every node shown again
    else
        hidden_ = std::move(mask);
    Q_EMIT visibilityChanged();
}

} // namespace sherpa::editor
