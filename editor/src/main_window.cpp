#include "main_window.h"
#include "main_window_actions.h"

#include <QAbstractItemView>
#include <QCloseEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMimeData>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>
#include <QTabBar>
#include <QTimer>
#include <QVulkanInstance>

#include "acceleration_dock.h"
#include "compare_controller.h"
#include "compare_controls.h"
#include "compare_state.h"
#include "culling_dock.h"
#include "culling_monitor.h"
#include "difference_legend.h"
#include "lab_dock.h"
#include "load_controller.h"
#include "log_dock.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "motion_controller.h"
#include "render_controller.h"
#include "scene_tree_dock.h"
#include "selection_controller.h"
#include "texture_dock.h"
#include "timeline_dock.h"
#include "validation_dock.h"
#include "view_controller.h"
#include "view_fitting.h"
#include "viewport_window.h"

namespace sherpa::editor {

namespace {
// Default dock column widths at 1600×1000 and the narrowest a dock may be.
// The right column's tables (vertex x/y/z, material field/value/offset) need the
// width more than the scene tree, whose details have their own pane.
constexpr int kLeftDockWidth = 300;
constexpr int kRightDockWidth = 330;
constexpr int kDockMinWidth = 160;

bool is_scene_file(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("gltf") || suffix == QLatin1String("glb");
}
} // namespace

MainWindow::MainWindow(QVulkanInstance* vulkan, QWidget* parent, bool ray_tracing)
    : QMainWindow(parent), vulkan_(vulkan), ray_tracing_asked_(ray_tracing) {
    setObjectName(QStringLiteral("sherpaMainWindow"));
    setWindowIcon(QIcon(QStringLiteral(":/sherpa.svg")));
    setAcceptDrops(true);
    setDockOptions(AnimatedDocks | AllowNestedDocks | AllowTabbedDocks);
    culling_ = new CullingMonitor(context_, this);
    // Named children: tests and tools find them with findChild(), not through accessors.
    culling_->setObjectName(QStringLiteral("cullingMonitor"));

    viewport_ = new ViewportWindow(vulkan_);
    viewport_container_ = QWidget::createWindowContainer(viewport_, this);
    viewport_container_->setObjectName(QStringLiteral("viewport"));
    viewport_container_->setMinimumSize(320, 240);
    viewport_container_->setFocusPolicy(Qt::StrongFocus);
    // The difference legend beside the viewport, shown in Difference mode only.
    auto* centre = new QWidget(this);
    auto* centre_layout = new QHBoxLayout(centre);
    centre_layout->setContentsMargins(0, 0, 0, 0);
    centre_layout->setSpacing(0);
    legend_ = new DifferenceLegend(centre);
    legend_->setObjectName(QStringLiteral("differenceLegend"));
    legend_->hide();
    centre_layout->addWidget(viewport_container_, 1);
    centre_layout->addWidget(legend_);
    setCentralWidget(centre);
    compare_state_ = new CompareState(this);
    compare_controls_ = new CompareControls(*compare_state_, this);

    progress_ = new QProgressBar(this);
    progress_->setObjectName(QStringLiteral("loadProgress"));
    progress_->setMaximumWidth(220);
    progress_->hide();
    cancel_ = new QPushButton(this);
    cancel_->hide();
    frame_label_ = new QLabel(this);
    frame_label_->setObjectName(QStringLiteral("frameLabel"));
    scene_label_ = new QLabel(this);
    statusBar()->addWidget(scene_label_, 1);
    statusBar()->addPermanentWidget(progress_);
    statusBar()->addPermanentWidget(cancel_);
    statusBar()->addPermanentWidget(frame_label_);

    createDocks();
    createActions();
    createMenus();
    createControllers();
    // Its device is made on the render thread while the window shows; the first
    // scene starts loading once it is known (its textures are prepared for it).
    frames_->start(vulkan_, ray_tracing_asked_);

    resize(1600, 1000);
    restoreGeometry(settings_.get(setting::kGeometry));
    restoreState(settings_.get(setting::kWindowState));
    views_->setDebugView(settings_.get(setting::kLastView), false);
    QString language = settings_.get(setting::kLanguage);
    // The system default is not a choice: leave the setting empty so it follows the system.
    if (language.isEmpty()) language = Translations::systemDefault();
    setLanguage(language, false);
    retranslate();
    updateStatus();
}

MainWindow::~MainWindow() {
    // The swapchain must go before the window's surface does; the viewport's signals
    // and frame callback would reach this half-destroyed window while QWidget closes it.
    viewport_->disconnect(this);
    viewport_->setFrameCallback({});
    delete frames_; // finishes the frame in flight, frees the engine on its thread
    frames_ = nullptr;
}

// The controllers, each given what it reads and the parts it acts on; their order is
// that of their dependencies (and of EditorContext::sceneReady's receivers).
void MainWindow::createControllers() {
    const bool device_pending = vulkan_ != nullptr;
    motion_ =
        new MotionController(context_, *docks_.timeline, *culling_, *docks_.log, *viewport_, this);
    selection_ = new SelectionController(context_, docks_, *viewport_, this);
    frames_ = new RenderController(context_, *culling_, docks_, *viewport_, *frame_label_,
                                   *a_->missing_checker, this);
    loads_ = new LoadController(context_, settings_, *docks_.log, *viewport_, *docks_.textures, *a_,
                                *progress_, *cancel_, *this, device_pending);
    views_ = new ViewController(context_, settings_, *culling_, docks_, *viewport_, *a_, *frames_,
                                *this);
    compare_ = new CompareController(context_, *compare_state_, *compare_controls_, *legend_,
                                     *docks_.log, *viewport_, *loads_, *frames_, *this);
    frames_->setFrameSource([this] {
        ViewportRequest frame;
        const QSize pixels = viewport_->pixelSize();
        frame.request.width = static_cast<std::uint32_t>(pixels.width());
        frame.request.height = static_cast<std::uint32_t>(pixels.height());
        frame.request.camera = render::explicit_camera(viewport_->camera().pose().spec());
        views_->fill(frame.request);
        selection_->fill(frame);
        motion_->fill(frame.request);
        compare_->fill(frame);
        return frame;
    });
    // The device made: the comparison's ray-traced modes (CompareController), the
    // environment built, then the scene asked for meanwhile loaded.
    connect(frames_, &RenderController::deviceKnown, views_,
            [this](const std::optional<tex::TextureTarget>& target) {
                if (target) views_->applyEnvironment();
                loads_->deviceKnown(target);
            });
    connect(loads_, &LoadController::sceneLoaded, views_, &ViewController::cameraChanged);
    connect(loads_, &LoadController::sceneLoaded, this, &MainWindow::updateStatus);
    connect(&context_, &EditorContext::sceneReady, this, &MainWindow::updateStatus);
    connect(docks_.sceneTree, &SceneTreeDock::jumpToCameraRequested, views_,
            &ViewController::jumpToCamera);
    connect(a_->reset_layout, &QAction::triggered, this, &MainWindow::resetLayout);
}

void MainWindow::createDocks() {
    docks_.sceneTree = new SceneTreeDock(context_, this);
    docks_.mesh = new MeshDock(context_, this);
    docks_.material = new MaterialDock(context_, this);
    docks_.textures = new TextureDock(context_, this);
    docks_.culling = new CullingDock(*culling_, this);
    docks_.log = new LogDock(this);
    docks_.lab = new LabDock(context_, this);
    docks_.acceleration = new AccelerationDock(context_, this);
    docks_.validation = new ValidationDock(context_, this);
    for (QDockWidget* d : findChildren<QDockWidget*>()) {
        // A dock's width is the user's, never its content's: without this, a long
        // summary line (selecting a primitive) widens the mesh dock and squeezes the
        // viewport. Content scrolls or wraps instead.
        d->widget()->setMinimumWidth(kDockMinWidth);
        for (QLabel* label : d->widget()->findChildren<QLabel*>()) label->setWordWrap(true);
        for (QAbstractItemView* view : d->widget()->findChildren<QAbstractItemView*>()) {
            fit_columns_to_content(view);
            copy_exact_on_ctrl_c(view);
        }
    }
    // Content hashes: when a column must cut one, keep both ends.
    if (auto* view = docks_.textures->findChild<QAbstractItemView*>())
        view->setTextElideMode(Qt::ElideMiddle);
    docks_.timeline = new TimelineDock(context_, this);
    resetLayout();
}

void MainWindow::resetLayout() {
    const WindowDocks& d = docks_;
    // Two columns of tabs around the viewport, the primary dock of each in front:
    // the viewport keeps most of the window (≥ 55% at 1600×1000).
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        dock->setFloating(false);
        removeDockWidget(dock);
    }
    // Vertical tabs: every dock title fits along the column's height, in any language.
    setTabPosition(Qt::LeftDockWidgetArea, QTabWidget::West);
    setTabPosition(Qt::RightDockWidgetArea, QTabWidget::East);
    addDockWidget(Qt::LeftDockWidgetArea, d.sceneTree);
    // Under the left column's tabs (split before they are tabbed), so that a message
    // that selects a node (the scene tree in front) leaves the list in view; shown for
    // files with messages.
    splitDockWidget(d.sceneTree, d.validation, Qt::Vertical);
    addDockWidget(Qt::RightDockWidgetArea, d.mesh);
    tabifyDockWidget(d.sceneTree, d.culling);
    tabifyDockWidget(d.culling, d.log);
    tabifyDockWidget(d.log, d.acceleration);
    tabifyDockWidget(d.mesh, d.material);
    tabifyDockWidget(d.material, d.textures);
    tabifyDockWidget(d.textures, d.lab);
    for (QDockWidget* dock : findChildren<QDockWidget*>()) dock->show();
    d.sceneTree->raise();
    d.mesh->raise();
    resizeDocks({d.sceneTree, d.mesh}, {kLeftDockWidth, kRightDockWidth}, Qt::Horizontal);
    // Shown for files with messages (none while the window is made).
    if (selection_)
        selection_->showValidationForScene();
    else
        d.validation->hide();
    // The timeline under the viewport only (the side columns keep their height), shown
    // for scenes that move.
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    addDockWidget(Qt::BottomDockWidgetArea, d.timeline);
    if (motion_)
        motion_->showTimelineForScene();
    else
        d.timeline->hide();
    // The tab bars exist once the layout has run: dock titles scroll, never elide
    // ("Szenenba…", "Proto…" in German).
    QTimer::singleShot(0, this, [this] {
        for (QTabBar* bar : findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
            bar->setElideMode(Qt::ElideNone);
            bar->setUsesScrollButtons(true);
        }
    });
}

bool MainWindow::setLanguage(const QString& code, bool remember) {
    if (!translations_.install(code)) return false;
    if (remember) settings_.set(setting::kLanguage, code);
    // Qt posts LanguageChange (changeEvent retranslates again then); doing it now makes
    // the switch visible in the same event-loop turn.
    retranslate();
    return true;
}

void MainWindow::updateStatus() {
    const scene::Scene* s = context_.scene();
    if (!s) {
        scene_label_->setText(
            tr("No scene. Open a glTF file or a built-in scene from the File menu."));
        setWindowTitle(tr("Sherpa"));
        return;
    }
    scene_label_->setText(tr("%1: %2 nodes, %3 primitives, %4 instances, %5 materials, %6 textures")
                              .arg(context_.sceneSpec())
                              .arg(s->nodes.size())
                              .arg(s->meshes.size())
                              .arg(s->instances.size())
                              .arg(s->materials.size())
                              .arg(s->textures.size()));
    setWindowTitle(tr("%1 — Sherpa").arg(QFileInfo(context_.sceneSpec()).fileName()));
}

QImage MainWindow::screenshot() {
    // Widgets paint into the pixmap; the native viewport does not, so its frame is
    // composited from the renderer's readback when there is one.
    const bool drawn = frames_->renderNow(); // drawn now at full size, and on screen
    QImage image = grab().toImage();
    if (drawn) {
        // The X server holds the presented frame: read it back like any window.
        const QPixmap frame = viewport_->screen()->grabWindow(viewport_->winId());
        QPainter painter(&image);
        painter.drawPixmap(viewport_container_->mapTo(this, QPoint(0, 0)), frame);
    }
    return image;
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (remember_layout_) {
        settings_.set(setting::kGeometry, saveGeometry());
        settings_.set(setting::kWindowState, saveState());
    }
    loads_->cancelLoad();
    QMainWindow::closeEvent(e);
}

void MainWindow::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QMainWindow::changeEvent(e);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
    for (const QUrl& url : e->mimeData()->urls())
        if (url.isLocalFile() && is_scene_file(url.toLocalFile())) {
            e->acceptProposedAction();
            return;
        }
}

void MainWindow::dropEvent(QDropEvent* e) {
    for (const QUrl& url : e->mimeData()->urls())
        if (url.isLocalFile() && is_scene_file(url.toLocalFile())) {
            loads_->openScene(url.toLocalFile());
            e->acceptProposedAction();
            return;
        }
}

} // namespace sherpa::editor
