#pragma once
// The window's frames: the render thread (device made at start), scene uploads and
// stream changes posted to it, each frame asked for and reported back (status bar,
// culling dock, texture and acceleration docks), material readback and the GPU
// culling check routed there. What a frame shows comes from the frame source the
// window assembles from its controllers (view, selection, motion, comparison).
#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

#include <sherpa/texture/texture_target.h>

#include "gpu_viewport.h"
#include "render_thread.h"
#include "resolution_scale.h"

class QAction;
class QLabel;
class QVulkanInstance;

namespace sherpa::editor {

class CullingMonitor;
class EditorContext;
class ViewportWindow;
struct WindowDocks;

class RenderController : public QObject {
    Q_OBJECT
public:
    // `frame_label`: the status bar's frame rate; `missing_checker`: View › Missing
    // Textures as Checker (a toggle uploads the scene again).
    RenderController(EditorContext& context, CullingMonitor& culling, const WindowDocks& docks,
                     ViewportWindow& viewport, QLabel& frame_label, QAction& missing_checker,
                     QObject* parent);
    ~RenderController() override;

    // Starts the render thread, which makes the device while the window shows
    // (deviceKnown says how it went). `vulkan` null: nothing is drawn, and says why.
    // `ray_tracing` (--rt on|off): ray trace where the device can.
    void start(QVulkanInstance* vulkan, bool ray_tracing);
    // What the viewport should show now (size, camera, view, selection...).
    void setFrameSource(std::function<ViewportRequest()> source);
    // The thread that owns the engine and draws; null without a usable Vulkan device.
    RenderThread* renderer() const { return render_.get(); }
    // The renderer ray traces (device support and --rt on); false until the device is known.
    bool rayTracing() const { return ray_tracing_; }
    // The settings of the last frame handed to the renderer, and the last frame the
    // render thread drew (size, scale, timings).
    const ViewportRequest& lastFrame() const { return last_frame_; }
    const FrameReport& lastReport() const { return *last_report_; }
    // Runs `task` on the render thread before the next frame (dropped without a device).
    void post(RenderThread::Task task);
    // The view's streams on the GPU (a re-upload when a view needs more), before the
    // next frame.
    void updateStreams();
    // Draws the current frame at full size now and waits until it is on screen; false
    // when nothing could be drawn (no device, a failed frame, the viewport hidden).
    bool renderNow();

Q_SIGNALS:
    // The device is made (`target`: what textures are prepared for) or could not be
    // (nullopt); `ray_tracing`: its renderer ray traces.
    void deviceKnown(const std::optional<sherpa::tex::TextureTarget>& target, bool ray_tracing);
    // Every frame the render thread reports (refused ones and comparisons included).
    void frameReported(const sherpa::editor::FrameReport& report);
    void firstFrame(); // the first frame drawn with a scene loaded

private:
    void connectReadbacks();
    void uploadScene();
    void renderFrame();
    void onFrameDone(const FrameReport& report);
    // Why the acceleration dock has no structures (--rt off, device, scene).
    QString noAccelerationReason() const;
    // The uploaded textures' warnings (missing, undecodable...) and notices, once per set.
    void logTextureMessages();
    // The path tracer's light-list warnings of an upload, logged once per session.
    void logLightWarnings(const SharedSession& session, const std::vector<std::string>& warnings);

    EditorContext& context_;
    CullingMonitor& culling_;
    const WindowDocks& docks_;
    ViewportWindow& viewport_;
    QLabel& frame_label_;
    QAction& missing_checker_;
    std::function<ViewportRequest()> source_;
    std::unique_ptr<RenderThread> render_; // null without a usable Vulkan device
    bool ray_tracing_asked_ = true;        // --rt on|off
    bool ray_tracing_ = false;             // the device's renderer ray traces
    bool gpu_failed_ = false;              // a frame threw: stop drawing, say so once
    std::weak_ptr<const tex::PreparedTextureSet> logged_textures_; // logTextureMessages()
    std::weak_ptr<const SceneSession> logged_lights_;              // logLightWarnings()
    std::unique_ptr<FrameReport> last_report_;
    FrameTimes frame_times_;
    bool first_frame_seen_ = false;
    int pass_frames_left_ = 0; // extra frames until the pass table has the first frame
    ViewportRequest last_frame_;
};

} // namespace sherpa::editor
