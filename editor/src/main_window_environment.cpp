// The window's environment lighting and display settings: the Environment menu and
// View › Tone Mapping (EnvironmentMenu), the environment given to the viewport when it
// changes (made on the render thread; its warnings reach the log), and the display
// settings in every frame.
#include "environment_menu.h"
#include "lab_dock.h"
#include "lab_runner.h"
#include "log_dock.h"
#include "main_window.h"
#include "main_window_actions.h"
#include "render_thread.h"
#include "variant_menu.h"
#include "viewport_window.h"

#include <QCoreApplication>
#include <QMenuBar>
#include <QPointer>

namespace sherpa::editor {

void MainWindow::setupEnvironment() {
    environment_ = new EnvironmentMenu(this);
    menuBar()->insertMenu(a_->culling->menuAction(), environment_->environmentMenu());
    a_->view->insertMenu(a_->cameras->menuAction(), environment_->toneMenu());
    connect(environment_, &EnvironmentMenu::environmentChanged, this,
            &MainWindow::applyEnvironment);
    connect(environment_, &EnvironmentMenu::displayChanged, this, [this] {
        updateLabLighting();
        viewport_->scheduleFrame();
    });
    // KHR_materials_variants: switched on the render thread, said in the log.
    auto* variants = new VariantMenu(
        context_,
        [this](VariantMenu::Task t) {
            if (render_) render_->post(std::move(t));
        },
        this);
    menuBar()->insertMenu(a_->culling->menuAction(), variants);
    connect(variants, &VariantMenu::switched, this, [this](const QString& message) {
        log_->append(LogDock::Level::Info, message);
        viewport_->scheduleFrame();
    });
}

// The Lab's lit frames (the shadows family) lit as the viewport is.
void MainWindow::updateLabLighting() {
    if (!lab_ || !environment_) return; // both made in the constructor; the Lab after
    gpu::FrameRequest settings;
    apply_display(environment_->display(), settings);
    lab_->runner().setLighting(environment_->choice(), settings);
}

void MainWindow::applyEnvironment() {
    updateLabLighting();
    if (!render_) return; // given to the device once it is ready
    const gpu::EnvironmentChoice choice = environment_->choice();
    // The command line's choice and the device becoming ready both ask: build it once.
    if (environment_posted_ && environment_posted_->kind == choice.kind &&
        environment_posted_->path == choice.path)
        return;
    environment_posted_ = choice;
    const QString name = choice.kind == gpu::EnvironmentChoice::Kind::None ? tr("none")
                         : choice.kind == gpu::EnvironmentChoice::Kind::Room
                             ? tr("the room")
                             : QString::fromStdString(choice.path);
    QPointer<MainWindow> self(this);
    render_->post([self, choice, name](GpuViewport& gpu) {
        const QStringList warnings = gpu.setEnvironment(choice);
        QMetaObject::invokeMethod(qApp, [self, warnings, name] {
            if (!self) return;
            for (const QString& w : warnings) self->log_->append(LogDock::Level::Warning, w);
            self->log_->append(LogDock::Level::Info, tr("Environment: %1.").arg(name));
            self->viewport_->scheduleFrame();
        });
    });
}

} // namespace sherpa::editor
