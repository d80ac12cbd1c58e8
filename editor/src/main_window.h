#pragma once
// The editor window: the Vulkan viewport in the centre, the five inspection docks
// and the log around it, menus and toolbar, scene loading off the UI thread.
// It owns the one mutable EditorContext and turns the docks' actions into changes.
#include <QMainWindow>

#include <optional>

#include "editor_context.h"
#include "editor_settings.h"
#include "gpu_viewport.h"
#include "resolution_scale.h"
#include "scene_load_job.h"
#include "translations.h"

class QActionGroup;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QToolBar;
class QVulkanInstance;

namespace sherpa::editor {

class AccelerationDock;
class CompareControls;
class EnvironmentMenu;
class CullingDock;
class DifferenceLegend;
class CullingMonitor;
class LabDock;
class ReloadController;
class RenderThread;
struct FrameReport;
class LogDock;
class MaterialDock;
class MeshDock;
class SceneTreeDock;
class TextureDock;
class TimelineDock;
class ValidationDock;
class ViewportWindow;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // `vulkan` may be null (no Vulkan): the viewport then stays empty and says why.
    // `ray_tracing` (--rt on|off): ray trace where the device can (RT viewport modes,
    // acceleration structures built on upload).
    explicit MainWindow(QVulkanInstance* vulkan, QWidget* parent = nullptr,
                        bool ray_tracing = true);
    ~MainWindow() override;

    const EditorContext& context() const { return context_; }
    SceneTreeDock* sceneTreeDock() const { return scene_tree_; }
    MeshDock* meshDock() const { return mesh_; }
    MaterialDock* materialDock() const { return material_; }
    TextureDock* textureDock() const { return textures_; }
    CullingDock* cullingDock() const { return culling_dock_; }
    TimelineDock* timelineDock() const { return timeline_; }
    LogDock* logDock() const { return log_; }
    LabDock* labDock() const { return lab_; }
    AccelerationDock* accelerationDock() const { return acceleration_; }
    ValidationDock* validationDock() const { return validation_; }
    // The renderer ray traces (device support and --rt on); false until the device is known.
    bool rayTracing() const { return ray_tracing_; }
    ViewportWindow* viewport() const { return viewport_; }

    // Starts loading; the current scene stays until the new one is ready.
    void openScene(const QString& spec);
    void reloadScene();
    // Reload on change: the watched files and the Settings menu's choice.
    ReloadController& reloadController() const { return *reload_; }
    void closeScene();
    void cancelLoad();
    // Texture dock actions: delete every KTX2 file of the cache directory; delete one
    // texture's cache files and reload, so it is compressed again.
    int clearTextureCache();
    void recompressTexture(int texture);
    // `remember`: store it as the setting of later launches. One-shot command-line
    // flags pass false, so one `--view` or `--language` run does not stick.
    bool setDebugView(const QString& name, bool remember = true);
    // Culling › Path: the renderer culls on the GPU (true) or the CPU.
    void setGpuCulling(bool gpu);
    QString debugView() const; // its name
    bool setLanguage(const QString& code, bool remember = true);
    const QString& language() const { return translations_.current(); }
    // False for a one-shot `--dock` layout: closing then keeps the stored layout.
    void setLayoutRemembered(bool remember) { remember_layout_ = remember; }
    // Puts every dock back in the default arrangement (View › Reset Layout).
    void resetLayout();
    // The whole window as shown, the viewport's last frame composited in.
    QImage screenshot();
    // Selects the object a validation message's JSON pointer names (an accessor's
    // element from `message`, as the Khronos validator words it) and brings the dock
    // that shows it to the front; false when the scene has nothing to select there.
    bool showPointer(const QString& pointer, const QString& message = {});
    // Selects a node by name (first match) or index; false if there is none.
    bool selectNodeNamed(const QString& name_or_index);
    // Selects whatever is under a viewport point (NDC); returns the instance or -1.
    int pickAt(QPointF ndc);
    // The scene instance the viewport highlights (selected primitive placed by the
    // selected node), or -1.
    int selectedInstance() const;
    // The scene instances outlined with it: the selected node's, or for a node without
    // a mesh, every instance of its subtree (its children's meshes) — a group, a
    // skeleton root or an empty transform shows what it moves.
    std::vector<std::uint32_t> outlinedInstances() const;
    // The settings of the last frame handed to the renderer.
    const ViewportFrame& lastFrame() const { return last_frame_; }
    // The last frame the render thread drew (size, scale, timings).
    const FrameReport& lastReport() const { return *last_report_; }
    // The thread that owns the engine and draws; null without a usable Vulkan device.
    RenderThread* renderer() const { return render_.get(); }
    // The viewport's mode switch and side B of a comparison (main_window_compare.cpp).
    CompareControls& compareControls() const { return *compare_; }
    // The Environment menu and View › Tone Mapping (main_window_environment.cpp).
    EnvironmentMenu& environmentMenu() const { return *environment_; }
    // Loads `spec` as side B of the comparison (File dialog of "Another File…");
    // `source_textures`: its textures uploaded as decoded from their images, not
    // through BC7/BC5 (the compression's error against the source).
    void compareWithFile(const QString& spec, bool source_textures = false);
    // Loads this file again as side B with every triangle primitive's tangents made by
    // `method` (authored ones replaced), from the file's unsplit vertices.
    void compareWithTangents(TangentMethod method);

Q_SIGNALS:
    void sceneLoaded(const QString& spec, double ms);
    void loadFailed(const QString& spec, const QString& error);
    void loadCanceled(const QString& spec);
    void firstFrame(); // the first frame drawn with a scene loaded

protected:
    void closeEvent(QCloseEvent* e) override;
    void changeEvent(QEvent* e) override;
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;

private:
    // main_window_menus.cpp
    void createActions();
    void createMenus();
    void retranslate();
    void retranslateOverlayButton(); // "Overlays (2)" and which in its tooltip
    void rebuildRecentMenu();
    void showAbout();
    void openFileDialog();

    void createDocks();
    void showTimelineForScene();
    // Warns in the log about nodes the timeline's pose pushes past the float range
    // (their bounds are left out; culling keeps them), once per change of that set.
    void logPoseOverflow();
    void createRenderer();
    // The render thread has made its device or failed to: open the scene asked for.
    void deviceKnown();
    void uploadScene();
    // Why the acceleration dock has no structures (--rt off, device, scene).
    QString noAccelerationReason() const;
    // The uploaded textures' warnings (missing, undecodable...) and notices, once per set.
    void logTextureMessages();
    // What the viewport should show now (size, camera, view, selection...).
    ViewportFrame currentFrame() const;
    void renderFrame();
    void onFrameDone(const FrameReport& report);
    // The view's streams on the GPU (a re-upload when a view needs more), before
    // the next frame.
    void updateStreams();
    void connectActions();
    void connectLab();        // main_window_lab.cpp
    void connectValidation(); // main_window_validation.cpp
    void showValidationForScene();
    // main_window_compare.cpp
    void connectCompare();
    void onCompareChanged();
    void setupEnvironment();
    void applyEnvironment();  // the menu's environment to the viewport
    void updateLabLighting(); // the Lab's lit frames lit as the viewport is
    // A frame the ray tracer refused: said in the log and status bar, back to raster.
    void onRefused(const QString& why);
    tex::PipelineOptions textureOptions() const; // the texture cache settings of now
    void onLoaded(SharedSession session);
    void onLoadFailed(const QString& spec, const QString& error);
    void onProgress(LoadStep step, int done, int total);
    void onCameraChanged();
    void frameSelection();
    void jumpToCamera(int node);
    void updateStatus();

    EditorContext context_;
    EditorSettings settings_;
    Translations translations_;
    SceneLoadJob loader_;
    CullingMonitor* culling_ = nullptr;
    QVulkanInstance* vulkan_ = nullptr;
    std::unique_ptr<RenderThread> render_;             // null without a usable Vulkan device
    std::optional<tex::TextureTarget> texture_target_; // the device's, once it is known
    bool device_pending_ = false;   // the render thread is still making the device
    bool ray_tracing_asked_ = true; // --rt on|off
    bool ray_tracing_ = false;      // the device's renderer ray traces
    QString pending_open_;          // asked for while the device was pending
    bool gpu_failed_ = false;       // a frame threw: stop drawing, say so once
    std::weak_ptr<const tex::PreparedTextureSet> logged_textures_; // logTextureMessages()
    std::unique_ptr<FrameReport> last_report_;
    FrameTimes frame_times_;
    ViewportWindow* viewport_ = nullptr;
    QWidget* viewport_container_ = nullptr;
    SceneTreeDock* scene_tree_ = nullptr;
    MeshDock* mesh_ = nullptr;
    MaterialDock* material_ = nullptr;
    TextureDock* textures_ = nullptr;
    CullingDock* culling_dock_ = nullptr;
    TimelineDock* timeline_ = nullptr; // animation playback: the pose each frame draws
    LogDock* log_ = nullptr;
    LabDock* lab_ = nullptr;
    CompareControls* compare_ = nullptr;
    EnvironmentMenu* environment_ = nullptr;
    std::optional<gpu::EnvironmentChoice> environment_posted_; // last given to the viewport
    DifferenceLegend* legend_ = nullptr;
    SceneLoadJob compare_loader_;                   // side B's file
    SharedSession compare_session_;                 // loaded by it, kept while comparing with it
    QString compare_label_;                         // what side B shows (the file, its textures)
    std::optional<TangentMethod> compare_tangents_; // side B's tangents, when regenerated
    AccelerationDock* acceleration_ = nullptr;
    ValidationDock* validation_ = nullptr; // under the left column, for files with messages
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QLabel* frame_label_ = nullptr;
    QLabel* scene_label_ = nullptr;
    // Ids from the engine's table (ViewCatalog): names are parsed once, where they
    // enter (menu, settings, command line), never per frame.
    std::uint32_t view_ = 0;     // gpu::DebugView::Lit
    std::uint32_t overlays_ = 0; // gpu::Overlay bits of the Overlays menu
    // The Lab's shadows family applied (main_window_lab.cpp); 0 taps: the device's default.
    std::uint32_t shadow_cascades_ = kDefaultShadowCascades, shadow_pcf_taps_ = 0;
    bool first_frame_seen_ = false;
    std::vector<std::uint32_t> pose_overflow_logged_; // nodes logPoseOverflow() last named
    bool remember_layout_ = true;
    int pass_frames_left_ = 0; // extra frames until the pass table has the first frame
    ViewportFrame last_frame_;
    ReloadController* reload_ = nullptr; // made with the Settings menu
    bool keep_camera_ = false;           // the next load is this file again: keep the view

    struct Actions; // every QAction, built in main_window_menus.cpp
    std::unique_ptr<Actions> a_;
};

} // namespace sherpa::editor
