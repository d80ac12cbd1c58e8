#include "render_thread.h"

#include <chrono>

namespace sherpa::editor {

namespace {

// The camera and the frame's size (the orbit camera's aspect follows the size; the
// request leaves the aspect to the viewport).
bool same_camera(const gpu::FrameRequest& a, const gpu::FrameRequest& b) {
    return a.camera.eye == b.camera.eye && a.camera.target == b.camera.target &&
           a.camera.up == b.camera.up && a.camera.fov_degrees == b.camera.fov_degrees &&
           a.camera.aspect == b.camera.aspect && a.width == b.width && a.height == b.height;
}

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

RenderThread::RenderThread(DeviceFactory make, QObject* parent)
    : QObject(parent), make_(std::move(make)) {
    thread_ = std::thread([this] { run(); });
}

RenderThread::~RenderThread() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

std::uint64_t RenderThread::latestRequest() const {
    std::lock_guard lock(mutex_);
    return serial_;
}

std::uint64_t RenderThread::requestFrame(const ViewportRequest& frame, std::uint64_t surface) {
    std::uint64_t serial = 0;
    {
        std::lock_guard lock(mutex_);
        serial = ++serial_;
        pending_ = Request{frame, surface, serial}; // an older request not yet started goes
    }
    wake_.notify_all();
    return serial;
}

void RenderThread::post(Task task, TaskKind kind) {
    std::deque<Queued> superseded; // destroyed outside the lock: they may hold a scene
    {
        std::lock_guard lock(mutex_);
        if (failed_) return; // a call() waiting on it throws (broken promise)
        if (kind == TaskKind::SceneUpload) {
            const auto upload = [](const Queued& q) { return q.kind == TaskKind::SceneUpload; };
            for (Queued& q : tasks_)
                if (upload(q)) superseded.push_back(std::move(q));
            std::erase_if(tasks_, upload);
        }
        tasks_.push_back({std::move(task), kind});
    }
    wake_.notify_all();
}

void RenderThread::forgetMotion() {
    std::lock_guard lock(mutex_);
    last_.reset(); // no camera to compare with: still
    refine_ = false;
}

void RenderThread::setInteractiveScaling(bool on) {
    std::lock_guard lock(mutex_);
    scaling_ = on;
}

void RenderThread::setTargetFrameMs(double ms) {
    std::lock_guard lock(mutex_);
    target_ms_ = ms;
}

bool RenderThread::renderAndWait(const ViewportRequest& frame, std::uint64_t surface) {
    std::uint64_t serial = 0;
    {
        std::lock_guard lock(mutex_);
        if (failed_) return false;
        serial = ++serial_;
        pending_.reset(); // this one is newer
        refine_ = false;
    }
    const Request request{frame, surface, serial};
    return call([this, request](GpuViewport& gpu) {
        draw(gpu, request, true);
        gpu.finish();
        return true;
    });
}

void RenderThread::releaseSurface() {
    {
        std::lock_guard lock(mutex_);
        pending_.reset();
        last_.reset();
        refine_ = false;
        if (failed_) return; // no swapchain was ever made
    }
    call([](GpuViewport& gpu) { gpu.presenter().releaseSurface(); });
}

bool RenderThread::makeDevice() {
    const auto start = std::chrono::steady_clock::now();
    QString error;
    try {
        gpu_ = make_(error);
    } catch (const std::exception& e) {
        error = QString::fromUtf8(e.what());
    }
    if (!gpu_) {
        {
            std::lock_guard lock(mutex_);
            failed_ = true;
            tasks_.clear();
            pending_.reset();
        }
        QMetaObject::invokeMethod(this, [this, error] { Q_EMIT deviceFailed(error); });
        return false;
    }
    QMetaObject::invokeMethod(
        this,
        [this, target = gpu_->textureTarget(), name = gpu_->deviceName(), ms = ms_since(start),
         rt = gpu_->rayTracing()] { Q_EMIT deviceReady(target, name, ms, rt); });
    return true;
}

void RenderThread::run() {
    if (!makeDevice()) return;
    GpuViewport& gpu = *gpu_;
    std::unique_lock lock(mutex_);
    while (true) {
        const auto woken = [this] { return stop_ || !tasks_.empty() || pending_.has_value(); };
        bool rested = false;
        // Accumulating path-traced samples: the next frame right away unless a request
        // comes (the camera moves) first.
        if (refine_ && !woken())
            rested = !wake_.wait_for(lock, std::chrono::milliseconds(accumulating_ ? 0 : kRestMs),
                                     woken);
        else
            wake_.wait(lock, woken);
        if (stop_) break;
        if (!tasks_.empty()) { // before frames: a frame may depend on them (uploads)
            Task task = std::move(tasks_.front().task);
            tasks_.pop_front();
            lock.unlock();
            try {
                task(gpu);
            } catch (const std::exception& e) {
                Q_EMIT renderError(QString::fromUtf8(e.what()));
            }
            task = nullptr;
            lock.lock();
            continue;
        }
        Request request;
        bool still = true;
        if (pending_) {
            request = *pending_;
            pending_.reset();
            // Moving: the camera changed since the last frame drawn, or the pose did
            // (a playing animation is motion too: the timeline makes a new pose per
            // step, and the same one while paused).
            still = !last_ || (same_camera(last_->frame.request, request.frame.request) &&
                               last_->frame.request.pose == request.frame.request.pose);
        } else if (rested && last_) {
            request = *last_; // the camera rests: the same frame at full size
        } else {
            refine_ = false;
            continue;
        }
        lock.unlock();
        draw(gpu, request, still);
        lock.lock();
    }
    lock.unlock();
    gpu_.reset(); // the engine goes on the thread that used it
}

// Draws on the render thread; `still`: at full size whatever the interactive scale.
void RenderThread::draw(GpuViewport& gpu, const Request& request, bool still) {
    float scale = 1.0f;
    {
        std::lock_guard lock(mutex_);
        if (!still && scaling_) scale = scale_;
    }
    FrameReport report;
    report.request = request.serial;
    report.scale = scale;
    report.width = request.frame.request.width;
    report.height = request.frame.request.height;
    const auto start = std::chrono::steady_clock::now();
    try {
        static_cast<PresentOutcome&>(report) =
            gpu.presenter().present(request.surface, request.frame, scale);
    } catch (const std::exception& e) {
        Q_EMIT renderError(QString::fromUtf8(e.what()));
        std::lock_guard lock(mutex_);
        last_.reset();
        refine_ = false;
        return;
    }
    report.ms = ms_since(start);
    {
        std::lock_guard lock(mutex_);
        // The completed frame's GPU time belongs to the present kFramesInFlight back.
        drawn_scales_.push_back(scale);
        while (drawn_scales_.size() > ViewportPresenter::kFramesInFlight + 1)
            drawn_scales_.pop_front();
        double cost = report.ms;
        if (report.gpu_ms > 0.0 && drawn_scales_.size() > ViewportPresenter::kFramesInFlight) {
            const float then = drawn_scales_.front();
            cost = std::max(cost, report.gpu_ms * double(scale * scale) / double(then * then));
        }
        // Every frame informs the next moving frame's scale: a still frame too says
        // what full size costs.
        if (report.shown) scale_ = next_resolution_scale(scale, cost, target_ms_);
        last_ = request;
        // A path-traced still frame goes on accumulating until kPathSamples.
        accumulating_ = report.shown && scale >= 1.0f && report.path_traced &&
                        report.path_samples < ViewportPresenter::kPathSamples;
        refine_ = report.shown && (scale < 1.0f || accumulating_);
    }
    Q_EMIT frameDone(report);
}

} // namespace sherpa::editor
