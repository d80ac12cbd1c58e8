#pragma once
// What the viewport shows and from where: View › Debug View, Overlays and UV Checker
// Density, the Culling menu (freeze, box colours, method, CPU or GPU path), the
// Environment menu and View › Tone Mapping (the environment made on the render thread),
// material variants, the shadow settings the Lab dock applies, and the camera
// choices (frame all, frame the selection, fly, View › glTF Cameras, a camera node of
// the scene tree). Ids from the engine's table (ViewCatalog): names are parsed once,
// where they enter (menu, settings, command line), never per frame.
#include <QObject>
#include <QString>

#include <cstdint>
#include <optional>

#include <sherpa/render/environment.h>
#include <sherpa/scene/shadow_cascades.h>

#include "gpu_viewport.h"

class QMainWindow;
class QMenu;

namespace sherpa::editor {

class CullingMonitor;
class EditorContext;
class EditorSettings;
class EnvironmentMenu;
class RenderController;
class ViewportWindow;
struct WindowActions;
struct WindowDocks;

class ViewController : public QObject {
    Q_OBJECT
public:
    // `actions`' menus exist (the Environment menu goes before Culling, Tone Mapping
    // before glTF Cameras).
    ViewController(EditorContext& context, EditorSettings& settings, CullingMonitor& culling,
                   const WindowDocks& docks, ViewportWindow& viewport, WindowActions& actions,
                   RenderController& frames, QMainWindow& window);

    // `remember`: store it as the setting of later launches. One-shot command-line
    // flags pass false, so one `--view` run does not stick.
    bool setDebugView(const QString& name, bool remember = true);
    QString debugView() const; // its name
    // Culling › Path: the renderer culls on the GPU (true) or the CPU.
    void setGpuCulling(bool gpu);
    // The Environment menu and View › Tone Mapping.
    EnvironmentMenu& environmentMenu() const { return *environment_; }
    // The view, overlays, culling, shadow and display fields of the next frame.
    void fill(render::FrameRequest& request) const;
    // The menus' texts and checks in the current language.
    void retranslate();
    // The menu's environment to the viewport (made on the render thread once).
    void applyEnvironment();
    // Looks through the scene's camera placed by `node` (View › glTF Cameras).
    void jumpToCamera(int node);
    // The camera moved: culling follows, the next frame shows it.
    void cameraChanged();

private:
    void connectActions();
    void setupEnvironment();
    void connectLab();
    void updateLabLighting(); // the Lab's lit frames lit as the viewport is
    void frameAll();          // View › Frame All and F: the camera framed on the scene
    void frameSelection();
    void fillCamerasMenu(QMenu& menu);
    void retranslateOverlayButton(); // "Overlays (2)" and which in its tooltip

    EditorContext& context_;
    EditorSettings& settings_;
    CullingMonitor& culling_;
    const WindowDocks& docks_;
    ViewportWindow& viewport_;
    WindowActions& a_;
    RenderController& frames_;
    QMainWindow& window_;
    EnvironmentMenu* environment_ = nullptr;
    std::optional<render::EnvironmentChoice> environment_posted_; // last given to the viewport
    std::uint32_t view_ = 0;                                      // render::DebugView::Lit
    std::uint32_t overlays_ = 0; // render::Overlay bits of the Overlays menu
    // The Lab's shadows family applied; 0 taps: the device's default.
    std::uint32_t shadow_cascades_ = scene::kDefaultShadowCascades, shadow_pcf_taps_ = 0;
};

} // namespace sherpa::editor
