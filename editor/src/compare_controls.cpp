#include "compare_controls.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QToolBar>
#include <QToolButton>
#include <cmath>
#include <string>

#include "view_catalog.h"

namespace sherpa::editor {

namespace {
// Of 255 (sRGB bytes); 0: automatic.
constexpr int kHeatScales[] = {4, 16, 64, 0};
constexpr int kThresholds[] = {1, 2, 4, 8};
// The widest a toolbar button's text gets (its full text in the tooltip).
constexpr int kMaxButtonTextWidth = 220;
} // namespace

CompareControls::CompareControls(CompareState& state, QWidget* parent)
    : QObject(parent), state_(state) {
    menu_ = new QMenu(parent);
    modes_ = new QActionGroup(this);
    for (ViewportMode m : {ViewportMode::Raster, ViewportMode::RayTraced, ViewportMode::Split,
                           ViewportMode::Difference}) {
        QAction* act = modes_->addAction(QString());
        act->setCheckable(true);
        connect(act, &QAction::triggered, &state_, [this, m] { state_.setMode(m); });
        mode_actions_.push_back(act);
        menu_->addAction(act);
    }
    menu_->addSeparator();
    side_menu_ = menu_->addMenu(QString());
    sides_ = new QActionGroup(this);
    side_rays_ = sides_->addAction(QString());
    side_rays_->setCheckable(true);
    connect(side_rays_, &QAction::triggered, &state_,
            [this] { state_.chooseSide(SideB::RayTraced); });
    side_menu_->addAction(side_rays_);
    side_views_ = side_menu_->addMenu(QString());
    for (const ViewEntry& v : ViewCatalog::views()) {
        QAction* act = sides_->addAction(QString());
        act->setCheckable(true);
        const std::uint32_t id = v.id;
        connect(act, &QAction::triggered, &state_,
                [this, id] { state_.chooseSide(SideB::OtherView, id); });
        view_actions_.push_back(act);
        side_views_->addAction(act);
    }
    side_file_ = sides_->addAction(QString());
    side_file_->setCheckable(true);
    // Always asks (another file, or the same one again): the choice lands in setOtherFile.
    connect(side_file_, &QAction::triggered, this, [this] {
        sync(); // keeps the current side checked until a file is loaded
        Q_EMIT otherFileRequested();
    });
    side_menu_->addAction(side_file_);
    heat_menu_ = menu_->addMenu(QString());
    threshold_menu_ = menu_->addMenu(QString());
    auto* heats = new QActionGroup(this);
    for (const int h : kHeatScales) {
        QAction* act = heats->addAction(QString());
        act->setCheckable(true);
        connect(act, &QAction::triggered, &state_,
                [this, h] { state_.setHeatScale(float(h) / 255.0f); });
        heat_actions_.push_back(act);
        heat_menu_->addAction(act);
    }
    auto* thresholds = new QActionGroup(this);
    for (const int t : kThresholds) {
        QAction* act = thresholds->addAction(QString());
        act->setCheckable(true);
        connect(act, &QAction::triggered, &state_,
                [this, t] { state_.setThreshold(float(t) / 255.0f); });
        threshold_actions_.push_back(act);
        threshold_menu_->addAction(act);
    }
    side_source_ = side_menu_->addAction(QString());
    connect(side_source_, &QAction::triggered, this, &CompareControls::sourceTexturesRequested);
    side_tangents_ = side_menu_->addMenu(QString());
    for (const scene::TangentMethod m : scene::kAllTangentMethods) {
        QAction* act = sides_->addAction(QString());
        act->setCheckable(true);
        connect(act, &QAction::triggered, this, [this, m] {
            sync(); // as for another file: checked once loaded
            Q_EMIT tangentsRequested(m);
        });
        tangent_actions_.push_back(act);
        side_tangents_->addAction(act);
    }
    connect(&state_, &CompareState::changed, this, &CompareControls::sync);
    connect(&state_, &CompareState::offerChanged, this, &CompareControls::sync);
    sync();
}

void CompareControls::addToToolBar(QToolBar* bar) {
    mode_button_ = new QToolButton(bar);
    mode_button_->setObjectName(QStringLiteral("viewportModeButton"));
    mode_button_->setMenu(menu_);
    mode_button_->setPopupMode(QToolButton::InstantPopup);
    side_button_ = new QToolButton(bar);
    side_button_->setObjectName(QStringLiteral("compareSideButton"));
    side_button_->setMenu(side_menu_);
    side_button_->setPopupMode(QToolButton::InstantPopup);
    bar->addWidget(mode_button_);
    bar->addWidget(side_button_);
    retranslate();
}

QString CompareControls::tangentMethodLabel(scene::TangentMethod method) {
    switch (method) {
    case scene::TangentMethod::MikkTSpace:
        return tr("MikkTSpace, exact (vertices split per corner)");
    case scene::TangentMethod::MikkTSpaceWelded:
        return tr("MikkTSpace, welded (last corner per vertex)");
    case scene::TangentMethod::Lengyel:
        return tr("Lengyel (summed per vertex)");
    }
    return {};
}

QString CompareControls::tangentMethodName(scene::TangentMethod method) {
    return QString::fromStdString(std::string(to_string(method)));
}

void CompareControls::sync() {
    const ViewportComparison& c = state_.comparison();
    const SideBOffer& offer = state_.offer();
    mode_actions_[static_cast<std::size_t>(ViewportMode::RayTraced)]->setEnabled(offer.ray_tracing);
    side_rays_->setEnabled(offer.ray_tracing);
    mode_actions_[static_cast<std::size_t>(c.mode)]->setChecked(true);
    side_rays_->setChecked(c.side == SideB::RayTraced);
    const bool file = c.side == SideB::OtherFile;
    side_file_->setChecked(file && !offer.tangents);
    for (std::size_t i = 0; i < tangent_actions_.size(); ++i)
        tangent_actions_[i]->setChecked(file && offer.tangents == scene::kAllTangentMethods[i]);
    const std::vector<ViewEntry> views = ViewCatalog::views();
    for (std::size_t i = 0; i < views.size(); ++i)
        view_actions_[i]->setChecked(c.side == SideB::OtherView && views[i].id == c.view);
    for (std::size_t i = 0; i < heat_actions_.size(); ++i)
        heat_actions_[i]->setChecked(std::lround(c.heat_max * 255.0f) == kHeatScales[i]);
    for (std::size_t i = 0; i < threshold_actions_.size(); ++i)
        threshold_actions_[i]->setChecked(std::lround(c.threshold * 255.0f) == kThresholds[i]);
    retranslate();
}

void CompareControls::retranslate() {
    const ViewportComparison& c = state_.comparison();
    const QString& other_file = state_.offer().file;
    const QString modes[] = {tr("Raster"), tr("Ray traced"), tr("Split (A | B)"),
                             tr("Difference (heat map)")};
    for (std::size_t i = 0; i < mode_actions_.size(); ++i) mode_actions_[i]->setText(modes[i]);
    const QString tips[] = {
        tr("The rasterizer: every view, overlays and the selection"),
        tr("Primary rays through the acceleration structures: the surface-data views"),
        tr("Side A left, side B right, one camera: drag the divider line (or Ctrl+drag "
           "anywhere) to move it"),
        tr("Heat map of |A − B| with its legend: mean, max, PSNR, % of pixels over the "
           "threshold")};
    for (std::size_t i = 0; i < mode_actions_.size(); ++i) {
        mode_actions_[i]->setStatusTip(tips[i]);
        mode_actions_[i]->setToolTip(tips[i]);
    }
    menu_->setTitle(tr("Viewport &Mode"));
    side_menu_->setTitle(tr("Compare &With (side B)"));
    side_views_->setTitle(tr("Another Debug View"));
    heat_menu_->setTitle(tr("Difference &Heat Scale"));
    threshold_menu_->setTitle(tr("Difference &Threshold"));
    for (std::size_t i = 0; i < heat_actions_.size(); ++i)
        heat_actions_[i]->setText(kHeatScales[i] > 0
                                      ? tr("%1/255 and above at full heat").arg(kHeatScales[i])
                                      : tr("Automatic (99.9th percentile of the differences)"));
    for (std::size_t i = 0; i < threshold_actions_.size(); ++i)
        threshold_actions_[i]->setText(tr("Over %1/255").arg(kThresholds[i]));
    side_rays_->setText(tr("The Ray Tracer"));
    side_source_->setText(tr("This File, Source Textures (no BC7/BC5)"));
    side_tangents_->setTitle(tr("This File, Tangents Regenerated By"));
    for (std::size_t i = 0; i < tangent_actions_.size(); ++i)
        tangent_actions_[i]->setText(tangentMethodLabel(scene::kAllTangentMethods[i]));
    side_file_->setText(other_file.isEmpty() ? tr("Another File…")
                                             : tr("Another File… (%1)").arg(other_file));
    const std::vector<ViewEntry> views = ViewCatalog::views();
    QString view_label;
    for (std::size_t i = 0; i < views.size(); ++i) {
        view_actions_[i]->setText(views[i].label);
        if (views[i].id == c.view) view_label = views[i].label;
    }
    if (!mode_button_) return;
    mode_button_->setText(tr("Viewport: %1").arg(modes[static_cast<std::size_t>(c.mode)]));
    mode_button_->setStatusTip(
        tr("Raster or ray traced frame, or side A (this view, rasterized) against side B with "
           "one camera. Split: drag the divider line (or Ctrl+drag anywhere) to move it."));
    const QString side = c.side == SideB::RayTraced ? tr("ray tracer")
                         : c.side == SideB::OtherView
                             ? view_label
                             : (other_file.isEmpty() ? tr("no file") : other_file);
    const QString side_text = tr("B: %1").arg(side);
    // A long file name would push the toolbar's last buttons into its overflow menu.
    side_button_->setText(
        side_button_->fontMetrics().elidedText(side_text, Qt::ElideMiddle, kMaxButtonTextWidth));
    const QString side_tip =
        c.comparing() ? tr("What side B of the comparison draws: %1").arg(side)
                      : tr("Side B is shown in the Split and Difference modes (Viewport button); "
                           "choosing it here switches to Split. Now: %1")
                            .arg(side);
    side_button_->setToolTip(side_tip);
    side_button_->setStatusTip(side_tip);
}

} // namespace sherpa::editor
