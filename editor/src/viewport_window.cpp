#include "viewport_window.h"

#include <QExposeEvent>
#include <QPlatformSurfaceEvent>
#include <QVulkanInstance>

namespace sherpa::editor {

ViewportWindow::ViewportWindow(QVulkanInstance* instance)
    : input_(new ViewportInput(*this, camera_)), divider_(new SplitDivider(*this)) {
    if (instance) {
        setSurfaceType(QSurface::VulkanSurface);
        setVulkanInstance(instance);
    }
    // What the user moved is drawn at the next paced update.
    connect(input_, &ViewportInput::cameraChanged, this, &ViewportWindow::scheduleFrame);
    connect(divider_, &SplitDivider::moved, this, &ViewportWindow::scheduleFrame);
}

ViewportWindow::~ViewportWindow() {
    // The filters go first: the input moves camera_, which would otherwise be gone
    // before QObject deletes its children, while QWindow's destructor still sends events.
    delete divider_;
    delete input_;
}

quint64 ViewportWindow::vulkanSurface() const {
    QVulkanInstance* inst = vulkanInstance();
    if (!inst || !handle()) return 0;
    // VkSurfaceKHR is a non-dispatchable handle: a 64-bit value on every platform.
    return reinterpret_cast<quint64>(
        QVulkanInstance::surfaceForWindow(const_cast<ViewportWindow*>(this)));
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

void ViewportWindow::renderNow() {
    if (isExposed() && frame_) frame_();
}

} // namespace sherpa::editor
