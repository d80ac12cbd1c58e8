// MainWindow: picking, selection and camera jumps in the viewport.
#include "main_window.h"
#include "main_window_actions.h"

#include "culling_dock.h"
#include "culling_monitor.h"
#include "gpu_viewport.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "picking.h"
#include "scene_tree_dock.h"
#include "view_fitting.h"
#include "viewport_window.h"

namespace sherpa::editor {

void MainWindow::onCameraChanged() {
    culling_->update(viewport_->camera().spec());
    viewport_->scheduleFrame();
}

int MainWindow::pickAt(QPointF ndc) {
    const Scene* scene = context_.scene();
    if (!scene) return -1;
    glm::vec3 origin, direction;
    viewport_->camera().ray({static_cast<float>(ndc.x()), static_cast<float>(ndc.y())}, origin,
                            direction);
    const PickHit hit = pick(*scene, origin, direction,
                             [this](std::size_t i) { return context_.instanceVisible(i); });
    if (!hit) {
        context_.setSelection({});
        return -1;
    }
    const MeshInstance& inst = scene->instances[static_cast<std::size_t>(hit.instance)];
    context_.selectMesh(static_cast<int>(inst.mesh_id), static_cast<int>(inst.node_id));
    context_.selectTriangle(static_cast<int>(hit.triangle));
    return static_cast<int>(hit.instance);
}

int MainWindow::selectedInstance() const {
    const Scene* scene = context_.scene();
    const Selection& sel = context_.selection();
    if (!scene || sel.mesh < 0) return -1;
    // The selected primitive as placed by the selected node (any node when none is).
    for (std::size_t i = 0; i < scene->instances.size(); ++i) {
        const MeshInstance& inst = scene->instances[i];
        if (static_cast<int>(inst.mesh_id) == sel.mesh &&
            (sel.node < 0 || static_cast<int>(inst.node_id) == sel.node))
            return static_cast<int>(i);
    }
    return -1;
}

std::vector<std::uint32_t> MainWindow::outlinedInstances() const {
    const Scene* scene = context_.scene();
    const int node = context_.selection().node;
    std::vector<std::uint32_t> out;
    if (!scene || node < 0 || static_cast<std::size_t>(node) >= scene->nodes.size()) return out;
    const bool own_mesh = scene->nodes[static_cast<std::size_t>(node)].mesh >= 0;
    // Nodes of the subtree (the node alone when it has a mesh of its own).
    std::vector<bool> in(scene->nodes.size(), false);
    std::vector<std::uint32_t> stack{static_cast<std::uint32_t>(node)};
    while (!stack.empty()) {
        const std::uint32_t n = stack.back();
        stack.pop_back();
        if (in[n]) continue; // a malformed file's cycle is walked once
        in[n] = true;
        if (own_mesh) continue;
        for (const std::uint32_t c : scene->nodes[n].children)
            if (c < in.size()) stack.push_back(c);
    }
    for (std::size_t i = 0; i < scene->instances.size(); ++i)
        if (scene->instances[i].node_id < in.size() && in[scene->instances[i].node_id])
            out.push_back(static_cast<std::uint32_t>(i));
    return out;
}

bool MainWindow::selectNodeNamed(const QString& name_or_index) {
    const Scene* scene = context_.scene();
    if (!scene) return false;
    bool is_index = false;
    const int index = name_or_index.toInt(&is_index);
    for (std::size_t n = 0; n < scene->nodes.size(); ++n)
        if (is_index ? static_cast<int>(n) == index
                     : QString::fromStdString(scene->nodes[n].name) == name_or_index) {
            context_.selectNode(static_cast<int>(n));
            return true;
        }
    return false;
}

void MainWindow::frameSelection() {
    const Scene* scene = context_.scene();
    const int node = context_.selection().node;
    if (!scene || node < 0) return;
    Aabb box;
    for (const MeshInstance& inst : scene->instances)
        if (static_cast<int>(inst.node_id) == node) box.expand(inst.world_bounds);
    if (!box.valid()) box.expand(glm::vec3(scene->node_world[static_cast<std::size_t>(node)][3]));
    viewport_->camera().frame(box);
    onCameraChanged();
}

void MainWindow::jumpToCamera(int node) {
    const Scene* scene = context_.scene();
    if (!scene) return;
    viewport_->setAutoFrame(false);
    for (std::size_t i = 0; i < scene->placed_cameras.size(); ++i)
        if (static_cast<int>(scene->placed_cameras[i].node) == node) {
            viewport_->camera().jumpTo(*scene, i);
            onCameraChanged();
            return;
        }
}

} // namespace sherpa::editor
