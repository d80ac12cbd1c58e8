#include "viewport_input.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>
#include <QWindow>
#include <algorithm>

#include "orbit_camera.h"

namespace sherpa::editor {

namespace {
constexpr double kClickSlopPixels = 4.0; // a press that moves less than this is a pick
} // namespace

ViewportInput::ViewportInput(QWindow& window, OrbitCamera& camera)
    : QObject(&window), window_(window), camera_(camera) {
    fly_timer_.setInterval(16);
    connect(&fly_timer_, &QTimer::timeout, this, &ViewportInput::flyStep);
    window.installEventFilter(this);
}

void ViewportInput::setFlyMode(bool fly) {
    fly_ = fly;
    keys_held_.clear();
    fly_timer_.stop();
}

bool ViewportInput::eventFilter(QObject* watched, QEvent* event) {
    if (watched != &window_) return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress:
        press(static_cast<const QMouseEvent&>(*event));
        return true;
    case QEvent::MouseMove:
        move(static_cast<const QMouseEvent&>(*event));
        return true;
    case QEvent::MouseButtonRelease:
        release(static_cast<const QMouseEvent&>(*event));
        return true;
    case QEvent::Wheel:
        wheel(static_cast<const QWheelEvent&>(*event));
        return true;
    case QEvent::KeyPress:
        keyPress(static_cast<const QKeyEvent&>(*event));
        return true;
    case QEvent::KeyRelease:
        keyRelease(static_cast<const QKeyEvent&>(*event));
        return true;
    case QEvent::Resize:
        resized();
        return false; // the window resizes too
    default:
        return false;
    }
}

void ViewportInput::resized() {
    const int w = window_.width(), h = window_.height();
    camera_.setAspect(h > 0 ? static_cast<float>(w) / static_cast<float>(h) : 1.0f);
    // Until the user moves the camera, the scene stays framed for the new aspect.
    if (auto_frame_) Q_EMIT frameAllRequested();
    Q_EMIT cameraChanged();
}

void ViewportInput::press(const QMouseEvent& e) {
    auto_frame_ = false;
    press_pos_ = last_pos_ = e.position();
    buttons_ = e.buttons();
    dragged_ = false;
}

void ViewportInput::move(const QMouseEvent& e) {
    if (e.buttons() == Qt::NoButton) return;
    const QPointF d = e.position() - last_pos_;
    last_pos_ = e.position();
    if ((e.position() - press_pos_).manhattanLength() > kClickSlopPixels) dragged_ = true;
    const auto dx = static_cast<float>(d.x()), dy = static_cast<float>(d.y());
    const bool pan = (e.buttons() & Qt::MiddleButton) ||
                     ((e.buttons() & Qt::LeftButton) && (e.modifiers() & Qt::ShiftModifier));
    if (pan)
        camera_.pan(dx, dy, static_cast<float>(window_.height()));
    else if (e.buttons() & Qt::LeftButton)
        fly_ ? camera_.look(dx, dy) : camera_.orbit(dx, dy);
    else if (e.buttons() & Qt::RightButton)
        camera_.dolly(-dy / 40.0f);
    Q_EMIT cameraChanged();
}

void ViewportInput::release(const QMouseEvent& e) {
    const int w = window_.width(), h = window_.height();
    if (!dragged_ && (buttons_ & Qt::LeftButton) && w > 0 && h > 0) {
        const QPointF p = e.position();
        Q_EMIT clicked(QPointF(2.0 * p.x() / w - 1.0, 1.0 - 2.0 * p.y() / h));
    }
    buttons_ = Qt::NoButton;
}

void ViewportInput::wheel(const QWheelEvent& e) {
    auto_frame_ = false;
    camera_.dolly(static_cast<float>(e.angleDelta().y()) / 120.0f);
    Q_EMIT cameraChanged();
}

void ViewportInput::keyPress(const QKeyEvent& e) {
    auto_frame_ = false;
    if (e.key() == Qt::Key_F && !e.isAutoRepeat()) {
        if (e.modifiers() & Qt::ShiftModifier)
            Q_EMIT frameSelectionRequested();
        else
            Q_EMIT frameAllRequested();
        return;
    }
    if (fly_ && !e.isAutoRepeat()) {
        keys_held_.insert(e.key());
        if (!fly_timer_.isActive()) {
            fly_clock_.start();
            fly_timer_.start();
        }
    }
}

void ViewportInput::keyRelease(const QKeyEvent& e) {
    if (e.isAutoRepeat()) return;
    keys_held_.remove(e.key());
    if (keys_held_.isEmpty()) fly_timer_.stop();
}

void ViewportInput::flyStep() {
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
}

} // namespace sherpa::editor
