#pragma once
// The viewport: a QWindow with a Vulkan surface (QVulkanInstance::surfaceForWindow),
// embedded with QWidget::createWindowContainer. The engine owns device and
// swapchain; this window owns the camera, and asks for a frame only when something
// changed (requestUpdate), so an idle editor renders nothing. Its input (ViewportInput:
// mouse and keys to camera actions) and the split view's divider (SplitDivider) filter
// its events.
#include <QWindow>

#include <functional>

#include "orbit_camera.h"
#include "split_divider.h"
#include "viewport_input.h"

class QVulkanInstance;

namespace sherpa::editor {

class ViewportWindow : public QWindow {
    Q_OBJECT
public:
    explicit ViewportWindow(QVulkanInstance* instance);
    ~ViewportWindow() override;

    OrbitCamera& camera() { return camera_; }
    const OrbitCamera& camera() const { return camera_; }
    // What moves the camera (its signals: cameraChanged, clicked, frame requests).
    ViewportInput& input() { return *input_; }
    // The split view's divider (none unless the comparison splits the view).
    SplitDivider& divider() { return *divider_; }
    // The surface for the engine's swapchain; VK_NULL_HANDLE until the window exists.
    quint64 vulkanSurface() const;
    QSize pixelSize() const { return size() * devicePixelRatio(); }
    // Called for each paced frame while exposed: asks for a frame (drawn elsewhere,
    // reported back with frameDrawn()).
    void setFrameCallback(std::function<void()> callback) { frame_ = std::move(callback); }
    // Something visible changed: render once more (coalesced by Qt to the refresh rate).
    void scheduleFrame();
    // A frame asked for has been presented (counted: framesRendered()).
    void frameDrawn() { ++frames_; }
    std::uint64_t framesRendered() const { return frames_; }
    // Asks for a frame now, not at the next paced update.
    void renderNow();

Q_SIGNALS:
    // The native window (and with it the Vulkan surface) is about to go: whoever
    // presents to it must drop its swapchain now.
    void surfaceAboutToBeDestroyed();

protected:
    bool event(QEvent* e) override;
    void exposeEvent(QExposeEvent* e) override;

private:
    OrbitCamera camera_;
    ViewportInput* input_;  // child: filters the window's events
    SplitDivider* divider_; // child, installed after input_: sees a drag first
    std::function<void()> frame_;
    std::uint64_t frames_ = 0;
};

} // namespace sherpa::editor
