// MainWindow: a validation message's JSON pointer -> the object it names, selected
// (and highlighted in the viewport where it is drawn), with the dock that shows it
// brought to the front. The resolution is the engine's (pointer_target.h).
#include "main_window.h"

#include <sherpa/scene/pointer_target.h>

#include "material_dock.h"
#include "mesh_dock.h"
#include "scene_tree_dock.h"
#include "texture_dock.h"
#include "validation_dock.h"

namespace sherpa::editor {

namespace {

// A vertex (or triangle) row of the mesh dock for element `element` of an accessor
// used as `attribute` by `mesh`; -1 when the element is not one row.
int element_row(const Scene& scene, const AccessorUse& use, std::int64_t element, bool& triangle) {
    triangle = false;
    if (element < 0 || use.engine_mesh < 0) return -1;
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(use.engine_mesh)];
    if (use.attribute == "indices") { // index i belongs to triangle i / 3 (lists only)
        triangle =
            mesh.topology() == Topology::Triangles && mesh.source_mode == PrimitiveMode::Triangles;
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

void MainWindow::showValidationForScene() {
    const Scene* scene = context_.scene();
    validation_->setVisible(scene && !scene->validation.messages.empty());
}

void MainWindow::connectValidation() {
    connect(
        validation_, &ValidationDock::messageActivated, this,
        [this](const QString& pointer, const QString& message) { showPointer(pointer, message); });
}

bool MainWindow::showPointer(const QString& pointer, const QString& message) {
    const Scene* scene = context_.scene();
    if (!scene) return false;
    const PointerTarget t = resolve_pointer(*scene, pointer.toStdString());
    QDockWidget* dock = nullptr;
    QString what;
    switch (t.kind) {
    case TargetKind::Node:
    case TargetKind::SkinJoint:
    case TargetKind::Camera:
    case TargetKind::Light:
    case TargetKind::Skin:
    case TargetKind::Animation:
    case TargetKind::AnimationChannel:
    case TargetKind::AnimationSampler:
        if (t.node >= 0) {
            context_.selectNode(t.node);
            dock = scene_tree_;
            what = tr("node %1").arg(t.node);
        }
        break;
    case TargetKind::Mesh:
    case TargetKind::Primitive:
    case TargetKind::Accessor:
        if (t.engine_mesh >= 0) {
            context_.selectMesh(t.engine_mesh, t.node);
            dock = mesh_;
            what = tr("primitive %1").arg(t.engine_mesh);
            if (t.kind == TargetKind::Accessor) {
                bool triangle = false;
                const int row =
                    element_row(*scene, t.uses.front(),
                                element_index_in_message(message.toStdString()), triangle);
                if (row >= 0 && triangle) context_.selectTriangle(row);
                if (row >= 0 && !triangle) context_.selectVertex(row);
                what = tr("accessor %1: %2 of primitive %3")
                           .arg(t.index)
                           .arg(QString::fromStdString(t.uses.front().attribute))
                           .arg(t.engine_mesh);
                if (row >= 0)
                    what += QLatin1String(", ") +
                            (triangle ? tr("triangle %1") : tr("vertex %1")).arg(row);
            }
        } else if (t.node >= 0) {
            context_.selectNode(t.node);
            dock = scene_tree_;
            what = tr("node %1").arg(t.node);
        }
        break;
    case TargetKind::Material:
    case TargetKind::Extension:
        if (t.material >= 0) {
            // A primitive drawn with it is highlighted; the material dock shows it.
            if (t.engine_mesh >= 0) context_.selectMesh(t.engine_mesh, t.node);
            context_.selectMaterial(t.material);
            dock = material_;
            what = tr("material %1").arg(t.material);
        }
        break;
    case TargetKind::Texture:
    case TargetKind::Image:
        if (t.texture >= 0) {
            context_.selectTexture(t.texture);
            dock = textures_;
            what = tr("texture %1").arg(t.texture);
        }
        break;
    default:
        break;
    }
    if (!dock) {
        validation_->setTargetText(
            tr("→ nothing the editor can select (%1).")
                .arg(QString::fromUtf8(to_string(t.kind).data(),
                                       qsizetype(to_string(t.kind).size()))));
        return false;
    }
    validation_->setTargetText(tr("→ %1").arg(what));
    dock->show();
    dock->raise();
    return true;
}

} // namespace sherpa::editor
