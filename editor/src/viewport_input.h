#pragma once
// The viewport's input: mouse, wheel and keys on the viewport window mapped to camera
// actions (orbit, pan, dolly, look and fly), picks (a click) and framing requests
// (F, Shift+F), and the window's size to the camera's aspect. An event filter on the
// window: the window itself only presents.
#include <QElapsedTimer>
#include <QObject>
#include <QPointF>
#include <QSet>
#include <QTimer>

class QKeyEvent;
class QMouseEvent;
class QWheelEvent;
class QWindow;

namespace sherpa::editor {

class OrbitCamera;

class ViewportInput : public QObject {
    Q_OBJECT
public:
    // Moves `camera` in answer to `window`'s input (filters the window's events).
    ViewportInput(QWindow& window, OrbitCamera& camera);

    // Left drag looks around and WASD/QE fly instead of orbiting.
    void setFlyMode(bool fly);
    // Until the user moves the camera, a resize re-frames the scene (the first
    // scene is framed before the window has its final size).
    void setAutoFrame(bool on) { auto_frame_ = on; }

Q_SIGNALS:
    void cameraChanged();
    void clicked(QPointF ndc); // normalised device coordinates, y up
    void frameAllRequested();
    void frameSelectionRequested();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void press(const QMouseEvent& e);
    void move(const QMouseEvent& e);
    void release(const QMouseEvent& e);
    void wheel(const QWheelEvent& e);
    void keyPress(const QKeyEvent& e);
    void keyRelease(const QKeyEvent& e);
    void resized();
    void flyStep();

    QWindow& window_;
    OrbitCamera& camera_;
    QPointF press_pos_, last_pos_;
    Qt::MouseButtons buttons_;
    bool dragged_ = false;
    bool fly_ = false;
    bool auto_frame_ = false;
    QSet<int> keys_held_;
    QTimer fly_timer_;
    QElapsedTimer fly_clock_;
};

} // namespace sherpa::editor
