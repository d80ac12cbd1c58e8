// The menus, toolbar and their texts. Texts are (re)set in retranslate() so a
// language switch at runtime updates every entry.
#include "environment_menu.h"
#include "main_window.h"
#include "main_window_actions.h"

#include <QAbstractItemModel>
#include <QAbstractProxyModel>
#include <QActionGroup>
#include <QApplication>
#include <QDesktopServices>
#include <QDir>
#include <QFileDialog>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QToolBar>
#include <QToolButton>
#include <QUrl>
#include <QVulkanInstance>

#include "acceleration_dock.h"
#include "compare_controls.h"
#include "culling_dock.h"
#include "culling_monitor.h"
#include "difference_legend.h"
#include "gpu_viewport.h"
#include "lab_dock.h"
#include "load_controller.h"
#include "log_dock.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "reload_controller.h"
#include "render_controller.h"
#include "scene_tree_dock.h"
#include "texture_dock.h"
#include "timeline_dock.h"
#include "validation_dock.h"
#include "view_catalog.h"
#include "view_controller.h"
#include "viewport_window.h"

namespace sherpa::editor {

namespace {
const char* const kBuiltins[] = {"builtin:default", "builtin:grid?n=10", "builtin:grid?n=100",
                                 "builtin:grid?n=1000"};
const char* const kQualities[] = {"fast", "balanced", "best"};
// Checks per UV unit offered for the uv checker views (the engine default is 8).
constexpr int kCheckerDensities[] = {4, 8, 16, 32, 64, 128};
} // namespace

void MainWindow::createActions() {
    a_ = std::make_unique<WindowActions>();
    WindowActions& a = *a_;
    a.open = new QAction(this);
    a.open->setShortcut(QKeySequence::Open);
    a.reload = new QAction(this);
    a.reload->setShortcuts({QKeySequence::Refresh, QKeySequence(Qt::CTRL | Qt::Key_R)});
    a.close = new QAction(this);
    a.close->setShortcut(QKeySequence::Close);
    a.quit = new QAction(this);
    a.quit->setShortcut(QKeySequence::Quit);
    a.clear_recent = new QAction(this);
    a.frame_all = new QAction(this);
    a.frame_selection = new QAction(this);
    a.fly = new QAction(this);
    a.fly->setCheckable(true);
    a.fly->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_G));
    a.reset_layout = new QAction(this);
    a.reset_layout->setObjectName(QStringLiteral("resetLayoutAction"));
    a.freeze = new QAction(this);
    a.freeze->setCheckable(true);
    a.box_colouring = new QAction(this);
    a.box_colouring->setCheckable(true);
    a.missing_checker = new QAction(this);
    a.missing_checker->setCheckable(true);
    a.missing_checker->setChecked(true);
    a.cpu_path = new QAction(this);
    a.cpu_path->setCheckable(true);
    a.cpu_path->setChecked(true);
    a.gpu_path = new QAction(this);
    a.gpu_path->setCheckable(true);
    auto* path_group = new QActionGroup(this);
    path_group->addAction(a.cpu_path);
    path_group->addAction(a.gpu_path);
    a.cache_dir = new QAction(this);
    a.about = new QAction(this);
    a.about_qt = new QAction(this);

    a.view_group = new QActionGroup(this);
    for (const ViewEntry& v : ViewCatalog::views()) {
        QAction* act = a.view_group->addAction(QString());
        act->setCheckable(true);
        act->setData(QString::fromLatin1(v.name));
        a.view_actions.push_back(act);
    }
    for (const ViewEntry& o : ViewCatalog::overlays()) {
        auto* act = new QAction(this);
        act->setCheckable(true);
        act->setData(QString::fromLatin1(o.name));
        a.overlay_actions.push_back(act);
    }
    a.method_group = new QActionGroup(this);
    for (scene::CullMethod m :
         {scene::CullMethod::Sphere, scene::CullMethod::PVertex, scene::CullMethod::Exact}) {
        QAction* act = a.method_group->addAction(QString());
        act->setCheckable(true);
        act->setChecked(m == culling_->method());
        a.method_actions.push_back(act);
    }
    a.language_group = new QActionGroup(this);
    for (const QString& code : Translations::available()) {
        QAction* act = a.language_group->addAction(Translations::nativeName(code));
        act->setCheckable(true);
        act->setData(code);
        connect(act, &QAction::triggered, this, [this, code] { setLanguage(code); });
        a.language_actions.push_back(act);
    }
    a.quality_group = new QActionGroup(this);
    for (const char* q : kQualities) {
        QAction* act = a.quality_group->addAction(QString());
        act->setCheckable(true);
        act->setData(QString::fromLatin1(q));
        act->setChecked(settings_.get(setting::kTextureQuality) == QLatin1String(q));
        a.quality_actions.push_back(act);
    }
    a.density_group = new QActionGroup(this);
    for (const int checks : kCheckerDensities) {
        QAction* act = a.density_group->addAction(QString::number(checks));
        act->setCheckable(true);
        act->setData(checks);
        act->setChecked(settings_.get(setting::kCheckerDensity) == checks);
        a.density_actions.push_back(act);
    }
    for (const char* spec : kBuiltins) {
        auto* act = new QAction(this);
        act->setData(QString::fromLatin1(spec));
        a.builtin_actions.push_back(act);
    }

    // The controllers connect the rest (createControllers()).
    connect(a.quit, &QAction::triggered, this, &QWidget::close);
    connect(a.about, &QAction::triggered, this, &MainWindow::showAbout);
    connect(a.about_qt, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainWindow::createMenus() {
    WindowActions& a = *a_;
    QMenuBar* bar = menuBar();
    a.file = bar->addMenu(QString());
    a.file->addAction(a.open);
    a.recent = a.file->addMenu(QString());
    a.builtin = a.file->addMenu(QString());
    for (QAction* act : a.builtin_actions) a.builtin->addAction(act);
    a.file->addSeparator();
    a.file->addAction(a.reload);
    a.file->addAction(a.close);
    a.file->addSeparator();
    a.file->addAction(a.quit);

    a.view = bar->addMenu(QString());
    a.debug_views = a.view->addMenu(QString());
    for (QAction* act : a.view_actions) a.debug_views->addAction(act);
    a.overlays = a.view->addMenu(QString());
    for (QAction* act : a.overlay_actions) a.overlays->addAction(act);
    a.checker_density = a.view->addMenu(QString());
    for (QAction* act : a.density_actions) a.checker_density->addAction(act);
    a.view->addSeparator();
    a.view->addAction(a.frame_all);
    a.view->addAction(a.frame_selection);
    a.view->addAction(a.fly);
    a.view->addAction(a.missing_checker);
    a.view->addMenu(compare_controls_->menu());
    a.cameras = a.view->addMenu(QString());
    a.view->addSeparator();
    a.docks = a.view->addMenu(QString());
    for (QDockWidget* d :
         {static_cast<QDockWidget*>(docks_.sceneTree), static_cast<QDockWidget*>(docks_.mesh),
          static_cast<QDockWidget*>(docks_.material), static_cast<QDockWidget*>(docks_.textures),
          static_cast<QDockWidget*>(docks_.culling), static_cast<QDockWidget*>(docks_.log),
          static_cast<QDockWidget*>(docks_.timeline), static_cast<QDockWidget*>(docks_.lab),
          static_cast<QDockWidget*>(docks_.acceleration),
          static_cast<QDockWidget*>(docks_.validation)})
        a.docks->addAction(d->toggleViewAction());
    a.view->addAction(a.reset_layout);

    a.culling = bar->addMenu(QString());
    a.culling->addAction(a.freeze);
    a.culling->addAction(a.box_colouring);
    a.cull_method = a.culling->addMenu(QString());
    for (QAction* act : a.method_actions) a.cull_method->addAction(act);
    a.cull_path = a.culling->addMenu(QString());
    a.cull_path->addAction(a.cpu_path);
    a.cull_path->addAction(a.gpu_path);

    a.settings = bar->addMenu(QString());
    a.language = a.settings->addMenu(QString());
    for (QAction* act : a.language_actions) a.language->addAction(act);
    a.quality = a.settings->addMenu(QString());
    for (QAction* act : a.quality_actions) a.quality->addAction(act);
    a.settings->addAction(a.cache_dir);
    reload_ = new ReloadController(
        context_, settings_, *docks_.log, *a.settings,
        [this] { loads_->reloadScene(true); }, // the user looks at one spot: keep it
        this);

    a.help = bar->addMenu(QString());
    a.help->addAction(a.about);
    a.help->addAction(a.about_qt);

    a.toolbar = addToolBar(QString());
    a.toolbar->setObjectName(QStringLiteral("mainToolbar"));
    a.toolbar->addAction(a.open);
    a.toolbar->addAction(a.reload);
    a.toolbar->addSeparator();
    a.view_button = new QToolButton(a.toolbar);
    a.view_button->setMenu(a.debug_views);
    a.view_button->setPopupMode(QToolButton::InstantPopup);
    a.toolbar->addWidget(a.view_button);
    compare_controls_->addToToolBar(a.toolbar);
    // One button for the overlays (their menu): six text buttons pushed the toolbar's
    // last ones into its overflow menu, in German at any width.
    a.overlay_button = new QToolButton(a.toolbar);
    a.overlay_button->setObjectName(QStringLiteral("overlaysButton"));
    a.overlay_button->setMenu(a.overlays);
    a.overlay_button->setPopupMode(QToolButton::InstantPopup);
    a.toolbar->addWidget(a.overlay_button);
    a.toolbar->addSeparator();
    a.toolbar->addAction(a.frame_all);
    a.toolbar->addAction(a.fly);
    a.toolbar->addAction(a.freeze);
}

void MainWindow::retranslate() {
    if (!a_) return;
    WindowActions& a = *a_;
    a.file->setTitle(tr("&File"));
    a.open->setText(tr("&Open…"));
    a.recent->setTitle(tr("Open &Recent"));
    a.builtin->setTitle(tr("&Built-in Scenes"));
    const QString builtin_names[] = {tr("Default scene"), tr("Grid, 10 × 10"),
                                     tr("Grid, 100 × 100"), tr("Grid, 1000 × 1000")};
    for (std::size_t i = 0; i < a.builtin_actions.size(); ++i)
        a.builtin_actions[i]->setText(builtin_names[i]);
    a.reload->setText(tr("Re&load"));
    a.close->setText(tr("&Close"));
    a.quit->setText(tr("&Quit"));
    a.clear_recent->setText(tr("Clear list"));
    a.view->setTitle(tr("&View"));
    a.debug_views->setTitle(tr("&Debug View"));
    a.overlays->setTitle(tr("&Overlays"));
    a.checker_density->setTitle(tr("&UV Checker Density (checks per UV unit)"));
    if (views_) views_->retranslate(); // the views' and overlays' names, the Environment menu
    a.frame_all->setText(tr("Frame &All (F)"));
    a.frame_selection->setText(tr("Frame &Selection (Shift+F)"));
    a.fly->setText(tr("&Fly Mode (WASD, Q/E)"));
    a.cameras->setTitle(tr("glTF &Cameras"));
    a.docks->setTitle(tr("&Docks"));
    a.reset_layout->setText(tr("&Reset Layout"));
    a.culling->setTitle(tr("&Culling"));
    a.freeze->setText(tr("&Freeze Culling Camera"));
    a.box_colouring->setText(tr("&Colour Boxes by Result"));
    a.missing_checker->setText(tr("&Missing Textures as Checker"));
    a.missing_checker->setToolTip(
        tr("Draw material slots whose image is missing or undecodable as a magenta/black "
           "checker (colour slots); off: the glTF defaults (white, flat normal)"));
    a.cull_method->setTitle(tr("&Method"));
    const QString methods[] = {tr("Bounding sphere"), tr("P-vertex (AABB)"), tr("Exact (SAT)")};
    for (std::size_t i = 0; i < a.method_actions.size(); ++i)
        a.method_actions[i]->setText(methods[i]);
    a.cull_path->setTitle(tr("&Path"));
    a.cpu_path->setText(tr("CPU"));
    a.gpu_path->setText(tr("GPU (compute shader, indirect draws)"));
    a.settings->setTitle(tr("&Settings"));
    if (reload_) reload_->retranslate();
    a.language->setTitle(tr("&Language"));
    for (QAction* act : a.language_actions)
        act->setChecked(act->data().toString() == translations_.current());
    a.quality->setTitle(tr("&Texture Quality"));
    const QString qualities[] = {tr("Fast"), tr("Balanced"), tr("Best")};
    for (std::size_t i = 0; i < a.quality_actions.size(); ++i)
        a.quality_actions[i]->setText(qualities[i]);
    a.cache_dir->setText(tr("Texture Cache &Directory…"));
    a.help->setTitle(tr("&Help"));
    a.about->setText(tr("&About Sherpa"));
    a.about_qt->setText(tr("About &Qt"));
    a.toolbar->setWindowTitle(tr("Main Toolbar"));
    cancel_->setText(tr("Cancel"));

    docks_.sceneTree->retranslate();
    docks_.mesh->retranslate();
    docks_.material->retranslate();
    docks_.textures->retranslate();
    docks_.culling->retranslate();
    docks_.log->retranslate();
    docks_.timeline->retranslate();
    docks_.acceleration->retranslate();
    docks_.validation->retranslate();
    compare_controls_->retranslate();
    legend_->retranslate();
    // Models read tr() in headerData/data: tell the views to ask again. Source models
    // only, each change announced first: a proxy forwards its source's signals, and a
    // bare layoutChanged() on it left its persistent indices dangling (a crash when a
    // view was chosen with a scene tree item selected).
    for (QAbstractItemModel* m : findChildren<QAbstractItemModel*>()) {
        if (qobject_cast<QAbstractProxyModel*>(m)) continue;
        if (m->columnCount() > 0)
            Q_EMIT m->headerDataChanged(Qt::Horizontal, 0, m->columnCount() - 1);
        Q_EMIT m->layoutAboutToBeChanged();
        Q_EMIT m->layoutChanged();
    }
    updateStatus();
}

void MainWindow::showAbout() {
    QString device = tr("none (Vulkan unavailable)");
    if (frames_->renderer()) {
        const std::optional<tex::TextureTarget>& target = loads_->textureTarget();
        device = target ? QString::fromStdString(target->name) : QString();
    } else if (vulkan_ && vulkan_->isValid()) {
        // Every physical device the instance sees (the engine picks lavapipe first).
        const QStringList names = GpuViewport::deviceNames(vulkan_->vkInstance());
        device = names.join(QStringLiteral("; "));
    }
    QMessageBox::about(this, tr("About Sherpa"),
                       tr("<h3>Sherpa %1</h3><p>A glTF 2.0 scene inspection editor.</p>"
                          "<p>Qt %2 (built with %3)<br>Vulkan devices: %4</p>")
                           .arg(QStringLiteral(SHERPA_VERSION), QString::fromLatin1(qVersion()),
                                QStringLiteral(QT_VERSION_STR), device.toHtmlEscaped()));
}

} // namespace sherpa::editor
