#pragma once
// The viewport's mode switch (View › Viewport Mode and two toolbar buttons): Raster,
// Ray traced, Split, Difference, and what side B of a comparison draws (the ray
// tracer, another debug view, another file, this file with its source textures or
// with tangents made by another method). Actions in, one plain state out
// (ViewportComparison, which CompareController puts into every ViewportRequest).
#include <QObject>

#include <optional>
#include <vector>

#include <sherpa/scene/tangents.h>

#include "viewport_mode.h"

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
    explicit CompareControls(QWidget* parent);
    const ViewportComparison& state() const { return state_; }
    QMenu* menu() const { return menu_; } // for View › Viewport Mode
    void addToToolBar(QToolBar* bar);

    void setMode(ViewportMode mode);
    void setSide(SideB side, std::uint32_t view = 0);
    void setDivider(float fraction);
    // Difference: full heat at this difference (0: automatic), "over" above threshold.
    void setHeatScale(float heat_max);
    void setThreshold(float threshold);
    // The device ray traces: the ray-traced mode and side are offered.
    void setRayTracing(bool available);
    // The other file side B shows (its name in the menu); empty: none chosen.
    // `tangents`: it is this file with every primitive's tangents made by that method.
    void setOtherFile(const QString& name, std::optional<TangentMethod> tangents = std::nullopt);
    // The menu's name of a tangent method (translated), and its command-line name.
    static QString tangentMethodLabel(TangentMethod method);
    static QString tangentMethodName(TangentMethod method);
    void retranslate();

Q_SIGNALS:
    void changed();
    // The user chose "Another File…": the window asks for one and loads it.
    void otherFileRequested();
    // The user chose this file with its source textures (no BC7/BC5): the window loads it.
    void sourceTexturesRequested();
    // The user chose this file with tangents by `method`: the window loads it.
    void tangentsRequested(sherpa::TangentMethod method);

private:
    // The side chosen in the menu: a comparison starts (Split) if none is shown.
    void chooseSide(SideB side, std::uint32_t view = 0);
    void sync(); // checks, enabled states and button texts from state_

    ViewportComparison state_;
    QString other_file_;
    std::optional<TangentMethod> other_tangents_;
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
