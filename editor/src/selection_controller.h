#pragma once
// What is selected and how it shows: picking in the viewport, the docks' selection
// requests made into EditorContext changes, a node chosen by name (command line), a
// validation message's JSON pointer resolved to the object it names, and the
// selection's highlight and outline in the next frame.
#include <QObject>
#include <QPointF>
#include <QString>

#include <cstdint>
#include <vector>

#include "gpu_viewport.h"

namespace sherpa::editor {

class EditorContext;
class ViewportWindow;
struct WindowDocks;

class SelectionController : public QObject {
    Q_OBJECT
public:
    SelectionController(EditorContext& context, const WindowDocks& docks, ViewportWindow& viewport,
                        QObject* parent);

    // Selects whatever is under a viewport point (NDC); returns the instance or -1.
    int pickAt(QPointF ndc);
    // Selects a node by name (first match) or index; false if there is none.
    bool selectNodeNamed(const QString& name_or_index);
    // Selects the object a validation message's JSON pointer names (an accessor's
    // element from `message`, as the Khronos validator words it) and brings the dock
    // that shows it to the front; false when the scene has nothing to select there.
    bool showPointer(const QString& pointer, const QString& message = {});
    // The scene instance the viewport highlights (selected primitive placed by the
    // selected node), or -1.
    int selectedInstance() const;
    // The scene instances outlined with it: the selected node's, or for a node without
    // a mesh, every instance of its subtree (its children's meshes) — a group, a
    // skeleton root or an empty transform shows what it moves.
    std::vector<std::uint32_t> outlinedInstances() const;
    // The highlight, outline, selected joint and hidden nodes of the next frame.
    void fill(ViewportRequest& frame) const;
    // The Validation dock shows for files with messages.
    void showValidationForScene();

private:
    void connectDocks();

    EditorContext& context_;
    const WindowDocks& docks_;
    ViewportWindow& viewport_;
};

} // namespace sherpa::editor
