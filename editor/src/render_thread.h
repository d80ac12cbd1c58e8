#pragma once
// Frames off the GUI thread. One thread owns the engine side of the viewport
// (GpuViewport: device, queue, renderer, swapchain) and is the only thread that
// calls it. The GUI thread hands it the latest frame it wants (a newer request
// replaces one not yet started, so camera input coalesces to its latest state)
// and tasks (upload a scene, read a material back); results come back as queued
// signals. Nothing on the GUI thread waits for a frame in flight except call()
// (tests, screenshots, the window's surface going away).
#include <QMetaType>
#include <QObject>
#include <QString>

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "frame_pacing.h"
#include "gpu_viewport.h"

namespace sherpa::editor {

// One frame as the render thread drew it: what ViewportPresenter::present() said, and the
// request it drew.
struct FrameReport : PresentOutcome {
    std::uint64_t request = 0;           // the requestFrame() it drew (1, 2, ...)
    double ms = 0.0;                     // present() on the render thread, wall clock
    float scale = 1.0f;                  // each side drawn at this fraction
    std::uint32_t width = 0, height = 0; // the full (viewport) size in pixels
};

class RenderThread : public QObject {
    Q_OBJECT
public:
    using Task = std::function<void(GpuViewport&)>;
    // Makes the engine side (device, renderer); null with `error` set when it cannot.
    using DeviceFactory = std::function<std::unique_ptr<GpuViewport>(QString& error)>;
    // Starts the thread, which first makes the device with `make` (so that the window
    // shows meanwhile) and owns it from then on. Tasks and frames asked for before
    // the device exists wait for it; deviceReady or deviceFailed says how it went.
    explicit RenderThread(DeviceFactory make, QObject* parent = nullptr);
    ~RenderThread() override; // finishes the frame in flight; frees the engine there

    // The frame to draw next on `surface`; replaces a request not yet started. A
    // frame whose camera or pose differs from the last one drawn is "moving" (orbiting,
    // a playing animation): drawn at the interactive resolution scale; once no new
    // request comes for FramePacing::kRestMs (the camera rests, playback pauses), the
    // last frame is drawn again at full size (the still image is always full size).
    std::uint64_t requestFrame(const ViewportRequest& frame, std::uint64_t surface);
    // The serial of the latest request (requestFrame(), renderAndWait()); 0 before
    // any. A FrameReport::request at or above it drew a frame asked for since.
    std::uint64_t latestRequest() const;
    // What a posted task is: a scene upload replaces one not yet started, which goes
    // with the whole scene it holds. Switching scenes faster than the device draws
    // (lavapipe compiling shaders for a new scene takes seconds) then keeps one scene
    // waiting, not every scene switched through.
    enum class TaskKind { Once, SceneUpload };
    // Runs `task` on the render thread before the next frame, in order of posting
    // (dropped when the device could not be made).
    void post(Task task, TaskKind kind = TaskKind::Once);
    // Runs `task` there and waits for its result (so for the frame in flight too);
    // throws std::future_error when the device could not be made.
    template <class F> auto call(F task) -> decltype(task(std::declval<GpuViewport&>()));
    // Draws `frame` at full size now and waits until it is presented and the queue
    // is idle (screenshots read the window right after).
    bool renderAndWait(const ViewportRequest& frame, std::uint64_t surface);
    // Drops the swapchain and any request for it, and waits (the surface is going).
    void releaseSurface();
    // The next frame is still (full size) whatever its camera: a new scene's framing
    // is a jump, not motion.
    void forgetMotion();
    // How moving frames are paced: reduced resolution or not (off draws every frame at
    // full size), and the frame time they aim at (kTargetFrameMs: 36 fps, for a 30 fps
    // goal).
    void setPacing(const PacingOptions& options);

Q_SIGNALS:
    // The device exists (GUI thread): what the loader prepares textures for, its
    // name and how long making it took.
    // `ray_tracing`: the renderer ray traces (acceleration structures built on upload).
    void deviceReady(const sherpa::tex::TextureTarget& textures, const QString& name, double ms,
                     bool ray_tracing);
    // It could not be made: nothing will be drawn, posted tasks are dropped.
    void deviceFailed(const QString& error);
    void frameDone(const sherpa::editor::FrameReport& report);
    void renderError(const QString& error);

private:
    bool makeDevice(); // on thread_, first
    void run();
    void draw(GpuViewport& gpu, const FrameOrder& order, bool still);

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    struct Queued {
        Task task;
        TaskKind kind = TaskKind::Once;
    };
    std::deque<Queued> tasks_;
    std::optional<FrameOrder> pending_;
    FramePacing pacing_; // which frame next, at what size
    bool stop_ = false;
    bool failed_ = false; // no device: tasks are dropped
    std::uint64_t serial_ = 0;
    DeviceFactory make_;
    std::unique_ptr<GpuViewport> gpu_; // made and used on thread_ only
    std::thread thread_;
};

template <class F> auto RenderThread::call(F task) -> decltype(task(std::declval<GpuViewport&>())) {
    using R = decltype(task(std::declval<GpuViewport&>()));
    auto promise = std::make_shared<std::promise<R>>();
    std::future<R> result = promise->get_future();
    post([promise, task = std::move(task)](GpuViewport& gpu) mutable {
        try {
            if constexpr (std::is_void_v<R>) {
                task(gpu);
                promise->set_value();
            } else {
                promise->set_value(task(gpu));
            }
        } catch (...) {
            promise->set_exception(std::current_exception());
        }
    });
    return result.get();
}

} // namespace sherpa::editor

Q_DECLARE_METATYPE(sherpa::editor::FrameReport)
