#pragma once
// The editor window: the Vulkan viewport in the centre, the inspection docks and the
// log around it, menus, toolbar and status bar. It owns the one mutable EditorContext
// and assembles the window; what the menus and docks ask is done by its controllers
// (context in, actions out), each with its own slots and state: LoadController
// (open, cancel, progress, recent files, load errors), ViewController (views,
// overlays, culling, environment, camera choices), SelectionController (picking,
// pointers, highlight), CompareController (A/B comparison), MotionController (the
// timeline's pose) and RenderController (the render thread and its frames).
#include <QMainWindow>

#include <memory>

#include "editor_context.h"
#include "editor_settings.h"
#include "translations.h"
#include "window_docks.h"

class QLabel;
class QProgressBar;
class QPushButton;
class QVulkanInstance;

namespace sherpa::editor {

class CompareControls;
class CompareState;
class CompareController;
class DifferenceLegend;
class CullingMonitor;
class LoadController;
class MotionController;
class ReloadController;
class RenderController;
class SelectionController;
class ViewController;
class ViewportWindow;
struct WindowActions;

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
    const WindowDocks& docks() const { return docks_; }
    ViewportWindow* viewport() const { return viewport_; }
    LoadController& loads() const { return *loads_; }
    ViewController& views() const { return *views_; }
    SelectionController& selection() const { return *selection_; }
    CompareController& comparison() const { return *compare_; }
    RenderController& frames() const { return *frames_; }
    // `remember`: store it as the setting of later launches (a one-shot `--language`
    // run passes false).
    bool setLanguage(const QString& code, bool remember = true);
    const QString& language() const { return translations_.current(); }
    // False for a one-shot `--dock` layout: closing then keeps the stored layout.
    void setLayoutRemembered(bool remember) { remember_layout_ = remember; }
    // The whole window as shown, the viewport's last frame composited in.
    QImage screenshot();

protected:
    void closeEvent(QCloseEvent* e) override;
    void changeEvent(QEvent* e) override;
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;

private:
    void createDocks();
    // Puts every dock back in the default arrangement (View › Reset Layout).
    void resetLayout();
    void createActions(); // main_window_menus.cpp
    void createMenus();   // main_window_menus.cpp
    void createControllers();
    void retranslate(); // main_window_menus.cpp
    void showAbout();   // main_window_menus.cpp
    void updateStatus();

    EditorContext context_;
    EditorSettings settings_;
    Translations translations_;
    QVulkanInstance* vulkan_ = nullptr;
    bool ray_tracing_asked_ = true; // --rt on|off
    CullingMonitor* culling_ = nullptr;
    WindowDocks docks_;
    ViewportWindow* viewport_ = nullptr;
    QWidget* viewport_container_ = nullptr;
    QLabel* frame_label_ = nullptr;
    QLabel* scene_label_ = nullptr;
    QProgressBar* progress_ = nullptr; // the load's, with its Cancel button
    QPushButton* cancel_ = nullptr;
    CompareState* compare_state_ = nullptr;       // the comparison the controls change
    CompareControls* compare_controls_ = nullptr; // on the toolbar and in the View menu
    DifferenceLegend* legend_ = nullptr;          // beside the viewport, in Difference mode
    std::unique_ptr<WindowActions> a_;            // every QAction, built in main_window_menus.cpp
    ReloadController* reload_ = nullptr;          // made with the Settings menu
    RenderController* frames_ = nullptr;
    LoadController* loads_ = nullptr;
    ViewController* views_ = nullptr;
    SelectionController* selection_ = nullptr;
    MotionController* motion_ = nullptr;
    CompareController* compare_ = nullptr;
    bool remember_layout_ = true;
};

} // namespace sherpa::editor
