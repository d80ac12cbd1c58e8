#pragma once
// What is selected in the open scene (node, primitive, material, texture, vertex,
// triangle) and the rules that make one selection from another (a node selects its
// first primitive and that primitive's material). Part of EditorContext: docks read
// it and listen to changed(); the window's controllers change it.
#include <QObject>

namespace sherpa::editor {

class EditorContext;

struct Selection {
    int node = -1;     // Scene::nodes
    int mesh = -1;     // Scene::meshes (one per glTF primitive)
    int material = -1; // Scene::materials
    int texture = -1;  // Scene::textures
    int vertex = -1;   // in the selected mesh
    int triangle = -1; // in the selected mesh
    bool operator==(const Selection&) const = default;
};

class SceneSelection : public QObject {
    Q_OBJECT
public:
    // Selects within `context`'s scene.
    explicit SceneSelection(const EditorContext& context);

    const Selection& current() const { return selection_; }
    void set(const Selection& selection);
    // Selects a node and its first primitive (and that primitive's material).
    void selectNode(int node);
    // Selects a primitive of the scene; `node` is an instance's node or -1.
    void selectMesh(int mesh, int node = -1);
    void selectMaterial(int material) { setField(&Selection::material, material); }
    void selectTexture(int texture) { setField(&Selection::texture, texture); }
    void selectVertex(int vertex) { setField(&Selection::vertex, vertex); }
    void selectTriangle(int triangle) { setField(&Selection::triangle, triangle); }
    // Nothing selected, without changed(): a new scene (EditorContext::setSession says
    // it once the scene is out).
    void clear() { selection_ = {}; }

Q_SIGNALS:
    void changed();

private:
    void setField(int Selection::*field, int value);

    const EditorContext& context_;
    Selection selection_;
};

} // namespace sherpa::editor
