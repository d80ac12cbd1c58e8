// sherpa-bench-editor: the editor's measured goals (run under xvfb-run -a).
//   1. switching to DamagedHelmet, warm (file cache hot): openScene -> sceneLoaded;
//   2. scrolling the vertex table of a 1M-vertex primitive: every repaint timed.
// Launch to first frame is measured on the real binary: `sherpa --timing ...`.
#include <QApplication>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QScrollBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QVulkanInstance>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "gpu_viewport.h"
#include "load_controller.h"
#include "main_window.h"
#include "vertex_table_model.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

double switch_ms(MainWindow& w, const QString& spec) {
    QSignalSpy loaded(&w.loads(), &LoadController::sceneLoaded);
    QElapsedTimer t;
    t.start();
    w.loads().openScene(spec);
    while (loaded.isEmpty()) QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    return static_cast<double>(t.nsecsElapsed()) / 1e6;
}

void bench_switch() {
    QVulkanInstance vulkan;
    sherpa::editor::GpuViewport::configureInstance(vulkan);
    vulkan.create();
    MainWindow w(vulkan.isValid() ? &vulkan : nullptr);
    w.show();
    const QString helmet =
        QStringLiteral(SHERPA_ASSETS_DIR "/gltf/DamagedHelmet/glTF/DamagedHelmet.gltf");
    switch_ms(w, helmet); // warm the file cache and the thread pool
    std::vector<double> ms;
    for (int i = 0; i < 5; ++i) {
        switch_ms(w, QStringLiteral("builtin:default"));
        ms.push_back(switch_ms(w, helmet));
    }
    std::sort(ms.begin(), ms.end());
    std::printf(
        "switch to DamagedHelmet (warm), 5 runs: min %.1f ms, median %.1f ms, max %.1f ms\n",
        ms.front(), ms[2], ms.back());
}

void bench_scroll() {
    auto scene = std::make_shared<scene::Scene>();
    scene::Mesh mesh;
    mesh.vertices.resize(1'000'000);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        mesh.vertices[i].position = {static_cast<float>(i) * 0.001f,
                                     std::sin(static_cast<float>(i)),
                                     1.0f / static_cast<float>(i + 1)};
    mesh.colors.assign(mesh.vertices.size(), glm::vec4(0.5f));
    scene->meshes.push_back(std::move(mesh));
    VertexTableModel model;
    model.setMesh(MeshRef{scene, 0});
    QTableView view;
    view.setModel(&model);
    view.verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    view.verticalHeader()->setDefaultSectionSize(view.fontMetrics().height() + 4);
    view.verticalHeader()->hide();
    view.resize(1400, 900);
    view.show();
    QCoreApplication::processEvents();
    QScrollBar* bar = view.verticalScrollBar();
    std::vector<double> frames;
    QElapsedTimer t;
    // Page-by-page through the first 20k rows, then jumps across the whole range (a drag
    // of the scroll thumb), then sorted by a column and scrolled again.
    const auto frame = [&](int value) {
        t.start();
        bar->setValue(value);
        view.viewport()->repaint();
        frames.push_back(static_cast<double>(t.nsecsElapsed()) / 1e6);
    };
    for (int v = 0; v < 20000; v += bar->pageStep()) frame(v);
    for (int i = 0; i <= 500; ++i)
        frame(static_cast<int>(static_cast<long long>(bar->maximum()) * i / 500));
    t.start();
    model.sort(VertexTableModel::PosY, Qt::DescendingOrder);
    const double sort_ms = static_cast<double>(t.nsecsElapsed()) / 1e6;
    for (int i = 0; i <= 500; ++i)
        frame(static_cast<int>(static_cast<long long>(bar->maximum()) * i / 500));
    std::sort(frames.begin(), frames.end());
    std::printf(
        "vertex table, 1M rows, %zu scroll repaints: median %.2f ms, p99 %.2f ms, max %.2f ms "
        "(frames over 50 ms: %zu); sort 1M rows by pos.y %.1f ms\n",
        frames.size(), frames[frames.size() / 2], frames[frames.size() * 99 / 100], frames.back(),
        static_cast<std::size_t>(
            std::count_if(frames.begin(), frames.end(), [](double f) { return f > 50.0; })),
        sort_ms);
}

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    bench_switch();
    bench_scroll();
    return 0;
}
