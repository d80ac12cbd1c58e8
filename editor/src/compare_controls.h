#pragma once
// The viewport's mode switch (View › Viewport Mode and two toolbar buttons): Raster,
// Ray traced, Split, Difference, and what side B of a comparison draws (the ray
// tracer, another debug view, another file, this file with its source textures or
// with tangents made by another method). The menus' actions over a CompareState:
// they act on it and show it.
#include <QObject>

#include <vector>

#include <sherpa/scene/tangents.h>

#include "compare_state.h"

class QAction;
class QActionGroup;
class QMenu;
class QToolBar;
class QToolButton;
class QWidget;

namespace sherpa::editor {

class CompareControls : public QObject {
    Q_OBJECT
public:
    // The menus show `state` and act on it.
    CompareControls(CompareState& state, QWidget* parent);
    QMenu* menu() const { return menu_; } // for View › Viewport Mode
    void addToToolBar(QToolBar* bar);
    // The menu's name of a tangent method (translated), and its command-line name.
    static QString tangentMethodLabel(scene::TangentMethod method);
    static QString tangentMethodName(scene::TangentMethod method);
    void retranslate();

Q_SIGNALS:
    // The user chose "Another File…": the window asks for one and loads it.
    void otherFileRequested();
    // The user chose this file with its source textures (no BC7/BC5): the window loads it.
    void sourceTexturesRequested();
    // The user chose this file with tangents by `method`: the window loads it.
    void tangentsRequested(sherpa::scene::TangentMethod method);

private:
    void sync(); // checks, enabled states and button texts from the state

    CompareState& state_;
    QMenu* menu_;
    QMenu* side_menu_;
    QMenu* side_views_;
    QMenu* side_tangents_;
    QMenu* heat_menu_;
    QMenu* threshold_menu_;
    std::vector<QAction*> heat_actions_, threshold_actions_; // kHeatScales, kThresholds
    QActionGroup* modes_;
    QActionGroup* sides_;
    std::vector<QAction*> mode_actions_; // by ViewportMode
    QAction* side_rays_;
    QAction* side_file_;
    QAction* side_source_;
    std::vector<QAction*> view_actions_;    // ViewCatalog::views() order
    std::vector<QAction*> tangent_actions_; // kAllTangentMethods order
    QToolButton* mode_button_ = nullptr;
    QToolButton* side_button_ = nullptr;
};

} // namespace sherpa::editor
