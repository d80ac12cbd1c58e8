#include "split_divider.h"

#include <QMouseEvent>
#include <QWindow>
#include <algorithm>
#include <cmath>

namespace sherpa::editor {

SplitDivider::SplitDivider(QWindow& window) : QObject(&window), window_(window) {
    window.installEventFilter(this);
}

void SplitDivider::setFraction(std::optional<float> fraction) {
    fraction_ = fraction;
    if (!fraction_) {
        dragging_ = false;
        window_.unsetCursor();
    }
}

bool SplitDivider::near(const QMouseEvent& e) const {
    return fraction_ &&
           std::abs(e.position().x() - double(*fraction_) * window_.width()) <= kGrabPixels;
}

bool SplitDivider::eventFilter(QObject* watched, QEvent* event) {
    if (watched != &window_) return false;
    const auto type = event->type();
    if (type != QEvent::MouseButtonPress && type != QEvent::MouseMove &&
        type != QEvent::MouseButtonRelease)
        return false;
    const auto& e = static_cast<const QMouseEvent&>(*event);
    if (type == QEvent::MouseButtonPress) { // the camera's input sees the press too
        dragging_ = fraction_ && e.button() == Qt::LeftButton &&
                    (near(e) || (e.modifiers() & Qt::ControlModifier));
        dragged_ = false;
        return false;
    }
    if (type == QEvent::MouseButtonRelease) {
        const bool was_drag = dragging_ && dragged_;
        dragging_ = dragged_ = false;
        return was_drag; // a divider drag is not a pick
    }
    if (dragging_ && (e.buttons() & Qt::LeftButton) && window_.width() > 0) {
        dragged_ = true;
        fraction_ = static_cast<float>(std::clamp(e.position().x() / window_.width(), 0.0, 1.0));
        Q_EMIT moved(*fraction_);
        return true; // the camera stays
    }
    // The grab zone shows itself: the split cursor over the divider.
    if (e.buttons() == Qt::NoButton) {
        if (near(e))
            window_.setCursor(Qt::SplitHCursor);
        else if (fraction_)
            window_.unsetCursor();
    }
    return false;
}

} // namespace sherpa::editor
