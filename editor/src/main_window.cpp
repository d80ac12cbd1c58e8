#include "main_window.h"
#include "main_window_actions.h"

#include <QAbstractItemView>
#include <QCloseEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
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
#include "compare_controls.h"
#include "culling_dock.h"
#include "culling_monitor.h"
#include "difference_legend.h"
#include "gpu_viewport.h"
#include "lab_dock.h"
#include "log_dock.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "picking.h"
#include "render_thread.h"
#include "scene_tree_dock.h"
#include "texture_dock.h"
#include "timeline_dock.h"
#include "validation_dock.h"
#include "view_catalog.h"
#include "view_fitting.h"
#include "viewport_window.h"

#include <sherpa/scene/framing.h>

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
    loader_.setParent(this); // members: they leave the children before QObject deletes them
    loader_.setObjectName(QStringLiteral("sceneLoader"));
    compare_loader_.setParent(this);
    compare_loader_.setObjectName(QStringLiteral("compareLoader"));

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
    legend_->hide();
    centre_layout->addWidget(viewport_container_, 1);
    centre_layout->addWidget(legend_);
    setCentralWidget(centre);
    compare_ = new CompareControls(this);

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

    last_report_ = std::make_unique<FrameReport>();
    createDocks();
    createActions();
    createMenus();
    setupEnvironment();
    connectActions();
    // Its device is made on the render thread while the window shows; the first
    // scene starts loading once it is known (its textures are prepared for it).
    createRenderer();

    resize(1600, 1000);
    restoreGeometry(settings_.geometry());
    restoreState(settings_.windowState());
    setDebugView(settings_.lastView(), false);
    QString language = settings_.language();
    // The system default is not a choice: leave the setting empty so it follows the system.
    if (language.isEmpty()) language = Translations::systemDefault();
    setLanguage(language, false);
    retranslate();
    updateStatus();
}

MainWindow::~MainWindow() {
    // The swapchain must go before the window's surface does; the viewport's signals
    // would reach this half-destroyed window while QWidget closes it.
    viewport_->disconnect(this);
    render_.reset(); // finishes the frame in flight, frees the engine on its thread
}

void MainWindow::createDocks() {
    scene_tree_ = new SceneTreeDock(context_, this);
    mesh_ = new MeshDock(context_, this);
    material_ = new MaterialDock(context_, this);
    textures_ = new TextureDock(context_, this);
    culling_dock_ = new CullingDock(*culling_, this);
    log_ = new LogDock(this);
    lab_ = new LabDock(context_, this);
    updateLabLighting();
    acceleration_ = new AccelerationDock(context_, this);
    validation_ = new ValidationDock(context_, this);
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
    if (auto* view = textures_->findChild<QAbstractItemView*>())
        view->setTextElideMode(Qt::ElideMiddle);
    timeline_ = new TimelineDock(context_, this);
    resetLayout();
}

void MainWindow::resetLayout() {
    // Two columns of tabs around the viewport, the primary dock of each in front:
    // the viewport keeps most of the window (≥ 55% at 1600×1000).
    for (QDockWidget* d : findChildren<QDockWidget*>()) {
        d->setFloating(false);
        removeDockWidget(d);
    }
    // Vertical tabs: every dock title fits along the column's height, in any language.
    setTabPosition(Qt::LeftDockWidgetArea, QTabWidget::West);
    setTabPosition(Qt::RightDockWidgetArea, QTabWidget::East);
    addDockWidget(Qt::LeftDockWidgetArea, scene_tree_);
    // Under the left column's tabs (split before they are tabbed), so that a message
    // that selects a node (the scene tree in front) leaves the list in view; shown for
    // files with messages.
    splitDockWidget(scene_tree_, validation_, Qt::Vertical);
    addDockWidget(Qt::RightDockWidgetArea, mesh_);
    tabifyDockWidget(scene_tree_, culling_dock_);
    tabifyDockWidget(culling_dock_, log_);
    tabifyDockWidget(log_, acceleration_);
    tabifyDockWidget(mesh_, material_);
    tabifyDockWidget(material_, textures_);
    tabifyDockWidget(textures_, lab_);
    for (QDockWidget* d : findChildren<QDockWidget*>()) d->show();
    scene_tree_->raise();
    mesh_->raise();
    resizeDocks({scene_tree_, mesh_}, {kLeftDockWidth, kRightDockWidth}, Qt::Horizontal);
    showValidationForScene();
    // The timeline under the viewport only (the side columns keep their height), shown
    // for scenes that move.
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    addDockWidget(Qt::BottomDockWidgetArea, timeline_);
    showTimelineForScene();
    // The tab bars exist once the layout has run: dock titles scroll, never elide
    // ("Szenenba…", "Proto…" in German).
    QTimer::singleShot(0, this, [this] {
        for (QTabBar* bar : findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
            bar->setElideMode(Qt::ElideNone);
            bar->setUsesScrollButtons(true);
        }
    });
}

void MainWindow::showTimelineForScene() {
    const Scene* scene = context_.scene();
    timeline_->setVisible(scene && (!scene->animations.empty() || !scene->motions.empty()));
}

void MainWindow::logPoseOverflow() {
    const Scene* scene = context_.scene();
    const auto pose = timeline_->pose();
    std::vector<std::uint32_t> nodes;
    if (scene && pose) nodes = posed_overflow_nodes(*scene, *pose);
    if (nodes == pose_overflow_logged_) return;
    pose_overflow_logged_ = nodes;
    for (std::uint32_t node : nodes)
        log_->append(LogDock::Level::Warning,
                     tr("At %1 s: %2")
                         .arg(timeline_->time(), 0, 'g', 4)
                         .arg(QString::fromStdString(posed_overflow_warning(*scene, node))));
}

void MainWindow::connectActions() {
    // Actions out of the docks become context changes here, and only here.
    connect(timeline_, &TimelineDock::poseChanged, this, [this] {
        culling_->setPose(timeline_->pose()); // the culling dock follows the motion
        logPoseOverflow();
        viewport_->scheduleFrame();
    });
    connect(&context_, &EditorContext::sceneReady, this, &MainWindow::showTimelineForScene);
    connect(&context_, &EditorContext::sceneReady, this, [this] { pose_overflow_logged_.clear(); });
    connect(&context_, &EditorContext::sceneReady, this, &MainWindow::showValidationForScene);
    connectValidation();
    connect(scene_tree_, &SceneTreeDock::selectNodeRequested, &context_,
            &EditorContext::selectNode);
    connect(scene_tree_, &SceneTreeDock::selectMeshRequested, &context_,
            &EditorContext::selectMesh);
    connect(scene_tree_, &SceneTreeDock::selectMaterialRequested, &context_,
            &EditorContext::selectMaterial);
    connect(scene_tree_, &SceneTreeDock::visibilityRequested, &context_,
            &EditorContext::setNodeVisible);
    connect(scene_tree_, &SceneTreeDock::jumpToCameraRequested, this, &MainWindow::jumpToCamera);
    connect(acceleration_, &AccelerationDock::selectMeshRequested, &context_,
            &EditorContext::selectMesh);
    connect(mesh_, &MeshDock::selectVertexRequested, &context_, &EditorContext::selectVertex);
    connect(mesh_, &MeshDock::selectTriangleRequested, &context_, &EditorContext::selectTriangle);
    connect(material_, &MaterialDock::selectTextureRequested, this, [this](int texture) {
        context_.selectTexture(texture);
        textures_->show();
        textures_->raise();
    });
    connect(textures_, &TextureDock::selectTextureRequested, &context_,
            &EditorContext::selectTexture);

    connectLab();
    connectCompare();
    connect(&loader_, &SceneLoadJob::loaded, this, &MainWindow::onLoaded);
    connect(&loader_, &SceneLoadJob::failed, this, &MainWindow::onLoadFailed);
    connect(&loader_, &SceneLoadJob::progress, this, &MainWindow::onProgress);
    connect(&loader_, &SceneLoadJob::canceled, this, [this](const QString& spec) {
        log_->append(LogDock::Level::Info,
                     tr("Loading %1 cancelled; the result is discarded.").arg(spec));
        onProgress(LoadStep::Idle, 0, 0);
        Q_EMIT loadCanceled(spec);
    });
    connect(cancel_, &QPushButton::clicked, this, &MainWindow::cancelLoad);

    connect(viewport_, &ViewportWindow::cameraChanged, this, &MainWindow::onCameraChanged);
    connect(viewport_, &ViewportWindow::clicked, this, [this](QPointF ndc) { pickAt(ndc); });
    connect(viewport_, &ViewportWindow::frameAllRequested, this, [this] {
        if (context_.scene()) viewport_->camera().frameAuto(*context_.scene());
        onCameraChanged();
    });
    connect(viewport_, &ViewportWindow::frameSelectionRequested, this, &MainWindow::frameSelection);
    connect(&context_, &EditorContext::selectionChanged, viewport_, &ViewportWindow::scheduleFrame);
    connect(&context_, &EditorContext::visibilityChanged, viewport_,
            &ViewportWindow::scheduleFrame);
}

QString MainWindow::debugView() const {
    return ViewCatalog::viewName(view_);
}

bool MainWindow::setDebugView(const QString& name, bool remember) {
    const std::optional<std::uint32_t> id = ViewCatalog::viewId(name);
    if (!id) return false;
    view_ = *id;
    if (remember) settings_.setLastView(name);
    retranslate(); // checks the matching menu entry
    updateStreams();
    return true;
}

bool MainWindow::setLanguage(const QString& code, bool remember) {
    if (!translations_.install(code)) return false;
    if (remember) settings_.setLanguage(code);
    // Qt posts LanguageChange (changeEvent retranslates again then); doing it now makes
    // the switch visible in the same event-loop turn.
    retranslate();
    return true;
}

void MainWindow::updateStatus() {
    const Scene* s = context_.scene();
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
    const bool drawn = render_ && !gpu_failed_ && viewport_->isExposed();
    if (drawn) {
        // Drawn now at full size (not a reduced or earlier frame), and on screen.
        last_frame_ = currentFrame();
        render_->renderAndWait(last_frame_, viewport_->vulkanSurface());
        // What the render thread posted back (texture bytes, frame times, passes) shows
        // too, and the columns refitted for it (a zero-time timer each: a few rounds).
        for (int round = 0; round < 3; ++round)
            QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
    }
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
    if (remember_layout_) settings_.saveLayout(saveGeometry(), saveState());
    loader_.cancel();
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
            openScene(url.toLocalFile());
            e->acceptProposedAction();
            return;
        }
}

} // namespace sherpa::editor
