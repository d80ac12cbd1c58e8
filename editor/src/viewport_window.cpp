#include "viewport_window.h"

#include <QExposeEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPlatformSurfaceEvent>
#include <QVulkanInstance>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace sherpa::editor {

namespace {
constexpr double kClickSlopPixels = 4.0; // a press that moves less than this is a pick
} // namespace

ViewportWindow::ViewportWindow(QVulkanInstance* instance) {
    if (instance) {
        setSurfaceType(QSurface::VulkanSurface);
        setVulkanInstance(instance);
    }
    fly_timer_.setInterval(16);
    connect(&fly_timer_, &QTimer::timeout, this, &ViewportWindow::flyStep);
}

quint64 ViewportWindow::vulkanSurface() const {
    QVulkanInstance* inst = vulkanInstance();
    if (!inst || !handle()) return 0;
    // VkSurfaceKHR is a non-dispatchable handle: a 64-bit value on every platform.
    return reinterpret_cast<quint64>(
        QVulkanInstance::surfaceForWindow(const_cast<ViewportWindow*>(this)));
}

void ViewportWindow::setFlyMode(bool fly) {
    fly_ = fly;
    keys_held_.clear();
    fly_timer_.stop();
}

void ViewportWindow::scheduleFrame() {
    if (isExposed()) requestUpdate();
}

bool ViewportWindow::event(QEvent* e) {
    if (e->type() == QEvent::UpdateRequest) {
        renderNow();
        return true;
    }
    if (e->type() == QEvent::PlatformSurface &&
        static_cast<QPlatformSurfaceEvent*>(e)->surfaceEventType() ==
            QPlatformSurfaceEvent::SurfaceAboutToBeDestroyed)
        Q_EMIT surfaceAboutToBeDestroyed(); // before Qt destroys the VkSurfaceKHR
    return QWindow::event(e);
}

void ViewportWindow::exposeEvent(QExposeEvent*) {
    // Minimised or hidden windows are not exposed: no frames at all then.
    if (isExposed()) scheduleFrame();
}

void ViewportWindow::resizeEvent(QResizeEvent*) {
    camera_.setAspect(height() > 0 ? static_cast<float>(width()) / static_cast<float>(height())
                                   : 1.0f);
    // Until the user moves the camera, the scene stays framed for the new aspect.
    if (auto_frame_) Q_EMIT frameAllRequested();
    Q_EMIT cameraChanged();
    scheduleFrame();
}

void ViewportWindow::renderNow() {
    if (isExposed() && frame_) frame_();
}

void ViewportWindow::frameDrawn() {
    ++frames_;
}

void ViewportWindow::setDivider(std::optional<float> fraction) {
    divider_ = fraction;
    if (!divider_) {
        dragging_divider_ = false;
        unsetCursor();
    }
}

bool ViewportWindow::nearDivider(QPointF p) const {
    return divider_ && std::abs(p.x() - double(*divider_) * width()) <= kDividerGrabPixels;
}

void ViewportWindow::mousePressEvent(QMouseEvent* e) {
    auto_frame_ = false;
    press_pos_ = last_pos_ = e->position();
    buttons_ = e->buttons();
    dragged_ = false;
    dragging_divider_ = divider_ && e->button() == Qt::LeftButton &&
                        (nearDivider(e->position()) || (e->modifiers() & Qt::ControlModifier));
}

void ViewportWindow::mouseMoveEvent(QMouseEvent* e) {
    if (dragging_divider_ && (e->buttons() & Qt::LeftButton) && width() > 0) {
        dragged_ = true; // not a pick
        divider_ = static_cast<float>(std::clamp(e->position().x() / width(), 0.0, 1.0));
        Q_EMIT dividerMoved(*divider_);
        scheduleFrame();
        return;
    }
    if (e->buttons() == Qt::NoButton) {
        // The grab zone shows itself: the split cursor over the divider.
        if (nearDivider(e->position()))
            setCursor(Qt::SplitHCursor);
        else if (divider_)
            unsetCursor();
        return;
    }
    const QPointF d = e->position() - last_pos_;
    last_pos_ = e->position();
    if ((e->position() - press_pos_).manhattanLength() > kClickSlopPixels) dragged_ = true;
    const auto dx = static_cast<float>(d.x()), dy = static_cast<float>(d.y());
    const bool pan = (e->buttons() & Qt::MiddleButton) ||
                     ((e->buttons() & Qt::LeftButton) && (e->modifiers() & Qt::ShiftModifier));
    if (pan)
        camera_.pan(dx, dy, static_cast<float>(height()));
    else if (e->buttons() & Qt::LeftButton)
        fly_ ? camera_.look(dx, dy) : camera_.orbit(dx, dy);
    else if (e->buttons() & Qt::RightButton)
        camera_.dolly(-dy / 40.0f);
    Q_EMIT cameraChanged();
    scheduleFrame();
}

void ViewportWindow::mouseReleaseEvent(QMouseEvent* e) {
    if (!dragged_ && (buttons_ & Qt::LeftButton) && width() > 0 && height() > 0) {
        const QPointF p = e->position();
        Q_EMIT clicked(QPointF(2.0 * p.x() / width() - 1.0, 1.0 - 2.0 * p.y() / height()));
    }
    buttons_ = Qt::NoButton;
    dragging_divider_ = false;
}

void ViewportWindow::wheelEvent(QWheelEvent* e) {
    auto_frame_ = false;
    camera_.dolly(static_cast<float>(e->angleDelta().y()) / 120.0f);
    Q_EMIT cameraChanged();
    scheduleFrame();
}

void ViewportWindow::keyPressEvent(QKeyEvent* e) {
    auto_frame_ = false;
    if (e->key() == Qt::Key_F && !e->isAutoRepeat()) {
        if (e->modifiers() & Qt::ShiftModifier)
            Q_EMIT frameSelectionRequested();
        else
            Q_EMIT frameAllRequested();
        return;
    }
    if (fly_ && !e->isAutoRepeat()) {
        keys_held_.insert(e->key());
        if (!fly_timer_.isActive()) {
            fly_clock_.start();
            fly_timer_.start();
        }
    }
}

void ViewportWindow::keyReleaseEvent(QKeyEvent* e) {
    if (e->isAutoRepeat()) return;
    keys_held_.remove(e->key());
    if (keys_held_.isEmpty()) fly_timer_.stop();
}

void ViewportWindow::flyStep() {
    // WASD + Q/E, speed proportional to the orbit distance so every scale feels the same.
    const float dt = static_cast<float>(fly_clock_.restart()) / 1000.0f;
    const float speed = std::max(camera_.pose().distance, 0.1f) * dt;
    glm::vec3 move(0.0f);
    if (keys_held_.contains(Qt::Key_W)) move.z += speed;
    if (keys_held_.contains(Qt::Key_S)) move.z -= speed;
    if (keys_held_.contains(Qt::Key_D)) move.x += speed;
    if (keys_held_.contains(Qt::Key_A)) move.x -= speed;
    if (keys_held_.contains(Qt::Key_E)) move.y += speed;
    if (keys_held_.contains(Qt::Key_Q)) move.y -= speed;
    if (move == glm::vec3(0.0f)) return;
    camera_.fly(move);
    Q_EMIT cameraChanged();
    scheduleFrame();
}

} // namespace sherpa::editor
