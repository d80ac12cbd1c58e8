// The Lab dock's hooks into the window: which culling method the viewport uses (the
// chart rings it) and applying a method the dock's chart or table picks.
#include "main_window.h"
#include "main_window_actions.h"

#include <array>

#include "culling_monitor.h"
#include "lab_dock.h"

namespace sherpa::editor {

namespace {
// The Culling › Method menu's order (main_window_menus.cpp).
constexpr std::array kMenuMethods{CullMethod::Sphere, CullMethod::PVertex, CullMethod::Exact};

// The Lab's name of the culling the viewport does (lab/families.h): the CPU tests by
// their CullMethod name, the GPU path ("gpu") with its p-vertex test.
QString culling_in_use(bool gpu, CullMethod method) {
    if (gpu) return method == CullMethod::PVertex ? QStringLiteral("gpu") : QString();
    const std::string_view name = to_string(method);
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}
} // namespace

void MainWindow::connectLab() {
    lab_->setMethodInUse([this](const QString& family) {
        if (family != QLatin1String("culling")) return QString(); // no switch in the viewport
        return culling_in_use(a_->gpu_path->isChecked(), culling_->method());
    });
    connect(lab_, &LabDock::applyRequested, this,
            [this](const QString& family, const QString& method) {
                if (family != QLatin1String("culling")) return; // see the dock's tooltip
                const bool gpu = method == QLatin1String("gpu");
                for (std::size_t i = 0; i < kMenuMethods.size(); ++i)
                    if (culling_in_use(gpu, kMenuMethods[i]) == method) {
                        a_->method_actions[i]->trigger();
                        setGpuCulling(gpu);
                    }
            });
}

} // namespace sherpa::editor
