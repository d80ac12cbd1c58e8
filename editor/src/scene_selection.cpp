#include "scene_selection.h"

#include "editor_context.h"

namespace sherpa::editor {

SceneSelection::SceneSelection(const EditorContext& context) : context_(context) {}

void SceneSelection::set(const Selection& selection) {
    if (selection == selection_) return;
    selection_ = selection;
    Q_EMIT changed();
}

void SceneSelection::selectNode(int node) {
    const scene::Scene* scene = context_.scene();
    Selection s;
    if (!scene || node < 0 || static_cast<std::size_t>(node) >= scene->nodes.size()) return set(s);
    s.node = node;
    const scene::Node& n = scene->nodes[static_cast<std::size_t>(node)];
    if (n.mesh >= 0 && static_cast<std::size_t>(n.mesh) < scene->mesh_primitives.size())
        for (std::int32_t m : scene->mesh_primitives[static_cast<std::size_t>(n.mesh)])
            if (m >= 0) {
                s.mesh = m;
                s.material =
                    static_cast<int>(scene->meshes[static_cast<std::size_t>(m)].material_id);
                break;
            }
    set(s);
}

void SceneSelection::selectMesh(int mesh, int node) {
    const scene::Scene* scene = context_.scene();
    if (!scene || mesh < 0 || static_cast<std::size_t>(mesh) >= scene->meshes.size()) return;
    Selection s;
    s.node = node;
    s.mesh = mesh;
    s.material = static_cast<int>(scene->meshes[static_cast<std::size_t>(mesh)].material_id);
    set(s);
}

void SceneSelection::setField(int Selection::*field, int value) {
    Selection s = selection_;
    s.*field = value;
    set(s);
}

} // namespace sherpa::editor
