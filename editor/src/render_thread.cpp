#include "render_thread.h"

#include <chrono>

namespace sherpa::editor {

namespace {

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
        pending_ = FrameOrder{frame, surface, serial}; // an older request not yet started goes
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
    pacing_.forget(); // no camera to compare with: still
}

void RenderThread::setPacing(const PacingOptions& options) {
    std::lock_guard lock(mutex_);
    pacing_.setOptions(options);
}

bool RenderThread::renderAndWait(const ViewportRequest& frame, std::uint64_t surface) {
    std::uint64_t serial = 0;
    {
        std::lock_guard lock(mutex_);
        if (failed_) return false;
        serial = ++serial_;
        pending_.reset(); // this one is newer
        pacing_.stopRefining();
    }
    const FrameOrder order{frame, surface, serial};
    return call([this, order](GpuViewport& gpu) {
        draw(gpu, order, true);
        gpu.finish();
        return true;
    });
}

void RenderThread::releaseSurface() {
    {
        std::lock_guard lock(mutex_);
        pending_.reset();
        pacing_.forget();
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
        // A frame to refine: drawn again unless a request comes (the camera moves) first.
        if (const auto rest = pacing_.restWait(); rest && !woken())
            rested = !wake_.wait_for(lock, *rest, woken);
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
        FrameOrder order;
        bool still = true;
        if (pending_) {
            order = std::move(*pending_);
            pending_.reset();
            still = pacing_.still(order);
        } else if (rested && pacing_.again()) {
            order = *pacing_.again(); // the camera rests: the same frame at full size
        } else {
            pacing_.stopRefining();
            continue;
        }
        lock.unlock();
        draw(gpu, order, still);
        lock.lock();
    }
    lock.unlock();
    gpu_.reset(); // the engine goes on the thread that used it
}

// Draws on the render thread; `still`: at full size whatever the interactive scale.
void RenderThread::draw(GpuViewport& gpu, const FrameOrder& order, bool still) {
    float scale = 1.0f;
    {
        std::lock_guard lock(mutex_);
        scale = pacing_.scale(still);
    }
    FrameReport report;
    report.request = order.serial;
    report.scale = scale;
    report.width = order.frame.request.width;
    report.height = order.frame.request.height;
    const auto start = std::chrono::steady_clock::now();
    try {
        static_cast<PresentOutcome&>(report) =
            gpu.presenter().present(order.surface, order.frame, scale);
    } catch (const std::exception& e) {
        Q_EMIT renderError(QString::fromUtf8(e.what()));
        std::lock_guard lock(mutex_);
        pacing_.forget();
        return;
    }
    report.ms = ms_since(start);
    {
        std::lock_guard lock(mutex_);
        pacing_.drawn(order, scale, report, report.ms);
    }
    Q_EMIT frameDone(report);
}

} // namespace sherpa::editor
