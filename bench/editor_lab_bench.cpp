// sherpa-bench-lab: UI event latency while the Lab dock runs a family on
// DamagedHelmet (goal: p99 <= 50 ms on lavapipe), run under
// `xvfb-run -a -s "-screen 0 1920x1200x24"`. A second thread posts an event to the
// GUI thread every 10 ms; the delay until each runs is recorded (p50, p99, max):
//   idle (the scene shown, nothing running: the floor of this machine),
//   each family running in the dock (its worker thread),
//   the same runs on the GUI thread (what a dock without a worker would do: the
//   reference the ratio is printed against; not for textures, which takes ~30 s).
// Arguments: [FAMILY|all] [SECONDS per family, default 5] [SCREENSHOT.png].
// Prints numbers; never part of the test suite.
#include <QApplication>
#include <QElapsedTimer>
#include <QStandardPaths>
#include <QVulkanInstance>
#include <algorithm>
#include <cstdio>
#include <vector>

#include <sherpa/lab/family.h>
#include <sherpa/scene/scene_loader.h>

#include "gpu_viewport.h"
#include "lab_dock.h"
#include "lab_runner.h"
#include "main_window.h"
#include "ui_latency.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;
using sherpa::bench::latencies_during;
using sherpa::bench::percentile;

using sherpa::editor::test::load; // the editor suites' bounded load

namespace {

void print_latency(const char* what, double seconds, const std::vector<double>& d) {
    std::printf("  %-30s %6.1f s %5zu events: p50 %6.1f ms, p99 %7.1f ms, max %7.1f ms\n", what,
                seconds, d.size(), percentile(d, 0.5), percentile(d, 0.99), percentile(d, 1.0));
}

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QVulkanInstance vulkan;
    GpuViewport::configureInstance(vulkan);
    vulkan.create();
    MainWindow w(vulkan.isValid() ? &vulkan : nullptr);
    w.setLanguage(QStringLiteral("en"), false);
    w.setLayoutRemembered(false);
    w.resize(1600, 1000);
    w.show();
    const QString helmet =
        QStringLiteral(SHERPA_ASSETS_DIR "/gltf/DamagedHelmet/glTF/DamagedHelmet.gltf");
    if (!load(w, helmet)) {
        std::fprintf(stderr, "could not load %s\n", qPrintable(helmet));
        return 1;
    }
    LabDock& dock = *w.docks().lab;
    dock.show();
    dock.raise();
    std::printf("DamagedHelmet, window 1600x1000, Lab dock shown; events posted every 10 ms\n");
    QElapsedTimer t;
    t.start();
    const std::vector<double> idle = latencies_during([] {
        QElapsedTimer idle_t;
        idle_t.start();
        while (idle_t.elapsed() < 3000)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    });
    print_latency("idle", double(t.elapsed()) / 1e3, idle);
    const QStringList families =
        argc > 1 && QByteArray(argv[1]) != "all"
            ? QStringList{QString::fromLocal8Bit(argv[1])}
            : QStringList{QStringLiteral("tangents"), QStringLiteral("textures"),
                          QStringLiteral("culling")};
    // Each family back to back in the dock until `seconds` have passed (textures once:
    // it alone takes longer), then the same number of runs on the GUI thread.
    const double seconds = argc > 2 ? std::max(1.0, std::atof(argv[2])) : 5.0;
    double worst_p99 = 0.0;
    for (const QString& family : families) {
        int runs = 0;
        bool done = false;
        auto c = QObject::connect(&dock.runner(), &LabRunner::finished, &w, [&] {
            done = true;
            ++runs;
        });
        t.restart();
        const std::vector<double> d = latencies_during([&] {
            do {
                done = false;
                dock.run(family);
                while (!done) QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
            } while (double(t.elapsed()) < seconds * 1e3);
        });
        QObject::disconnect(c);
        const double worker_s = double(t.elapsed()) / 1e3;
        const QByteArray what = QStringLiteral("%1 x%2 in the dock").arg(family).arg(runs).toUtf8();
        print_latency(what.constData(), worker_s, d);
        worst_p99 = std::max(worst_p99, percentile(d, 0.99));
        if (family == QLatin1String("textures")) continue; // too long to block the GUI for
        // The reference: the same runs on the GUI thread (a dock without a worker), the
        // scene loaded before the clock starts (the dock's runs load it inside theirs).
        scene::LoadResult scene = scene::load_scene(helmet.toStdString(), lab::lab_load_options());
        if (!scene) {
            std::fprintf(stderr, "could not load %s: %s\n", qPrintable(helmet),
                         scene.error.c_str());
            return 1;
        }
        t.restart();
        const std::vector<double> blocking = latencies_during([&] {
            for (int i = 0; i < runs; ++i)
                lab::make_family(family.toStdString())->run(*scene.scene, {});
        });
        const QByteArray ref =
            QStringLiteral("%1 x%2 on the GUI thread").arg(family).arg(runs).toUtf8();
        print_latency(ref.constData(), double(t.elapsed()) / 1e3, blocking);
        std::printf("  %-30s p99 GUI thread / dock: %.1fx\n", "",
                    percentile(blocking, 0.99) / std::max(0.001, percentile(d, 0.99)));
    }
    std::printf("  worst p99 while the dock runs a family: %.1f ms (goal <= 50 ms)\n", worst_p99);
    if (argc > 3) w.screenshot().save(QString::fromLocal8Bit(argv[3])); // the dock with a report
    return 0;
}
