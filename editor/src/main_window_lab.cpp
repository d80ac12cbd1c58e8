// The Lab dock's hooks into the window: which culling method or shadow setting the
// viewport uses (the chart rings it) and applying a method the dock's chart or table
// picks.
#include "main_window.h"
#include "main_window_actions.h"

#include <array>

#include <QStatusBar>

#include <sherpa/lab/families.h>

#include "culling_monitor.h"
#include "lab_dock.h"
#include "viewport_window.h"

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
        // The viewport's maps are kDefaultShadowResolution; with the device's default
        // taps (unknown here) no method is named.
        if (family == QLatin1String("shadows"))
            return shadow_pcf_taps_ == 0
                       ? QString()
                       : QString::fromStdString(lab::shadow_method_name(
                             kDefaultShadowResolution, shadow_cascades_, shadow_pcf_taps_));
        if (family != QLatin1String("culling")) return QString(); // no switch in the viewport
        return culling_in_use(a_->gpu_path->isChecked(), culling_->method());
    });
    connect(lab_, &LabDock::applyRequested, this,
            [this](const QString& family, const QString& method) {
                if (family == QLatin1String("shadows")) {
                    std::uint32_t resolution = 0, cascades = 0, taps = 0;
                    if (!lab::parse_shadow_method(method.toStdString(), resolution, cascades, taps))
                        return;
                    shadow_cascades_ = cascades;
                    shadow_pcf_taps_ = taps;
                    statusBar()->showMessage(
                        tr("Shadows: %1 cascades, %2 PCF taps; the viewport's maps stay "
                           "%3x%3 texels (fixed when its renderer is made), not %4")
                            .arg(cascades)
                            .arg(taps)
                            .arg(kDefaultShadowResolution)
                            .arg(resolution),
                        10000);
                    viewport_->scheduleFrame();
                    return;
                }
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
