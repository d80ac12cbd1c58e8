// SelectionController: picking, the docks' selection requests, pointer selection
// (a validation message's JSON pointer -> the object it names, selected, with the dock
// that shows it brought to the front; the resolution is the engine's,
// pointer_target.h) and the selection's highlight in each frame.
#include "selection_controller.h"

#include <sherpa/scene/pointer_target.h>

#include "acceleration_dock.h"
#include "editor_context.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "motion_playback.h"
#include "picking.h"
#include "scene_tree_dock.h"
#include "texture_dock.h"
#include "validation_dock.h"
#include "viewport_window.h"
#include "window_docks.h"

namespace sherpa::editor {

namespace {

// A vertex (or triangle) row of the mesh dock for element `element` of an accessor
// used as `attribute` by `mesh`; -1 when the element is not one row.
int element_row(const scene::Scene& scene, const scene::AccessorUse& use, std::int64_t element,
                bool& triangle) {
    triangle = false;
    if (element < 0 || use.engine_mesh < 0) return -1;
    const scene::Mesh& mesh = scene.meshes[static_cast<std::size_t>(use.engine_mesh)];
    if (use.attribute == "indices") { // index i belongs to triangle i / 3 (lists only)
        triangle = mesh.topology() == scene::Topology::Triangles &&
                   mesh.source_mode == scene::PrimitiveMode::Triangles;
        const std::int64_t row = triangle ? element / 3 : -1;
        return row < static_cast<std::int64_t>(mesh.triangle_count()) ? static_cast<int>(row) : -1;
    }
    // Source vertex -> engine vertex (unwelding keeps the first copy first).
    if (mesh.source_vertex.empty())
        return element < static_cast<std::int64_t>(mesh.vertices.size()) ? static_cast<int>(element)
                                                                         : -1;
    for (std::size_t v = 0; v < mesh.source_vertex.size(); ++v)
        if (mesh.source_vertex[v] == element) return static_cast<int>(v);
    return -1;
}

} // namespace

SelectionController::SelectionController(EditorContext& context, const WindowDocks& docks,
                                         ViewportWindow& viewport, QObject* parent)
    : QObject(parent), context_(context), docks_(docks), viewport_(viewport) {
    connectDocks();
}

void SelectionController::connectDocks() {
    // Actions out of the docks become context changes here, and only here.
    connect(docks_.sceneTree, &SceneTreeDock::selectNodeRequested, &context_.selection(),
            &SceneSelection::selectNode);
    connect(docks_.sceneTree, &SceneTreeDock::selectMeshRequested, &context_.selection(),
            &SceneSelection::selectMesh);
    connect(docks_.sceneTree, &SceneTreeDock::selectMaterialRequested, &context_.selection(),
            &SceneSelection::selectMaterial);
    connect(docks_.sceneTree, &SceneTreeDock::visibilityRequested, &context_.visibility(),
            &NodeVisibility::setNodeVisible);
    connect(docks_.acceleration, &AccelerationDock::selectMeshRequested, &context_.selection(),
            &SceneSelection::selectMesh);
    connect(docks_.mesh, &MeshDock::selectVertexRequested, &context_.selection(),
            &SceneSelection::selectVertex);
    connect(docks_.mesh, &MeshDock::selectTriangleRequested, &context_.selection(),
            &SceneSelection::selectTriangle);
    connect(docks_.material, &MaterialDock::selectTextureRequested, this, [this](int texture) {
        context_.selection().selectTexture(texture);
        docks_.textures->show();
        docks_.textures->raise();
    });
    connect(docks_.textures, &TextureDock::selectTextureRequested, &context_.selection(),
            &SceneSelection::selectTexture);
    connect(
        docks_.validation, &ValidationDock::messageActivated, this,
        [this](const QString& pointer, const QString& message) { showPointer(pointer, message); });
    connect(&context_, &EditorContext::sceneReady, this,
            &SelectionController::showValidationForScene);
    connect(&viewport_.input(), &ViewportInput::clicked, this,
            [this](QPointF ndc) { pickAt(ndc); });
    connect(&context_.selection(), &SceneSelection::changed, &viewport_,
            &ViewportWindow::scheduleFrame);
    connect(&context_.visibility(), &NodeVisibility::changed, &viewport_,
            &ViewportWindow::scheduleFrame);
}

void SelectionController::fill(ViewportRequest& frame) const {
    const Selection& sel = context_.selection().current();
    frame.hiddenNodes = context_.visibility().hidden();
    render::FrameRequest& request = frame.request;
    if (const scene::Scene* scene = context_.scene();
        scene && sel.node >= 0 && is_joint(*scene, static_cast<std::uint32_t>(sel.node)))
        request.selected_joint = static_cast<std::uint32_t>(sel.node);
    request.highlight_outline = outlinedInstances();
    if (const int instance = selectedInstance(); instance >= 0) {
        request.highlight_instance = static_cast<std::uint32_t>(instance);
        if (sel.triangle >= 0)
            request.highlight_triangle = static_cast<std::uint32_t>(sel.triangle);
        if (sel.vertex >= 0) request.highlight_vertex = static_cast<std::uint32_t>(sel.vertex);
    }
}

int SelectionController::pickAt(QPointF ndc) {
    const scene::Scene* scene = context_.scene();
    if (!scene) return -1;
    glm::vec3 origin, direction;
    viewport_.camera().pose().ray({static_cast<float>(ndc.x()), static_cast<float>(ndc.y())},
                                  origin, direction);
    const PickHit hit = pick(*scene, origin, direction, [this](std::size_t i) {
        return context_.visibility().instanceVisible(i);
    });
    if (!hit) {
        context_.selection().set({});
        return -1;
    }
    const scene::MeshInstance& inst = scene->instances[static_cast<std::size_t>(hit.instance)];
    context_.selection().selectMesh(static_cast<int>(inst.mesh_id), static_cast<int>(inst.node_id));
    context_.selection().selectTriangle(static_cast<int>(hit.triangle));
    return static_cast<int>(hit.instance);
}

int SelectionController::selectedInstance() const {
    const scene::Scene* scene = context_.scene();
    const Selection& sel = context_.selection().current();
    if (!scene || sel.mesh < 0) return -1;
    // The selected primitive as placed by the selected node (any node when none is).
    for (std::size_t i = 0; i < scene->instances.size(); ++i) {
        const scene::MeshInstance& inst = scene->instances[i];
        if (static_cast<int>(inst.mesh_id) == sel.mesh &&
            (sel.node < 0 || static_cast<int>(inst.node_id) == sel.node))
            return static_cast<int>(i);
    }
    return -1;
}

std::vector<std::uint32_t> SelectionController::outlinedInstances() const {
    const scene::Scene* scene = context_.scene();
    const int node = context_.selection().current().node;
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

bool SelectionController::selectNodeNamed(const QString& name_or_index) {
    const scene::Scene* scene = context_.scene();
    if (!scene) return false;
    bool is_index = false;
    const int index = name_or_index.toInt(&is_index);
    for (std::size_t n = 0; n < scene->nodes.size(); ++n)
        if (is_index ? static_cast<int>(n) == index
                     : QString::fromStdString(scene->nodes[n].name) == name_or_index) {
            context_.selection().selectNode(static_cast<int>(n));
            return true;
        }
    return false;
}

void SelectionController::showValidationForScene() {
    const scene::Scene* scene = context_.scene();
    docks_.validation->setVisible(scene && !scene->validation.messages.empty());
}

bool SelectionController::showPointer(const QString& pointer, const QString& message) {
    const scene::Scene* scene = context_.scene();
    if (!scene) return false;
    const scene::PointerTarget t = scene::resolve_pointer(*scene, pointer.toStdString());
    QDockWidget* dock = nullptr;
    QString what;
    const auto selectNode = [&] { // the node itself, in the scene tree
        context_.selection().selectNode(t.node);
        dock = docks_.sceneTree;
        what = tr("node %1").arg(t.node);
    };
    switch (t.kind) {
    case scene::TargetKind::Node:
    case scene::TargetKind::SkinJoint:
    case scene::TargetKind::Camera:
    case scene::TargetKind::Light:
    case scene::TargetKind::Skin:
    case scene::TargetKind::Animation:
    case scene::TargetKind::AnimationChannel:
    case scene::TargetKind::AnimationSampler:
        if (t.node >= 0) {
            selectNode();
        }
        break;
    case scene::TargetKind::Mesh:
    case scene::TargetKind::Primitive:
    case scene::TargetKind::Accessor:
        if (t.engine_mesh >= 0) {
            context_.selection().selectMesh(t.engine_mesh, t.node);
            dock = docks_.mesh;
            what = tr("primitive %1").arg(t.engine_mesh);
            if (t.kind == scene::TargetKind::Accessor) {
                bool triangle = false;
                const int row =
                    element_row(*scene, t.uses.front(),
                                scene::element_index_in_message(message.toStdString()), triangle);
                if (row >= 0 && triangle) context_.selection().selectTriangle(row);
                if (row >= 0 && !triangle) context_.selection().selectVertex(row);
                what = tr("accessor %1: %2 of primitive %3")
                           .arg(t.index)
                           .arg(QString::fromStdString(t.uses.front().attribute))
                           .arg(t.engine_mesh);
                if (row >= 0)
                    what += QLatin1String(", ") +
                            (triangle ? tr("triangle %1") : tr("vertex %1")).arg(row);
            }
        } else if (t.node >= 0) {
            selectNode();
        }
        break;
    case scene::TargetKind::Material:
    case scene::TargetKind::Extension:
        if (t.material >= 0) {
            // A primitive drawn with it is highlighted; the material dock shows it.
            if (t.engine_mesh >= 0) context_.selection().selectMesh(t.engine_mesh, t.node);
            context_.selection().selectMaterial(t.material);
            dock = docks_.material;
            what = tr("material %1").arg(t.material);
        }
        break;
    case scene::TargetKind::Texture:
    case scene::TargetKind::Image:
        if (t.texture >= 0) {
            context_.selection().selectTexture(t.texture);
            dock = docks_.textures;
            what = tr("texture %1").arg(t.texture);
        }
        break;
    default:
        break;
    }
    if (!dock) {
        docks_.validation->setTargetText(
            tr("→ nothing the editor can select (%1).")
                .arg(QString::fromUtf8(to_string(t.kind).data(),
                                       qsizetype(to_string(t.kind).size()))));
        return false;
    }
    docks_.validation->setTargetText(tr("→ %1").arg(what));
    dock->show();
    dock->raise();
    return true;
}

} // namespace sherpa::editor
