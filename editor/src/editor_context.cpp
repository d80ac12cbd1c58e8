#include "editor_context.h"

namespace sherpa::editor {

EditorContext::EditorContext(QObject* parent) : QObject(parent) {}
EditorContext::~EditorContext() = default;

void EditorContext::setSession(SharedSession session) {
    session_ = std::move(session);
    selection_.clear();
    visibility_.clear();
    Q_EMIT sceneReady();
    // The new scene is out: then what is selected in it (nothing), for every listener.
    Q_EMIT selection_.changed();
}

} // namespace sherpa::editor
