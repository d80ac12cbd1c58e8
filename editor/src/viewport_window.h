#pragma once
// The viewport: a QWindow with a Vulkan surface (QVulkanInstance::surfaceForWindow),
// embedded with QWidget::createWindowContainer. The engine owns device and
// swapchain; this window owns the camera and input, and asks for a frame only
// when something changed (requestUpdate), so an idle editor renders nothing.
#include <QElapsedTimer>
#include <QSet>
#include <QTimer>
#include <QWindow>

#include <functional>
#include <optional>

#include "orbit_camera.h"

class QVulkanInstance;

namespace sherpa::editor {

class ViewportWindow : public QWindow {
    Q_OBJECT
public:
    explicit ViewportWindow(QVulkanInstance* instance);

    OrbitCamera& camera() { return camera_; }
    const OrbitCamera& camera() const { return camera_; }
    void setFlyMode(bool fly);
    // The surface for the engine's swapchain; VK_NULL_HANDLE until the window exists.
    quint64 vulkanSurface() const;
    QSize pixelSize() const { return size() * devicePixelRatio(); }
    // Called for each paced frame while exposed: asks for a frame (drawn elsewhere,
    // reported back with frameDrawn()).
    void setFrameCallback(std::function<void()> callback) { frame_ = std::move(callback); }
    // Something visible changed: render once more (coalesced by Qt to the refresh rate).
    void scheduleFrame();
    // A frame asked for has been presented (counted: framesRendered()).
    void frameDrawn();
    // Until the user moves the camera, a resize re-frames the scene (the first
    // scene is framed before the window has its final size).
    void setAutoFrame(bool on) { auto_frame_ = on; }
    std::uint64_t framesRendered() const { return frames_; }
    // Asks for a frame now, not at the next paced update.
    void renderNow();
    // Split view: the divider at this fraction of the width (none: no divider). A
    // left drag that starts within kDividerGrabPixels of it (the cursor shows it), or
    // with Ctrl held anywhere, moves it instead of the camera.
    void setDivider(std::optional<float> fraction);
    std::optional<float> divider() const { return divider_; }
    static constexpr double kDividerGrabPixels = 8.0;

Q_SIGNALS:
    void cameraChanged();
    void clicked(QPointF ndc); // normalised device coordinates, y up
    void frameAllRequested();
    void frameSelectionRequested();
    void dividerMoved(float fraction); // dragged by the user, 0..1 of the width
    // The native window (and with it the Vulkan surface) is about to go: whoever
    // presents to it must drop its swapchain now.
    void surfaceAboutToBeDestroyed();

protected:
    bool event(QEvent* e) override;
    void exposeEvent(QExposeEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void keyReleaseEvent(QKeyEvent* e) override;

private:
    void flyStep();
    bool nearDivider(QPointF p) const;

    OrbitCamera camera_;
    std::function<void()> frame_;
    QPointF press_pos_, last_pos_;
    Qt::MouseButtons buttons_;
    bool dragged_ = false;
    std::optional<float> divider_;
    bool dragging_divider_ = false;
    bool fly_ = false;
    bool auto_frame_ = false;
    QSet<int> keys_held_;
    QTimer fly_timer_;
    QElapsedTimer fly_clock_;
    std::uint64_t frames_ = 0;
};

} // namespace sherpa::editor
