#include "editor_context.h"

namespace sherpa::editor {

EditorContext::EditorContext(QObject* parent) : QObject(parent) {}
EditorContext::~EditorContext() = default;

bool EditorContext::nodeVisible(int node) const {
    return node < 0 || static_cast<std::size_t>(node) >= node_visible_.size() ||
           node_visible_[static_cast<std::size_t>(node)] != 0;
}

bool EditorContext::instanceVisible(std::size_t instance) const {
    if (!scene() || instance >= scene()->instances.size()) return false;
    // Hiding a node hides its subtree, as in every DCC tool.
    for (int n = static_cast<int>(scene()->instances[instance].node_id); n >= 0;
         n = scene()->nodes[static_cast<std::size_t>(n)].parent)
        if (!nodeVisible(n)) return false;
    return true;
}

void EditorContext::setSession(SharedSession session) {
    session_ = std::move(session);
    selection_ = {};
    node_visible_.assign(session_ ? session_->scene->nodes.size() : 0, 1);
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
    if (node < 0 || static_cast<std::size_t>(node) >= node_visible_.size()) return;
    char& v = node_visible_[static_cast<std::size_t>(node)];
    if ((v != 0) == visible) return;
    v = visible ? 1 : 0;
    Q_EMIT visibilityChanged();
}

} // namespace sherpa::editor
