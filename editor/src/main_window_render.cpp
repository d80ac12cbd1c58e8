// MainWindow and its render thread: the device made at start, scene uploads and
// stream changes posted to the thread, frames asked for and reported back (status
// bar, culling dock), material readback and the GPU culling check routed there.
#include "environment_menu.h"
#include "main_window.h"
#include "main_window_actions.h"

#include <QElapsedTimer>
#include <QLabel>
#include <utility>

#include "acceleration_dock.h"
#include "compare_controls.h"
#include "culling_dock.h"
#include "culling_monitor.h"
#include "difference_legend.h"
#include "gpu_viewport.h"
#include "log_dock.h"
#include "material_dock.h"
#include "motion_playback.h"
#include "render_thread.h"
#include "texture_dock.h"
#include "timeline_dock.h"
#include "view_catalog.h"
#include "viewport_window.h"

namespace sherpa::editor {

namespace {
// More than the renderer's frames in flight: the first frame's culling counts are
// read back by then.
constexpr int kPassReadbackFrames = 4;
} // namespace

void MainWindow::createRenderer() {
    if (!vulkan_) {
        log_->append(LogDock::Level::Error, tr("No Vulkan instance: the viewport cannot render."));
        return;
    }
    // The device is made on the render thread while the window shows. openScene()
    // waits for it (the loader prepares textures for its TextureTarget): a scene asked
    // for meanwhile starts loading when it is known, either way.
    device_pending_ = true;
    render_ = std::make_unique<RenderThread>(
        [instance = vulkan_, rt = ray_tracing_asked_](QString& error) {
            return GpuViewport::create(*instance, rt, error);
        });
    connect(render_.get(), &RenderThread::deviceReady, this,
            [this](const tex::TextureTarget& target, const QString& name, double ms, bool rt) {
                log_->append(
                    LogDock::Level::Info,
                    tr("Rendering on %1 (renderer ready in %2 ms).").arg(name).arg(ms, 0, 'f', 1));
                texture_target_ = target;
                ray_tracing_ = rt;
                compare_->setRayTracing(rt);
                applyEnvironment();
                deviceKnown();
            });
    connect(render_.get(), &RenderThread::deviceFailed, this, [this](const QString& error) {
        log_->append(LogDock::Level::Error, tr("The renderer could not start: %1").arg(error));
        render_.release()->deleteLater(); // its thread has ended; the signal is still on
        deviceKnown();
    });
    connect(render_.get(), &RenderThread::frameDone, this, &MainWindow::onFrameDone);
    connect(render_.get(), &RenderThread::renderError, this, [this](const QString& e) {
        gpu_failed_ = true;
        log_->append(LogDock::Level::Error, tr("Rendering stopped: %1").arg(e));
    });
    viewport_->setFrameCallback([this] { renderFrame(); });
    // The swapchain must go before its surface (closing the window destroys it).
    connect(viewport_, &ViewportWindow::surfaceAboutToBeDestroyed, this, [this] {
        if (render_) render_->releaseSurface();
    });
    // Read back on the render thread, shown when it comes (the dock shows the CPU
    // record meanwhile): selecting a material never waits for a frame.
    material_->setReadback([this](int material, MaterialReadbackDone done) {
        if (render_)
            render_->post([this, material, done = std::move(done)](GpuViewport& gpu) {
                std::optional<GpuMaterialReadback> r = gpu.readMaterial(material);
                QMetaObject::invokeMethod(this, [done, r] { done(r); });
            });
    });
    // Checked on the render thread between frames, answered later: the GUI thread
    // never waits for the frame in flight. A scene not uploaded yet is not compared.
    culling_->setGpuCheck([this](const Frustum& frustum, CullMethod method,
                                 std::vector<std::uint8_t> cpu_visible, GpuCullDone done) {
        if (render_)
            render_->post([this, frustum, method, cpu_visible = std::move(cpu_visible),
                           scene = context_.sharedScene(),
                           done = std::move(done)](GpuViewport& gpu) {
                std::optional<GpuCullResult> result;
                QString failure;
                try {
                    GpuViewport::GpuCullCheck check;
                    if (gpu.scene() == scene.get() &&
                        gpu.checkGpuCulling(frustum, method, cpu_visible, check))
                        result =
                            GpuCullResult{check.gpu_ms, static_cast<std::int64_t>(check.visible),
                                          static_cast<std::int64_t>(check.differences)};
                } catch (const std::exception& e) {
                    failure = QString::fromUtf8(e.what());
                }
                QMetaObject::invokeMethod(culling_, [this, done, result, failure] {
                    if (!failure.isEmpty())
                        log_->append(LogDock::Level::Error,
                                     tr("GPU culling failed: %1").arg(failure));
                    done(result);
                });
            });
    });
    connect(&context_, &EditorContext::sceneReady, this, &MainWindow::uploadScene);
}

void MainWindow::deviceKnown() {
    device_pending_ = false;
    if (!pending_open_.isEmpty()) openScene(std::exchange(pending_open_, QString()));
}

void MainWindow::uploadScene() {
    logTextureMessages();
    pass_frames_left_ = kPassReadbackFrames;
    if (!render_) return;
    const ViewportFrame streams = currentFrame();
    render_->post(
        [this, session = context_.sharedSession(), streams,
         checker = a_->missing_checker->isChecked()](GpuViewport& gpu) {
            gpu.setSession(nullptr); // so that the stream policy costs no upload
            gpu.setMissingTexturesChecker(checker);
            gpu.useStreamsFor(streams);
            gpu.setSession(session);
            const auto bytes = static_cast<std::int64_t>(gpu.textureBytes());
            // Built on upload (ray tracing on): handed over as data, for this session only.
            QMetaObject::invokeMethod(
                this, [this, bytes, session, stats = gpu.accelerationStats()] {
                    textures_->setGpuBytes(bytes);
                    if (session == context_.sharedSession())
                        acceleration_->setStats(stats, noAccelerationReason());
                });
        },
        RenderThread::TaskKind::SceneUpload);
    render_->forgetMotion(); // the new scene's first frame at full size
    viewport_->scheduleFrame();
}

QString MainWindow::noAccelerationReason() const {
    if (!ray_tracing_asked_)
        return tr("Ray tracing is off (--rt off): no acceleration structures.");
    if (!ray_tracing_) return tr("The device does not ray trace: no acceleration structures.");
    if (!context_.scene()) return tr("No scene.");
    return tr("The scene has no triangles: no acceleration structures.");
}

void MainWindow::updateStreams() {
    if (render_)
        render_->post([frame = currentFrame()](GpuViewport& gpu) { gpu.useStreamsFor(frame); });
    viewport_->scheduleFrame();
}

ViewportFrame MainWindow::currentFrame() const {
    ViewportFrame frame;
    const QSize pixels = viewport_->pixelSize();
    frame.width = static_cast<std::uint32_t>(pixels.width());
    frame.height = static_cast<std::uint32_t>(pixels.height());
    frame.camera = viewport_->camera().spec();
    frame.view = view_;
    frame.overlays = overlays_;
    frame.checkerDensity = static_cast<float>(settings_.checkerDensity());
    if (a_->box_colouring->isChecked()) frame.overlays |= ViewCatalog::cullBoxesOverlay();
    frame.gpuCulling = a_->gpu_path->isChecked();
    frame.cullMethod = culling_->method();
    frame.shadowCascades = shadow_cascades_;
    frame.shadowPcfTaps = shadow_pcf_taps_;
    if (culling_->frozen()) frame.frozenCulling = culling_->cullingCamera();
    frame.compare = compare_->state();
    frame.compareSession = compare_session_;
    frame.display = environment_->display();
    const Selection& sel = context_.selection();
    frame.pose = timeline_->pose();
    frame.hiddenNodes = context_.hiddenNodes();
    if (const Scene* scene = context_.scene();
        scene && sel.node >= 0 && is_joint(*scene, static_cast<std::uint32_t>(sel.node)))
        frame.selectedJoint = static_cast<std::uint32_t>(sel.node);
    frame.outlineInstances = outlinedInstances();
    if (const int instance = selectedInstance(); instance >= 0) {
        frame.highlightInstance = static_cast<std::uint32_t>(instance);
        if (sel.triangle >= 0) frame.highlightTriangle = static_cast<std::uint32_t>(sel.triangle);
        if (sel.vertex >= 0) frame.highlightVertex = static_cast<std::uint32_t>(sel.vertex);
    }
    return frame;
}

void MainWindow::renderFrame() {
    if (!render_ || gpu_failed_) return;
    last_frame_ = currentFrame();
    // Handed over, not waited for: a newer request replaces it if not started yet.
    render_->requestFrame(last_frame_, viewport_->vulkanSurface());
}

void MainWindow::onFrameDone(const FrameReport& report) {
    if (!report.refused.isEmpty()) {
        onRefused(report.refused);
        return;
    }
    if (report.difference.valid) legend_->setNumbers(report.difference);
    // Skipped because the swapchain was out of date and has just been recreated:
    // draw again at the new size, or the last size change would never show.
    if (!report.shown) {
        viewport_->scheduleFrame();
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
    frame_label_->setText(text);
    frame_label_->setToolTip(
        tr("Mean of the last %1 frames, not counting the renderer's first (pipeline "
           "creation). While the camera moves or an animation plays on a slow device, frames "
           "are drawn at a lower resolution and without shadows to keep %2 fps; at rest or "
           "paused the full frame follows.")
            .arg(frame_times_.count())
            .arg(kGoalFps));
    viewport_->frameDrawn();
    if (report.cull_passes)
        culling_dock_->setRendererPasses(report.passes, report.cached_shadows);
    else if (context_.scene() && pass_frames_left_ > 0) {
        // The renderer reads a frame's culling counts back when it reuses that
        // frame's slot: draw the few frames that takes now, or the pass table
        // says "no frame yet" until the camera first moves.
        --pass_frames_left_;
        viewport_->scheduleFrame();
    }
    if (!first_frame_seen_ && context_.scene()) { // a frame that shows the scene
        first_frame_seen_ = true;
        Q_EMIT firstFrame();
    }
}

} // namespace sherpa::editor
