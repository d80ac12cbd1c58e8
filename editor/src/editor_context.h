#pragma once
// The read-only state every dock sees ("context in, actions out"): the current
// scene session (the scene with its prepared textures, thumbnails and timings), what
// is selected in it (SceneSelection) and which of its nodes are shown
// (NodeVisibility). Docks hold a const reference and only listen; the main window
// owns the one mutable instance and its controllers change it in answer to the
// actions docks emit.
#include <QObject>
#include <QString>

#include <memory>

#include <sherpa/scene/scene.h>

#include "node_visibility.h"
#include "scene_selection.h"
#include "scene_session.h"

namespace sherpa::editor {

class EditorContext : public QObject {
    Q_OBJECT
public:
    explicit EditorContext(QObject* parent = nullptr);
    ~EditorContext() override;

    // The loaded scene as one value; null when none is open.
    const SceneSession* session() const { return session_.get(); }
    const SharedSession& sharedSession() const { return session_; }
    const scene::Scene* scene() const { return session_ ? session_->scene.get() : nullptr; }
    std::shared_ptr<const scene::Scene> sharedScene() const {
        return session_ ? session_->scene : nullptr;
    }
    QString sceneSpec() const { return session_ ? session_->spec : QString(); }
    // What is selected in the scene, and which nodes are shown: read by docks,
    // changed by the window's controllers (docks see a const context).
    const SceneSelection& selection() const { return selection_; }
    SceneSelection& selection() { return selection_; }
    const NodeVisibility& visibility() const { return visibility_; }
    NodeVisibility& visibility() { return visibility_; }

    // Swaps in a loaded scene in one step (null: none open), nothing selected and
    // every node shown, and emits sceneReady, then the selection's changed().
    void setSession(SharedSession session);

Q_SIGNALS:
    // A new session (or none, after Close): the docks read it from the context, the
    // viewport uploads it. Emitted once per setSession(), before the selection's changed().
    void sceneReady();

private:
    SharedSession session_;
    SceneSelection selection_{*this};
    NodeVisibility visibility_{*this};
};

} // namespace sherpa::editor
