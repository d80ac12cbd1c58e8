#pragma once
// The read-only state every dock sees ("context in, actions out"): the current
// scene session (the scene with its prepared textures, thumbnails and timings), the selection,
// per-node visibility and the latest culling numbers. Docks hold a const reference and only listen;
// the main window owns the one mutable instance and changes it in answer to the actions docks emit.
#include <QObject>
#include <QString>

#include <memory>
#include <vector>

#include <sherpa/scene/scene.h>

#include "scene_session.h"

namespace sherpa::editor {

struct Selection {
    int node = -1;     // Scene::nodes
    int mesh = -1;     // Scene::meshes (one per glTF primitive)
    int material = -1; // Scene::materials
    int texture = -1;  // Scene::textures
    int vertex = -1;   // in the selected mesh
    int triangle = -1; // in the selected mesh
    bool operator==(const Selection&) const = default;
};

class EditorContext : public QObject {
    Q_OBJECT
public:
    explicit EditorContext(QObject* parent = nullptr);
    ~EditorContext() override;

    // The loaded scene as one value; null when none is open.
    const SceneSession* session() const { return session_.get(); }
    const SharedSession& sharedSession() const { return session_; }
    const Scene* scene() const { return session_ ? session_->scene.get() : nullptr; }
    std::shared_ptr<const Scene> sharedScene() const {
        return session_ ? session_->scene : nullptr;
    }
    QString sceneSpec() const { return session_ ? session_->spec : QString(); }
    const Selection& selection() const { return selection_; }
    bool nodeVisible(int node) const;
    // Instances whose node and every ancestor are visible (hidden_subtrees(), the
    // renderer's rule).
    bool instanceVisible(std::size_t instance) const;
    // Per node, true where unchecked; null while every node is shown. A new mask per
    // change (never modified once handed out): what the viewport's frames carry to
    // the renderer.
    std::shared_ptr<const std::vector<bool>> hiddenNodes() const { return hidden_; }

    // --- mutation, for the main window only (docks see a const context) ---
    // Swaps in a loaded scene in one step (null: none open) and emits sceneReady.
    void setSession(SharedSession session);
    void clearScene() { setSession(nullptr); }
    void setSelection(const Selection& selection);
    // Selects a node and its first primitive (and that primitive's material).
    void selectNode(int node);
    // Selects a primitive of the scene; `node` is an instance's node or -1.
    void selectMesh(int mesh, int node = -1);
    void selectMaterial(int material) { setSelectionField(&Selection::material, material); }
    void selectTexture(int texture) { setSelectionField(&Selection::texture, texture); }
    void selectVertex(int vertex) { setSelectionField(&Selection::vertex, vertex); }
    void selectTriangle(int triangle) { setSelectionField(&Selection::triangle, triangle); }
    void setNodeVisible(int node, bool visible);

Q_SIGNALS:
    // A new session (or none, after Close): the docks read it from the context, the
    // viewport uploads it. Emitted once per setSession(), before selectionChanged.
    void sceneReady();
    void selectionChanged();
    void visibilityChanged();

private:
    void setSelectionField(int Selection::*field, int value);

    SharedSession session_;
    Selection selection_;
    std::shared_ptr<const std::vector<bool>> hidden_;
    std::vector<bool> hidden_subtrees_; // hidden_ with the subtree rule applied
};

} // namespace sherpa::editor
