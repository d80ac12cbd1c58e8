#pragma once
// The window's menus, toolbar and actions (private to main_window*.cpp).
#include <QActionGroup>
#include <QMenu>
#include <QToolBar>
#include <QToolButton>

#include <vector>

#include "main_window.h"

namespace sherpa::editor {

struct MainWindow::Actions {
    QMenu *file, *recent, *builtin, *view, *debug_views, *overlays, *cameras, *docks, *culling,
        *cull_method, *cull_path, *settings, *language, *quality, *help, *checker_density;
    QToolBar* toolbar;
    QToolButton* view_button;
    QToolButton* overlay_button = nullptr; // the Overlays menu on the toolbar
    QAction *open, *reload, *close, *quit, *frame_all, *frame_selection, *fly, *reset_layout;
    QAction *freeze, *box_colouring, *missing_checker, *cpu_path, *gpu_path, *cache_dir, *about,
        *about_qt, *clear_recent;
    QActionGroup *view_group, *method_group, *language_group, *quality_group, *density_group;
    std::vector<QAction*> view_actions, overlay_actions, method_actions, language_actions,
        quality_actions, builtin_actions, density_actions;
};

} // namespace sherpa::editor
