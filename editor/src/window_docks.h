#pragma once
// The window's docks, as MainWindow assembles them: plain pointers (the window owns
// the widgets), handed to the controllers that need them and to whoever inspects the
// window (tests, tools).
namespace sherpa::editor {

class AccelerationDock;
class CullingDock;
class LabDock;
class LogDock;
class MaterialDock;
class MeshDock;
class SceneTreeDock;
class TextureDock;
class TimelineDock;
class ValidationDock;

struct WindowDocks {
    SceneTreeDock* sceneTree = nullptr;
    MeshDock* mesh = nullptr;
    MaterialDock* material = nullptr;
    TextureDock* textures = nullptr;
    CullingDock* culling = nullptr;
    TimelineDock* timeline = nullptr; // animation playback: the pose each frame draws
    LogDock* log = nullptr;
    LabDock* lab = nullptr;
    AccelerationDock* acceleration = nullptr;
    ValidationDock* validation = nullptr; // under the left column, for files with messages
};

} // namespace sherpa::editor
