// RenderController: the device made at start, scene uploads and stream changes posted
// to the render thread, frames asked for and reported back (status bar, culling dock),
// material readback and the GPU culling check routed there.
#include "render_controller.h"

#include <QAction>
#include <QCoreApplication>
#include <QLabel>
#include <QVulkanInstance>
#include <utility>

#include "acceleration_dock.h"
#include "culling_dock.h"
#include "culling_monitor.h"
#include "editor_context.h"
#include "log_dock.h"
#include "material_dock.h"
#include "texture_dock.h"
#include "viewport_window.h"
#include "window_docks.h"

namespace sherpa::editor {

namespace {
// More than the renderer's frames in flight: the first frame's culling counts are
// read back by then.
constexpr int kPassReadbackFrames = 4;
} // namespace

RenderController::RenderController(EditorContext& context, CullingMonitor& culling,
                                   const WindowDocks& docks, ViewportWindow& viewport,
                                   QLabel& frame_label, QAction& missing_checker, QObject* parent)
    : QObject(parent), context_(context), culling_(culling), docks_(docks), viewport_(viewport),
      frame_label_(frame_label), missing_checker_(missing_checker),
      last_report_(std::make_unique<FrameReport>()) {}

RenderController::~RenderController() {
    render_.reset(); // finishes the frame in flight, frees the engine on its thread
}

void RenderController::setFrameSource(std::function<ViewportRequest()> source) {
    source_ = std::move(source);
}

void RenderController::start(QVulkanInstance* vulkan, bool ray_tracing) {
    ray_tracing_asked_ = ray_tracing;
    if (!vulkan) {
        docks_.log->append(LogDock::Level::Error,
                           tr("No Vulkan instance: the viewport cannot render."));
        return;
    }
    // The device is made on the render thread while the window shows. Loads wait for
    // it (the loader prepares textures for its TextureTarget): a scene asked for
    // meanwhile starts loading when it is known, either way.
    render_ = std::make_unique<RenderThread>([instance = vulkan, rt = ray_tracing](QString& error) {
        return GpuViewport::create(*instance, rt, error);
    });
    connect(render_.get(), &RenderThread::deviceReady, this,
            [this](const tex::TextureTarget& target, const QString& name, double ms, bool rt) {
                docks_.log->append(
                    LogDock::Level::Info,
                    tr("Rendering on %1 (renderer ready in %2 ms).").arg(name).arg(ms, 0, 'f', 1));
                ray_tracing_ = rt;
                Q_EMIT deviceKnown(target, rt);
            });
    connect(render_.get(), &RenderThread::deviceFailed, this, [this](const QString& error) {
        docks_.log->append(LogDock::Level::Error,
                           tr("The renderer could not start: %1").arg(error));
        render_.release()->deleteLater(); // its thread has ended; the signal is still on
        Q_EMIT deviceKnown(std::nullopt, false);
    });
    connect(render_.get(), &RenderThread::frameDone, this, &RenderController::onFrameDone);
    connect(render_.get(), &RenderThread::renderError, this, [this](const QString& e) {
        gpu_failed_ = true;
        docks_.log->append(LogDock::Level::Error, tr("Rendering stopped: %1").arg(e));
    });
    viewport_.setFrameCallback([this] { renderFrame(); });
    // The swapchain must go before its surface (closing the window destroys it).
    connect(&viewport_, &ViewportWindow::surfaceAboutToBeDestroyed, this, [this] {
        if (render_) render_->releaseSurface();
    });
    connectReadbacks();
    connect(&context_, &EditorContext::sceneReady, this, &RenderController::uploadScene);
    // Materials resolve failed textures at upload: upload again (uploadScene reads it).
    connect(&missing_checker_, &QAction::toggled, this, [this] {
        if (render_) uploadScene();
    });
}

void RenderController::connectReadbacks() {
    // Read back on the render thread, shown when it comes (the dock shows the CPU
    // record meanwhile): selecting a material never waits for a frame.
    docks_.material->setReadback([this](int material, MaterialReadbackDone done) {
        if (render_)
            render_->post([this, material, done = std::move(done)](GpuViewport& gpu) {
                std::optional<GpuMaterialReadback> r = gpu.readbacks().readMaterial(material);
                QMetaObject::invokeMethod(this, [done, r] { done(r); });
            });
    });
    // Checked on the render thread between frames, answered later: the GUI thread
    // never waits for the frame in flight. A scene not uploaded yet is not compared.
    culling_.setGpuCheck([this](const scene::Frustum& frustum, scene::CullMethod method,
                                std::vector<std::uint8_t> cpu_visible, GpuCullDone done) {
        if (render_)
            render_->post([this, frustum, method, cpu_visible = std::move(cpu_visible),
                           scene = context_.sharedScene(),
                           done = std::move(done)](GpuViewport& gpu) {
                std::optional<GpuCullResult> result;
                QString failure;
                try {
                    if (gpu.scene().scene() == scene.get())
                        result = gpu.readbacks().checkGpuCulling(frustum, method, cpu_visible);
                } catch (const std::exception& e) {
                    failure = QString::fromUtf8(e.what());
                }
                QMetaObject::invokeMethod(&culling_, [this, done, result, failure] {
                    if (!failure.isEmpty())
                        docks_.log->append(LogDock::Level::Error,
                                           tr("GPU culling failed: %1").arg(failure));
                    done(result);
                });
            });
    });
}

void RenderController::post(RenderThread::Task task) {
    if (render_) render_->post(std::move(task));
}

void RenderController::uploadScene() {
    logTextureMessages();
    pass_frames_left_ = kPassReadbackFrames;
    if (!render_) return;
    const ViewportRequest streams = source_();
    render_->post(
        [this, session = context_.sharedSession(), streams,
         checker = missing_checker_.isChecked()](GpuViewport& gpu) {
            const UploadedScene up = gpu.load(session, streams, checker);
            // Built on upload (ray tracing on): handed over as data, for this session only.
            QMetaObject::invokeMethod(this, [this, up, session] {
                docks_.textures->setGpuBytes(static_cast<std::int64_t>(up.textureBytes));
                if (session != context_.sharedSession()) return;
                docks_.acceleration->setStats(up.acceleration, noAccelerationReason());
                logLightWarnings(session, up.lightWarnings);
            });
        },
        RenderThread::TaskKind::SceneUpload);
    render_->forgetMotion(); // the new scene's first frame at full size
    viewport_.scheduleFrame();
}

QString RenderController::noAccelerationReason() const {
    if (!ray_tracing_asked_)
        return tr("Ray tracing is off (--rt off): no acceleration structures.");
    if (!ray_tracing_) return tr("The device does not ray trace: no acceleration structures.");
    if (!context_.scene()) return tr("No scene.");
    return tr("The scene has no triangles: no acceleration structures.");
}

void RenderController::logTextureMessages() {
    const SceneSession* session = context_.session();
    const PreparedTextures prepared = session ? session->textures : nullptr;
    // uploadScene() runs again for the same set (settings toggles): say it once.
    if (!prepared || prepared == logged_textures_.lock()) return;
    logged_textures_ = prepared;
    for (const std::string& w : prepared->warnings)
        docks_.log->append(LogDock::Level::Warning, QString::fromStdString(w));
    for (const std::string& n : prepared->notices)
        docks_.log->append(LogDock::Level::Info, QString::fromStdString(n));
}

void RenderController::logLightWarnings(const SharedSession& session,
                                        const std::vector<std::string>& warnings) {
    // Every upload of the session makes the same list (settings toggles): say it once.
    if (session == logged_lights_.lock()) return;
    logged_lights_ = session;
    for (const std::string& w : warnings)
        docks_.log->append(LogDock::Level::Warning, QString::fromStdString(w));
}

void RenderController::updateStreams() {
    if (render_)
        render_->post([frame = source_()](GpuViewport& gpu) { gpu.scene().useStreamsFor(frame); });
    viewport_.scheduleFrame();
}

void RenderController::renderFrame() {
    if (!render_ || gpu_failed_) return;
    last_frame_ = source_();
    // Handed over, not waited for: a newer request replaces it if not started yet.
    render_->requestFrame(last_frame_, viewport_.vulkanSurface());
}

bool RenderController::renderNow() {
    if (!render_ || gpu_failed_ || !viewport_.isExposed()) return false;
    // Drawn now at full size (not a reduced or earlier frame), and on screen.
    last_frame_ = source_();
    render_->renderAndWait(last_frame_, viewport_.vulkanSurface());
    // What the render thread posted back (texture bytes, frame times, passes) shows
    // too, and the columns refitted for it (a zero-time timer each: a few rounds).
    for (int round = 0; round < 3; ++round)
        QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
    return true;
}

void RenderController::onFrameDone(const FrameReport& report) {
    Q_EMIT frameReported(report); // the comparison's refusal and difference numbers
    if (!report.refused.isEmpty()) return;
    // Skipped because the swapchain was out of date and has just been recreated:
    // draw again at the new size, or the last size change would never show.
    if (!report.shown) {
        viewport_.scheduleFrame();
        return;
    }
    *last_report_ = report;
    frame_times_.add(report.ms);
    // The first frame makes the pipelines: shown as such, not as a frame rate.
    QString text = frame_times_.count() == 0
                       ? tr("first frame %1 ms (makes the pipelines)").arg(report.ms, 0, 'f', 1)
                       : tr("%1 fps, %2 ms per frame")
                             .arg(frame_times_.fps(), 0, 'f', 1)
                             .arg(frame_times_.meanMs(), 0, 'f', 1);
    if (report.gpu_ms >= 0.0) text += tr(" (GPU %1 ms)").arg(report.gpu_ms, 0, 'f', 1);
    text += tr(", resolution %1%").arg(qRound(report.scale * 100.0f));
    if (report.path_samples > 0) {
        text += tr(", path traced %1 spp").arg(report.path_samples);
        if (report.path_error >= 0.0)
            text += tr(", estimated error %1%").arg(100.0 * report.path_error, 0, 'f', 2);
    }
    frame_label_.setText(text);
    frame_label_.setToolTip(
        tr("Mean of the last %1 frames, not counting the renderer's first (pipeline "
           "creation). While the camera moves or an animation plays on a slow device, frames "
           "are drawn at a lower resolution and without shadows to keep %2 fps; at rest or "
           "paused the full frame follows.")
            .arg(frame_times_.count())
            .arg(kGoalFps));
    viewport_.frameDrawn();
    if (report.cull_passes)
        docks_.culling->setRendererPasses(report.passes, report.cached_shadows);
    else if (context_.scene() && pass_frames_left_ > 0) {
        // The renderer reads a frame's culling counts back when it reuses that
        // frame's slot: draw the few frames that takes now, or the pass table
        // says "no frame yet" until the camera first moves.
        --pass_frames_left_;
        viewport_.scheduleFrame();
    }
    if (!first_frame_seen_ && context_.scene()) { // a frame that shows the scene
        first_frame_seen_ = true;
        Q_EMIT firstFrame();
    }
}

} // namespace sherpa::editor
