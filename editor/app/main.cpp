// sherpa: the editor. See command_line.h for the arguments.
#include <QApplication>
#include <QElapsedTimer>
#include <QVulkanInstance>
#include <cstdio>
#include <cstring>

#include "command_line.h"
#include "gpu_viewport.h"
#include "main_window.h"

#include <sherpa/core/heap_tuning.h>

namespace {

void name_application() {
    QCoreApplication::setOrganizationName(QStringLiteral("Sherpa"));
    QCoreApplication::setApplicationName(QStringLiteral("Sherpa"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SHERPA_VERSION));
}

// --help and --version print and exit: they need no display, so they are answered
// before QApplication (which aborts without one) exists.
bool asks_for_help_or_version(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        for (const char* flag : {"--help", "-h", "-?", "--help-all", "--version", "-v"})
            if (std::strcmp(argv[i], flag) == 0) return true;
    return false;
}

} // namespace

int main(int argc, char** argv) {
    // A CPU Vulkan device frees and reallocates large blocks every frame: keep them mapped.
    sherpa::core::keep_freed_memory_mapped();
    if (asks_for_help_or_version(argc, argv)) {
        QCoreApplication core(argc, argv);
        name_application();
        sherpa::editor::CommandLine cl;
        QString error;
        // Prints the help or the version and exits 0.
        sherpa::editor::parse_command_line(QCoreApplication::arguments(), cl, error);
        std::fprintf(stderr, "sherpa: %s\n", qPrintable(error));
        return 2;
    }
    QElapsedTimer launch;
    launch.start();
    QApplication app(argc, argv);
    name_application();
    QApplication::setDesktopFileName(QStringLiteral("sherpa"));

    sherpa::editor::CommandLine cl;
    QString error;
    if (!sherpa::editor::parse_command_line(QApplication::arguments(), cl, error)) {
        std::fprintf(stderr, "sherpa: %s\n", qPrintable(error));
        return 2;
    }

    // The engine needs Vulkan 1.3; the instance is Qt's so that surfaceForWindow works.
    QVulkanInstance vulkan;
    sherpa::editor::GpuViewport::configureInstance(vulkan);
    if (!vulkan.create())
        std::fprintf(stderr, "sherpa: no Vulkan instance (error %d); the viewport stays empty\n",
                     static_cast<int>(vulkan.errorCode()));

    sherpa::editor::MainWindow window(vulkan.isValid() ? &vulkan : nullptr, nullptr,
                                      cl.ray_tracing);
    // The device is made on the render thread while the window shows; the scene
    // starts loading on the thread pool once it is known.
    sherpa::editor::run_command_line(window, cl, launch.nsecsElapsed());
    window.show();
    return QApplication::exec();
}
