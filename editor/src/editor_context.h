#pragma once
// The read-only state every dock sees ("context in, actions out"): the current
// scene, the selection, per-node visibility and the latest culling numbers. Docks
// hold a const reference and only listen; the main window owns the one mutable
// instance and changes it in answer to the actions docks emit.
#include <QObject>
#include <QString>

#include <memory>
#include <vector>

#include <sherpa/scene/scene.h>

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

// Thumbnails and other per-scene data computed off the UI thread along with the scene.
struct SceneExtras;

class EditorContext : public QObject {
    Q_OBJECT
public:
    explicit EditorContext(QObject* parent = nullptr);
    ~EditorContext() override;

    const Scene* scene() const { return scene_.get(); }
    std::shared_ptr<const Scene> sharedScene() const { return scene_; }
    const SceneExtras* extras() const { return extras_.get(); }
    std::shared_ptr<const SceneExtras> sharedExtras() const { return extras_; }
    const QString& sceneSpec() const { return spec_; }
    const Selection& selection() const { return selection_; }
    bool nodeVisible(int node) const;
    // Instances whose node and every ancestor are visible.
    bool instanceVisible(std::size_t instance) const;

    // --- mutation, for the main window only (docks see a const context) ---
    void setScene(QString spec, std::shared_ptr<const Scene> scene,
                  std::shared_ptr<const SceneExtras> extras);
    void clearScene();
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
    void sceneChanged();
    void selectionChanged();
    void visibilityChanged();

private:
    void setSelectionField(int Selection::*field, int value);

    QString spec_;
    std::shared_ptr<const Scene> scene_;
    std::shared_ptr<const SceneExtras> extras_;
    Selection selection_;
    std::vector<char> node_visible_;
};

} // namespace sherpa::editor
