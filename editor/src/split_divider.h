#pragma once
// The split view's divider on the viewport window: where it is (a fraction of the
// width) and its drag. A left drag that starts within kGrabPixels of it (the cursor
// shows it), or with Ctrl held anywhere, moves it instead of the camera. An event
// filter on the window, ahead of the camera's input (ViewportInput).
#include <QObject>

#include <optional>

class QMouseEvent;
class QWindow;

namespace sherpa::editor {

class SplitDivider : public QObject {
    Q_OBJECT
public:
    // Filters `window`'s mouse events; install it after the camera's input, so that a
    // divider drag reaches it first.
    explicit SplitDivider(QWindow& window);

    // The divider at this fraction of the width (none: no divider, no drag).
    void setFraction(std::optional<float> fraction);
    std::optional<float> fraction() const { return fraction_; }
    static constexpr double kGrabPixels = 8.0;

Q_SIGNALS:
    void moved(float fraction); // dragged by the user, 0..1 of the width

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool near(const QMouseEvent& e) const;

    QWindow& window_;
    std::optional<float> fraction_;
    bool dragging_ = false; // a left press started a drag of the divider
    bool dragged_ = false;  // and it moved (the release is not a pick)
};

} // namespace sherpa::editor
