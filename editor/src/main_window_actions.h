#pragma once
// The window's menus, toolbar and actions: made by MainWindow (main_window_menus.cpp),
// each action connected by the controller whose slot it reaches.
#include <QActionGroup>
#include <QMenu>
#include <QToolBar>
#include <QToolButton>

#include <vector>

namespace sherpa::editor {

struct WindowActions {
    QMenu *file, *recent, *builtin, *view, *debug_views, *overlays, *cameras, *docks, *culling,
        *cull_method, *cull_path, *settings, *language, *quality, *help, *checker_density;
    QToolBar* toolbar;
    QToolButton* view_button;
    QToolButton* overlay_button = nullptr; // the Overlays menu on the toolbar
    QAction *open, *reload, *close, *quit, *frame_all, *frame_selection, *fly, *reset_layout;
    QAction *freeze, *box_colouring, *missing_checker, *cpu_path, *gpu_path, *cache_dir, *about,
        *about_qt, *clear_recent;
    QActionGroup *view_group, *method_group, *language_group, *quality_group, *density_group;
    // view_actions, overlay_actions: ViewCatalog's order; method_actions: Sphere,
    // P-vertex, Exact; data() of view, overlay, language, quality, density and builtin
    // actions: the name, code, level, checks or spec they choose.
    std::vector<QAction*> view_actions, overlay_actions, method_actions, language_actions,
        quality_actions, builtin_actions, density_actions;
};

} // namespace sherpa::editor
