// What a new user tripped over (issue 14), in the window as launched: one texture
// cache with sherpa-cli, one-shot flags that do not stick, deterministic framing for
// screenshots, a viewport that keeps most of the window, and no cut-off text in the
// default layout at 1600×1000 in every language.
#include <QAbstractItemView>
#include <QChartView>
#include <QDockWidget>
#include <QGraphicsTextItem>
#include <QHeaderView>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QStyle>
#include <QTabBar>
#include <QTableView>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <QVulkanInstance>
#include <QtTest>

#include "attribute_model.h"
#include "command_line.h"
#include "compare_controls.h"
#include "culling_dock.h"
#include "cut_off_checks.h"
#include "difference_legend.h"
#include "editor_settings.h"
#include "gpu_viewport.h"
#include "lab_dock.h"
#include "lab_runner.h"
#include "log_dock.h"
#include "main_window.h"
#include "material_dock.h"
#include "material_fields_model.h"
#include "mesh_dock.h"
#include "scene_tree_dock.h"
#include "scene_tree_model.h"
#include "test_assets.h"
#include "texture_dock.h"
#include "texture_table_model.h"
#include "validation_dock.h"
#include "vertex_table_model.h"
#include "viewport_window.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {
constexpr QSize kWindow(1600, 1000);
const QStringList kLanguages = {QStringLiteral("en"), QStringLiteral("de"),
                                QStringLiteral("zh_CN")};
} // namespace

using namespace sherpa::editor::test;

class LayoutTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void oneTextureCacheWithTheCli();
    void oneShotFlagsDoNotPersist();
    void framingIsTheSameEveryRun();
    void viewportKeepsMostOfTheWindow();
    void passTableFilledByTheFirstFrame();
    void nothingIsCutOffInAnyLanguage();
    void motionSceneIsNotCutOff();
    void viewportModesAreNotCutOff();
    void sideBSaysWhenItShowsAndStartsAComparison();
    void validationIsNotCutOff();

private:
    // A window of 1600×1000 with builtin:default loaded and the sphere selected,
    // laid out: what `sherpa builtin:default --select sphere --screenshot` shoots.
    std::unique_ptr<MainWindow> launch(const QString& language = QStringLiteral("en"));
    // The language switched at run time, as View › Language does, and the layout settled.
    static bool switch_language(MainWindow& w, const QString& language);

    QVulkanInstance vulkan_;
};

void LayoutTests::initTestCase() {
    test::isolate_settings();
    qputenv("SHERPA_VALIDATION", "1");
    GpuViewport::configureInstance(vulkan_);
    vulkan_.create();
}

std::unique_ptr<MainWindow> LayoutTests::launch(const QString& language) {
    auto w = std::make_unique<MainWindow>(vulkan_.isValid() ? &vulkan_ : nullptr);
    w->setLanguage(language, false);
    w->resize(kWindow);
    w->show();
    if (!QTest::qWaitForWindowExposed(w.get())) return nullptr;
    if (!test::load(*w, QStringLiteral("builtin:default"))) return nullptr;
    if (!w->selection().selectNodeNamed(QStringLiteral("sphere"))) return nullptr;
    bool settled = false;
    when_layout_settles(*w, [&settled] { settled = true; });
    QElapsedTimer t;
    t.start();
    while (!settled && t.elapsed() < 20000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return settled ? std::move(w) : nullptr;
}

bool LayoutTests::switch_language(MainWindow& w, const QString& language) {
    if (w.language() != language && !w.setLanguage(language, false)) return false;
    bool settled = false;
    when_layout_settles(w, [&settled] { settled = true; });
    QElapsedTimer t;
    t.start();
    while (!settled && t.elapsed() < 20000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return settled;
}

void LayoutTests::oneTextureCacheWithTheCli() {
    // The XDG base directory rule, written out here rather than asked of the engine.
    const QByteArray xdg = qgetenv("XDG_CACHE_HOME");
    QVERIFY(!xdg.isEmpty());
    QCOMPARE(EditorSettings().get(setting::kCacheDirectory),
             QString::fromUtf8(xdg) + "/sherpa/textures");
    qputenv("XDG_CACHE_HOME", "");
    QCOMPARE(EditorSettings().get(setting::kCacheDirectory),
             QDir::homePath() + "/.cache/sherpa/textures");
    qputenv("XDG_CACHE_HOME", xdg);
}

void LayoutTests::oneShotFlagsDoNotPersist() {
    {
        EditorSettings s;
        s.set(setting::kLastView, QStringLiteral("lit"));
        s.set(setting::kLanguage, QStringLiteral("en"));
    }
    {
        MainWindow w(vulkan_.isValid() ? &vulkan_ : nullptr);
        CommandLine cl;
        QString error;
        QVERIFY(parse_command_line({QStringLiteral("sherpa"), QStringLiteral("--view"),
                                    QStringLiteral("uv0-checker"), QStringLiteral("--language"),
                                    QStringLiteral("de"), QStringLiteral("--dock"),
                                    QStringLiteral("log")},
                                   cl, error));
        QSignalSpy loaded(&w.loads(), &LoadController::sceneLoaded);
        run_command_line(w, cl, 0);
        QCOMPARE(w.views().debugView(), QStringLiteral("uv0-checker"));
        QCOMPARE(w.language(), QStringLiteral("de"));
        QVERIFY(loaded.wait(test::kLoadTimeoutMs));
        w.close();
    }
    // The next plain launch opens as the settings say, not as the last flags did.
    EditorSettings s;
    QCOMPARE(s.get(setting::kLastView), QStringLiteral("lit"));
    QCOMPARE(s.get(setting::kLanguage), QStringLiteral("en"));
    MainWindow next(nullptr);
    QCOMPARE(next.views().debugView(), QStringLiteral("lit"));
    QCOMPARE(next.language(), QStringLiteral("en"));
    // A menu choice is a choice: it is remembered.
    QVERIFY(next.views().setDebugView(QStringLiteral("normal")));
    QCOMPARE(EditorSettings().get(setting::kLastView), QStringLiteral("normal"));
    next.views().setDebugView(QStringLiteral("lit"));
}

void LayoutTests::framingIsTheSameEveryRun() {
    if (!vulkan_.isValid()) QSKIP("no Vulkan");
    render::FrameRequest runs[2];
    for (render::FrameRequest& run : runs) {
        std::unique_ptr<MainWindow> w = launch();
        QVERIFY(w);
        w->viewport()->renderNow(); // what screenshot() draws before grabbing
        run = w->frames().lastFrame().request;
        // Framed for the viewport as finally laid out, not an earlier size.
        const QSize size = w->viewport()->pixelSize();
        QCOMPARE(QSize(int(run.width), int(run.height)), size);
        OrbitCamera fresh;
        fresh.setAspect(float(size.width()) / float(size.height()));
        fresh.frameAuto(*w->context().scene());
        // The request leaves the aspect to the viewport, which is that size.
        QCOMPARE(run.camera.eye, fresh.pose().spec().eye);
        QCOMPARE(run.camera.aspect, 0.0f);
    }
    QCOMPARE(runs[0].width, runs[1].width);
    QCOMPARE(runs[0].height, runs[1].height);
    QCOMPARE(runs[0].camera.eye, runs[1].camera.eye);
    QCOMPARE(runs[0].camera.target, runs[1].camera.target);
}

void LayoutTests::viewportKeepsMostOfTheWindow() {
    std::unique_ptr<MainWindow> w = launch();
    QVERIFY(w);
    QWidget* viewport = w->centralWidget();
    const double share =
        double(viewport->width() * viewport->height()) / double(w->width() * w->height());
    qInfo("viewport %dx%d = %.1f%% of the window", viewport->width(), viewport->height(),
          100.0 * share);
    QVERIFY2(share >= 0.55, qPrintable(QString::number(share)));
    // Content does not widen a dock: a primitive with a long summary, all mesh tabs.
    const int width = viewport->width();
    w->selection().selectNodeNamed(QStringLiteral("instance grid"));
    w->selection().selectNodeNamed(QStringLiteral("torus"));
    wait_settled(*w);
    QCOMPARE(viewport->width(), width);
    w->docks().textures->raise(); // a secondary tab in front does not resize the column
    wait_settled(*w);
    QCOMPARE(viewport->width(), width);
    // Secondary docks are tabs behind the primary ones.
    const auto tabbed = [&w](QDockWidget* front, QDockWidget* behind) {
        return w->tabifiedDockWidgets(front).contains(behind);
    };
    QVERIFY(tabbed(w->docks().mesh, w->docks().material));
    QVERIFY(tabbed(w->docks().mesh, w->docks().textures));
    QVERIFY(tabbed(w->docks().sceneTree, w->docks().culling));
    QVERIFY(tabbed(w->docks().sceneTree, w->docks().log));
    // View › Reset Layout brings a floating, hidden arrangement back.
    w->docks().culling->setFloating(true);
    w->docks().mesh->hide();
    test::reset_layout(*w);
    QVERIFY(!w->docks().culling->isFloating());
    QVERIFY(w->docks().mesh->isVisibleTo(w.get()));
    wait_settled(*w);
    QCOMPARE(viewport->width(), width);
}

void LayoutTests::passTableFilledByTheFirstFrame() {
    if (!vulkan_.isValid()) QSKIP("no Vulkan");
    std::unique_ptr<MainWindow> w = launch();
    QVERIFY(w);
    // No camera move: the frames drawn for the load alone fill it.
    QTRY_VERIFY_WITH_TIMEOUT(w->docks().culling->passRows() > 0, 10000);
}

void LayoutTests::nothingIsCutOffInAnyLanguage() {
    // One window, the language switched as a user does (View › Language): every text
    // is retranslated in place and the layout settles again. The Lab's report stays.
    std::unique_ptr<MainWindow> w = launch();
    QVERIFY(w);
    // The Lab dock with a report: its chart and tables count too.
    QSignalSpy lab_done(&w->docks().lab->runner(), &LabRunner::finished);
    w->docks().lab->run(QStringLiteral("culling"));
    QVERIFY(lab_done.wait(120000));
    for (const QString& language : kLanguages) {
        QVERIFY(switch_language(*w, language));
        // All languages fit a 1600 px screen (the toolbar overflows into its menu).
        QVERIFY2(w->minimumSizeHint().width() <= kWindow.width(),
                 qPrintable(QStringLiteral("%1: minimum width %2")
                                .arg(language)
                                .arg(w->minimumSizeHint().width())));
        QCOMPARE(w->width(), kWindow.width());
        // Dock tab titles are whole (QMainWindow's tab bars, its direct children).
        for (QTabBar* bar : w->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly))
            for (int i = 0; i < bar->count(); ++i)
                QVERIFY2(bar->fontMetrics().horizontalAdvance(bar->tabText(i)) <
                             std::max(bar->tabRect(i).width(),
                                      bar->tabRect(i).height()), // vertical tabs
                         qPrintable(language + ": tab " + bar->tabText(i)));
        // Each tab of each dock group in front in turn.
        QStringList cut = cut_in_every_dock(*w);
        // The columns a user needs show whole without scrolling.
        cut << cut_needed_columns(*w);
        cut << toolbar_problems(*w);
        cut.removeDuplicates();
        QVERIFY2(cut.isEmpty(), qPrintable(language + ": " + cut.join(QStringLiteral("\n"))));
    }
}

void LayoutTests::motionSceneIsNotCutOff() {
    // A skinned, animated scene: skins, joints and animations in the scene tree, the
    // timeline shown under the viewport, the vertex table's JOINTS/WEIGHTS columns.
    std::unique_ptr<MainWindow> w = launch();
    QVERIFY(w);
    QVERIFY(test::load(*w, test::asset(QStringLiteral("RiggedSimple"))));
    QVERIFY(w->selection().selectNodeNamed(QStringLiteral("1")));
    w->docks().sceneTree->view()->expandAll();
    for (const QString& language : kLanguages) {
        QVERIFY(switch_language(*w, language));
        const QStringList cut = cut_in_every_dock(*w, QStringLiteral("rigged"));
        QVERIFY2(cut.isEmpty(), qPrintable(language + ": " + cut.join(QStringLiteral("\n"))));
    }
}

void LayoutTests::viewportModesAreNotCutOff() {
    // The mode switch's toolbar buttons and the difference legend beside the viewport
    // (issues 17, 18), in Difference mode with numbers, in every language.
    if (!vulkan_.isValid()) QSKIP("no Vulkan");
    std::unique_ptr<MainWindow> w = launch();
    QVERIFY(w);
    // The longest side-B label: this file with tangents by another method.
    w->comparison().compareWithTangents(scene::TangentMethod::MikkTSpaceWelded);
    QTRY_VERIFY_WITH_TIMEOUT(test::compare_session(*w) != nullptr, 30000);
    w->comparison().state().setMode(ViewportMode::Difference);
    // Numbers of the latest completed frame: a few frames on.
    for (int i = 0; i < 20 && !w->frames().lastReport().difference.valid; ++i) {
        w->frames().renderer()->renderAndWait(w->frames().lastFrame(),
                                              w->viewport()->vulkanSurface());
        QCoreApplication::processEvents();
    }
    QVERIFY(w->frames().lastReport().difference.valid);
    for (const QString& language : kLanguages) {
        QVERIFY(switch_language(*w, language));
        QStringList cut;
        // The window's minimum width still fits the screen (the toolbar overflows).
        if (w->minimumSizeHint().width() > kWindow.width())
            cut << QStringLiteral("minimum width %1").arg(w->minimumSizeHint().width());
        cut << toolbar_problems(*w);
        // Toolbar buttons on the bar are whole (those past its end are in its menu).
        for (auto* bar : w->findChildren<QToolBar*>())
            for (auto* button : bar->findChildren<QToolButton*>())
                if (button->isVisible() && button->width() < button->sizeHint().width())
                    cut << QStringLiteral("toolbar: %1 (%2 < %3)")
                               .arg(button->text())
                               .arg(button->width())
                               .arg(button->sizeHint().width());
        // The legend's texts fit its width and height.
        for (QLabel* label : test::difference_legend(*w).findChildren<QLabel*>()) {
            if (label->pixmap().isNull() &&
                (label->wordWrap() ? label->heightForWidth(label->width()) > label->height()
                                   : label->sizeHint().width() > label->width()))
                cut << QStringLiteral("legend: %1").arg(label->text());
        }
        QVERIFY2(cut.isEmpty(), qPrintable(language + ": " + cut.join(QStringLiteral("\n"))));
    }
}

void LayoutTests::sideBSaysWhenItShowsAndStartsAComparison() {
    // "B: ray tracer" was greyed out in Raster mode with no word why. It says when
    // side B shows, and choosing a side B starts a comparison (Split).
    QMainWindow host;
    auto* bar = host.addToolBar(QStringLiteral("bar"));
    CompareState state;
    CompareControls controls(state, &host);
    controls.addToToolBar(bar);
    state.setRayTracing(true);
    host.show();
    QVERIFY(QTest::qWaitForWindowExposed(&host));
    auto* side = bar->findChild<QToolButton*>(QStringLiteral("compareSideButton"));
    QVERIFY(side);
    QCOMPARE(state.comparison().mode, ViewportMode::Raster);
    QVERIFY(side->isEnabled());
    QVERIFY2(side->toolTip().contains(QStringLiteral("Split")) &&
                 side->toolTip().contains(QStringLiteral("Difference")),
             qPrintable(side->toolTip()));
    QAction* rays = side->menu()->actions().value(0); // "The Ray Tracer", first
    QVERIFY(rays && rays->isEnabled());
    rays->trigger();
    QCOMPARE(state.comparison().mode, ViewportMode::Split);
    QCOMPARE(state.comparison().side, SideB::RayTraced);
    // Already comparing: the mode stays.
    state.setMode(ViewportMode::Difference);
    rays->trigger();
    QCOMPARE(state.comparison().mode, ViewportMode::Difference);
    // A long side-B name is shortened on the button, whole in its tooltip.
    state.setOtherFile(QStringLiteral("AVeryLongExportedFileNameFromTheExporter_final_v7.gltf"),
                       scene::TangentMethod::Lengyel);
    state.setSide(SideB::OtherFile);
    QVERIFY(side->fontMetrics().horizontalAdvance(side->text()) <= 230);
    QVERIFY(side->toolTip().contains(QStringLiteral("final_v7.gltf")));
}

void LayoutTests::validationIsNotCutOff() {
    // A file with validation messages (materials using extensions that are not drawn):
    // the Validation dock under the left column, its groups and pointers, the selected
    // message in full, and the material dock's line about what is not drawn.
    std::unique_ptr<MainWindow> w = launch();
    QVERIFY(w);
    QVERIFY(test::load(
        *w, QStringLiteral(SHERPA_TEST_DATA_DIR "/unsupported_material_extensions.gltf")));
    QVERIFY(w->docks().validation->isVisible());
    QVERIFY(w->docks().validation->activatePointer(
        QStringLiteral("/materials/0/extensions/ADOBE_materials_thin_transparency")));
    for (const QString& language : kLanguages) {
        QVERIFY(switch_language(*w, language));
        QStringList cut = cut_in_every_dock(*w);
        w->docks().material->raise();
        wait_settled(*w);
        // Wrapped labels show every line (a label cut in height loses its last words).
        for (QDockWidget* dock : {static_cast<QDockWidget*>(w->docks().validation),
                                  static_cast<QDockWidget*>(w->docks().material)})
            for (QLabel* label : dock->findChildren<QLabel*>())
                if (label->isVisible() && !label->text().isEmpty() &&
                    label->heightForWidth(label->width()) > label->height())
                    cut << QStringLiteral("%1 label: %2 (%3 > %4 px high)")
                               .arg(dock->objectName(), label->text())
                               .arg(label->heightForWidth(label->width()))
                               .arg(label->height());
        cut.removeDuplicates();
        QVERIFY2(cut.isEmpty(), qPrintable(language + ": " + cut.join(QStringLiteral("\n"))));
    }
}

QTEST_MAIN(LayoutTests)
#include "layout_tests.moc"
