// SceneTreeModel: validation markers. Each item whose object a validation message
// names (engine mark_objects(): nodes, primitives, materials, skins, animations)
// carries the icon of the worst severity among them; a node also shows the worst of
// the primitives and materials it draws, so a collapsed tree still points the way.
#include "scene_tree_model.h"

namespace sherpa::editor {

namespace {
int at(const std::vector<int>& marks, int i) {
    return i >= 0 && static_cast<std::size_t>(i) < marks.size() ? marks[static_cast<std::size_t>(i)]
                                                                : -1;
}
} // namespace

void SceneTreeModel::rebuildMarks() {
    const scene::Scene* scene = context_.scene();
    marks_ = scene ? scene::mark_objects(*scene, scene->validation.messages) : scene::ObjectMarks{};
}

int SceneTreeModel::mark(const Item& item) const {
    const scene::Scene* scene = context_.scene();
    if (!scene) return -1;
    switch (item.kind) {
    case Kind::Node: { // its own messages, and those of what it draws (items below)
        int worst = at(marks_.nodes, item.index);
        auto worse = [&worst](int m) {
            if (m >= 0 && (worst < 0 || m < worst)) worst = m;
        };
        const int mesh = scene->nodes[static_cast<std::size_t>(item.index)].mesh;
        if (mesh >= 0 && static_cast<std::size_t>(mesh) < scene->mesh_primitives.size())
            for (const std::int32_t m : scene->mesh_primitives[static_cast<std::size_t>(mesh)])
                if (m >= 0) {
                    worse(at(marks_.engine_meshes, m));
                    worse(at(
                        marks_.materials,
                        static_cast<int>(scene->meshes[static_cast<std::size_t>(m)].material_id)));
                }
        return worst;
    }
    case Kind::Joint:
        return at(marks_.nodes, item.node);
    case Kind::Primitive:
        return static_cast<std::size_t>(item.index) < scene->primitives.size()
                   ? at(marks_.engine_meshes,
                        scene->primitives[static_cast<std::size_t>(item.index)].engine_mesh)
                   : -1;
    case Kind::Material:
        return at(marks_.materials, item.index);
    case Kind::Skin:
        return at(marks_.skins, item.index);
    case Kind::Animation:
        return at(marks_.animations, item.index);
    case Kind::SceneRoot:
    case Kind::Light:
    case Kind::Camera:
    case Kind::Channel:
    case Kind::Sampler:
        return -1;
    }
    return -1;
}

} // namespace sherpa::editor
