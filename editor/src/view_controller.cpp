// ViewController: the View, Culling and Environment menus' choices, the Lab's shadow
// and culling methods applied to the viewport, and the camera choices.
#include "view_controller.h"
#include "main_window_actions.h"

#include <QMainWindow>
#include <QMenuBar>
#include <QPointer>
#include <QStatusBar>

#include <array>

#include <sherpa/lab/families.h>

#include "culling_monitor.h"
#include "editor_context.h"
#include "editor_settings.h"
#include "environment_menu.h"
#include "lab_dock.h"
#include "lab_runner.h"
#include "log_dock.h"
#include "render_controller.h"
#include "variant_menu.h"
#include "view_catalog.h"
#include "viewport_window.h"
#include "window_docks.h"

namespace sherpa::editor {

namespace {
// The Culling › Method menu's order (main_window_menus.cpp).
constexpr std::array kMenuMethods{scene::CullMethod::Sphere, scene::CullMethod::PVertex,
                                  scene::CullMethod::Exact};

// The Lab's name of the culling the viewport does (lab/families.h): the CPU tests by
// their CullMethod name, the GPU path ("gpu") with its p-vertex test.
QString culling_in_use(bool gpu, scene::CullMethod method) {
    if (gpu) return method == scene::CullMethod::PVertex ? QStringLiteral("gpu") : QString();
    const std::string_view name = to_string(method);
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}
} // namespace

ViewController::ViewController(EditorContext& context, EditorSettings& settings,
                               CullingMonitor& culling, const WindowDocks& docks,
                               ViewportWindow& viewport, WindowActions& actions,
                               RenderController& frames, QMainWindow& window)
    : QObject(&window), context_(context), settings_(settings), culling_(culling), docks_(docks),
      viewport_(viewport), a_(actions), frames_(frames), window_(window) {
    connectActions();
    setupEnvironment();
    connectLab();
}

void ViewController::connectActions() {
    for (QAction* act : a_.view_actions)
        connect(act, &QAction::triggered, this,
                [this, act] { setDebugView(act->data().toString()); });
    const std::vector<ViewEntry> overlays = ViewCatalog::overlays();
    for (std::size_t i = 0; i < a_.overlay_actions.size(); ++i)
        connect(a_.overlay_actions[i], &QAction::toggled, this,
                [this, bit = overlays[i].id](bool on) {
                    overlays_ = on ? overlays_ | bit : overlays_ & ~bit;
                    frames_.updateStreams(); // an overlay may read streams no material does
                    retranslateOverlayButton();
                });
    for (std::size_t i = 0; i < a_.method_actions.size(); ++i)
        connect(a_.method_actions[i], &QAction::triggered, this,
                [this, m = kMenuMethods[i]] { culling_.setMethod(m); });
    for (QAction* act : a_.density_actions)
        connect(act, &QAction::triggered, this, [this, act] {
            settings_.set(setting::kCheckerDensity, act->data().toInt());
            viewport_.scheduleFrame();
        });
    connect(a_.frame_all, &QAction::triggered, this, &ViewController::frameAll);
    connect(a_.frame_selection, &QAction::triggered, this, &ViewController::frameSelection);
    connect(a_.fly, &QAction::toggled, &viewport_.input(), &ViewportInput::setFlyMode);
    connect(a_.freeze, &QAction::toggled, &culling_, &CullingMonitor::setFrozen);
    connect(a_.box_colouring, &QAction::toggled, &frames_, &RenderController::updateStreams);
    connect(a_.gpu_path, &QAction::toggled, &culling_, &CullingMonitor::setGpuPath);
    connect(&culling_, &CullingMonitor::updated, &viewport_, &ViewportWindow::scheduleFrame);
    connect(a_.cameras, &QMenu::aboutToShow, this, [this] { fillCamerasMenu(*a_.cameras); });
    const ViewportInput& input = viewport_.input();
    connect(&input, &ViewportInput::cameraChanged, this, &ViewController::cameraChanged);
    connect(&input, &ViewportInput::frameAllRequested, this, &ViewController::frameAll);
    connect(&input, &ViewportInput::frameSelectionRequested, this, &ViewController::frameSelection);
}

QString ViewController::debugView() const {
    return ViewCatalog::viewName(view_);
}

bool ViewController::setDebugView(const QString& name, bool remember) {
    const std::optional<std::uint32_t> id = ViewCatalog::viewId(name);
    if (!id) return false;
    view_ = *id;
    if (remember) settings_.set(setting::kLastView, name);
    retranslate(); // checks the matching menu entry
    frames_.updateStreams();
    return true;
}

void ViewController::setGpuCulling(bool gpu) {
    (gpu ? a_.gpu_path : a_.cpu_path)->setChecked(true);
}

void ViewController::fill(render::FrameRequest& request) const {
    request.view = static_cast<render::DebugView>(view_);
    request.overlays = overlays_;
    request.uv_checker_density = static_cast<float>(settings_.get(setting::kCheckerDensity));
    if (a_.box_colouring->isChecked()) request.overlays |= ViewCatalog::cullBoxesOverlay();
    request.cull = a_.gpu_path->isChecked() ? render::CullPath::Gpu : render::CullPath::Cpu;
    request.cull_method = culling_.method();
    request.cascades = shadow_cascades_;
    request.shadow_pcf_taps = shadow_pcf_taps_;
    if (const auto& frozen = culling_.frozenCamera())
        request.freeze_cull = render::explicit_camera(*frozen);
    apply_display(environment_->display(), request);
}

void ViewController::retranslate() {
    const std::vector<ViewEntry> views = ViewCatalog::views();
    for (std::size_t i = 0; i < views.size(); ++i) {
        a_.view_actions[i]->setText(views[i].label);
        a_.view_actions[i]->setChecked(view_ == views[i].id);
        if (view_ == views[i].id) a_.view_button->setText(tr("View: %1").arg(views[i].label));
    }
    const std::vector<ViewEntry> overlays = ViewCatalog::overlays();
    for (std::size_t i = 0; i < overlays.size(); ++i)
        a_.overlay_actions[i]->setText(overlays[i].label);
    retranslateOverlayButton();
    environment_->retranslate();
}

void ViewController::retranslateOverlayButton() {
    if (!a_.overlay_button) return;
    QStringList on;
    for (QAction* act : a_.overlay_actions)
        if (act->isChecked()) on << act->text().remove(QLatin1Char('&'));
    a_.overlay_button->setText(on.isEmpty() ? tr("Overlays") : tr("Overlays (%1)").arg(on.size()));
    a_.overlay_button->setToolTip(on.isEmpty()
                                      ? tr("Overlays: none shown")
                                      : tr("Overlays: %1").arg(on.join(QStringLiteral(", "))));
}

void ViewController::setupEnvironment() {
    environment_ = new EnvironmentMenu(&window_);
    window_.menuBar()->insertMenu(a_.culling->menuAction(), environment_->environmentMenu());
    a_.view->insertMenu(a_.cameras->menuAction(), environment_->toneMenu());
    connect(environment_, &EnvironmentMenu::environmentChanged, this,
            &ViewController::applyEnvironment);
    connect(environment_, &EnvironmentMenu::displayChanged, this, [this] {
        updateLabLighting();
        viewport_.scheduleFrame();
    });
    // KHR_materials_variants: switched on the render thread, said in the log.
    auto* variants = new VariantMenu(
        context_, [this](VariantMenu::Task t) { frames_.post(std::move(t)); }, &window_);
    window_.menuBar()->insertMenu(a_.culling->menuAction(), variants);
    connect(variants, &VariantMenu::switched, this, [this](const QString& message) {
        docks_.log->append(LogDock::Level::Info, message);
        viewport_.scheduleFrame();
    });
}

// The Lab's lit frames (the shadows family) lit as the viewport is.
void ViewController::updateLabLighting() {
    render::FrameRequest settings;
    apply_display(environment_->display(), settings);
    docks_.lab->runner().setLighting(environment_->choice(), settings);
}

void ViewController::applyEnvironment() {
    updateLabLighting();
    if (!frames_.renderer()) return; // given to the device once it is ready
    const render::EnvironmentChoice choice = environment_->choice();
    // The command line's choice and the device becoming ready both ask: build it once.
    if (environment_posted_ && environment_posted_->kind == choice.kind &&
        environment_posted_->path == choice.path)
        return;
    environment_posted_ = choice;
    const QString name = choice.kind == render::EnvironmentChoice::Kind::None ? tr("none")
                         : choice.kind == render::EnvironmentChoice::Kind::Room
                             ? tr("the room")
                             : QString::fromStdString(choice.path);
    QPointer<ViewController> self(this);
    frames_.post([self, choice, name](GpuViewport& gpu) {
        const QStringList warnings = gpu.scene().setEnvironment(choice);
        QMetaObject::invokeMethod(qApp, [self, warnings, name] {
            if (!self) return;
            for (const QString& w : warnings) self->docks_.log->append(LogDock::Level::Warning, w);
            self->docks_.log->append(LogDock::Level::Info, tr("Environment: %1.").arg(name));
            self->viewport_.scheduleFrame();
        });
    });
}

void ViewController::connectLab() {
    docks_.lab->setMethodInUse([this](const QString& family) {
        // The viewport's maps are kDefaultShadowResolution; with the device's default
        // taps (unknown here) no method is named.
        if (family == QLatin1String("shadows"))
            return shadow_pcf_taps_ == 0
                       ? QString()
                       : QString::fromStdString(lab::shadow_method_name(
                             scene::kDefaultShadowResolution, shadow_cascades_, shadow_pcf_taps_));
        if (family != QLatin1String("culling")) return QString(); // no switch in the viewport
        return culling_in_use(a_.gpu_path->isChecked(), culling_.method());
    });
    connect(docks_.lab, &LabDock::applyRequested, this,
            [this](const QString& family, const QString& method) {
                if (family == QLatin1String("shadows")) {
                    std::uint32_t resolution = 0, cascades = 0, taps = 0;
                    if (!lab::parse_shadow_method(method.toStdString(), resolution, cascades, taps))
                        return;
                    shadow_cascades_ = cascades;
                    shadow_pcf_taps_ = taps;
                    window_.statusBar()->showMessage(
                        tr("Shadows: %1 cascades, %2 PCF taps; the viewport's maps stay "
                           "%3x%3 texels (fixed when its renderer is made), not %4")
                            .arg(cascades)
                            .arg(taps)
                            .arg(scene::kDefaultShadowResolution)
                            .arg(resolution),
                        10000);
                    viewport_.scheduleFrame();
                    return;
                }
                if (family != QLatin1String("culling")) return; // see the dock's tooltip
                const bool gpu = method == QLatin1String("gpu");
                for (std::size_t i = 0; i < kMenuMethods.size(); ++i)
                    if (culling_in_use(gpu, kMenuMethods[i]) == method) {
                        a_.method_actions[i]->trigger();
                        setGpuCulling(gpu);
                    }
            });
}

void ViewController::cameraChanged() {
    culling_.update(viewport_.camera().pose().spec());
    viewport_.scheduleFrame();
}

void ViewController::frameAll() {
    if (context_.scene()) viewport_.camera().frameAuto(*context_.scene());
    cameraChanged();
}

void ViewController::frameSelection() {
    const scene::Scene* scene = context_.scene();
    const int node = context_.selection().current().node;
    if (!scene || node < 0) return;
    core::Aabb box;
    for (const scene::MeshInstance& inst : scene->instances)
        if (static_cast<int>(inst.node_id) == node) box.expand(inst.world_bounds);
    if (!box.valid()) box.expand(glm::vec3(scene->node_world[static_cast<std::size_t>(node)][3]));
    viewport_.camera().frame(box);
    cameraChanged();
}

void ViewController::jumpToCamera(int node) {
    const scene::Scene* scene = context_.scene();
    if (!scene) return;
    viewport_.input().setAutoFrame(false);
    for (std::size_t i = 0; i < scene->placed_cameras.size(); ++i)
        if (static_cast<int>(scene->placed_cameras[i].node) == node) {
            viewport_.camera().jumpTo(*scene, i);
            cameraChanged();
            return;
        }
}

void ViewController::fillCamerasMenu(QMenu& menu) {
    menu.clear();
    const scene::Scene* s = context_.scene();
    if (!s || s->placed_cameras.empty()) {
        menu.addAction(tr("(the scene has no cameras)"))->setEnabled(false);
        return;
    }
    for (std::size_t i = 0; i < s->placed_cameras.size(); ++i) {
        const scene::Camera& c = s->cameras[s->placed_cameras[i].camera];
        const QString name =
            c.name.empty() ? tr("Camera %1").arg(i) : QString::fromStdString(c.name);
        const int node = static_cast<int>(s->placed_cameras[i].node);
        connect(menu.addAction(name), &QAction::triggered, this,
                [this, node] { jumpToCamera(node); });
    }
}

} // namespace sherpa::editor
