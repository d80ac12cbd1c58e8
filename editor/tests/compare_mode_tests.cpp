// The viewport's A/B comparison modes in a window: Split shows side A left and side B
// right, dragging moves the divider, and the difference of a scene with itself is zero.
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/comparison.h>

#include <QHeaderView>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTableView>
#include <QVulkanInstance>
#include <QtTest>
#include <limits>
#include <set>

#include "acceleration_dock.h"
#include "acceleration_model.h"
#include "command_line.h"
#include "compare_controls.h"
#include "difference_legend.h"
#include "log_dock.h"
#include "main_window.h"
#include "scene_tree_dock.h"
#include "test_assets.h"
#include "view_catalog.h"
#include "viewport_window.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

// Pixels of columns [x0, x1) where the two images differ by more than 2/255 in a channel.
int differing(const QImage& a, const QImage& b, int x0, int x1) {
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = x0; x < x1; ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            if (std::abs(qRed(p) - qRed(q)) > 2 || std::abs(qGreen(p) - qGreen(q)) > 2 ||
                std::abs(qBlue(p) - qBlue(q)) > 2)
                ++n;
        }
    return n;
}

std::uint32_t view(const char* name) {
    return *ViewCatalog::viewId(QString::fromLatin1(name));
}

} // namespace

class CompareModeTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void splitShowsALeftAndBRight();
    void draggingMovesTheDivider();
    void differenceOfASceneWithItselfIsZero();
    void cleanup();

private:
    void checkValidation();

    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_ = 0;
};

void CompareModeTests::initTestCase() {
    window_ = test::open_validated_window(vulkan_);
    QVERIFY(window_);
    if (!window_->frames().renderer()) QSKIP("no Vulkan device");
    QTRY_VERIFY_WITH_TIMEOUT(window_->frames().rayTracing(), 10000);
}

void CompareModeTests::cleanupTestCase() {
    if (window_) checkValidation();
    window_.reset();
}

void CompareModeTests::cleanup() {
    if (!window_) return;
    window_->comparison().state().setMode(ViewportMode::Raster);
    window_->views().setDebugView(QStringLiteral("lit"), false);
}

void CompareModeTests::checkValidation() {
    const QString fresh = test::fresh_validation_messages(*window_, seen_);
    QVERIFY2(fresh.isEmpty(), qPrintable(fresh));
}

void CompareModeTests::splitShowsALeftAndBRight() {
    MainWindow& w = *window_;
    QVERIFY(test::load(w, QStringLiteral("builtin:default")));
    w.selection().pickAt(QPointF(-0.99, 0.99));
    QVERIFY(w.views().setDebugView(QStringLiteral("normal"), false));
    const QImage a = test::viewport_shot(w);
    QVERIFY(w.views().setDebugView(QStringLiteral("uv0"), false));
    const QImage b = test::viewport_shot(w);
    QVERIFY(w.views().setDebugView(QStringLiteral("normal"), false));
    CompareState& c = w.comparison().state();
    c.setSide(SideB::OtherView, view("uv0"));
    c.setMode(ViewportMode::Split);
    c.setDivider(0.5f);
    const QImage split = test::viewport_shot(w);
    QVERIFY(w.frames().lastReport().refused.isEmpty());
    const int mid = split.width() / 2, band = 4, h = split.height();
    QVERIFY(differing(a, b, 0, split.width()) > split.width() * h / 10); // the views differ
    // A left of the divider, B right of it (a thin band around the line aside).
    const int left = differing(split, a, 0, mid - band);
    const int right = differing(split, b, mid + band, split.width());
    QVERIFY2(left <= (mid - band) * h / 200, qPrintable(QString::number(left)));
    QVERIFY2(right <= (mid - band) * h / 200, qPrintable(QString::number(right)));
    QVERIFY(differing(split, a, mid + band, split.width()) > mid * h / 20);
    // The screenshot the docs show.
    if (qEnvironmentVariableIsSet("SHERPA_SPLIT_SHOT"))
        w.screenshot().save(qEnvironmentVariable("SHERPA_SPLIT_SHOT"));
    checkValidation();
}

void CompareModeTests::draggingMovesTheDivider() {
    MainWindow& w = *window_;
    QVERIFY(w.views().setDebugView(QStringLiteral("normal"), false));
    CompareState& c = w.comparison().state();
    c.setSide(SideB::OtherView, view("uv0"));
    c.setMode(ViewportMode::Split);
    c.setDivider(0.5f);
    ViewportWindow* vp = w.viewport();
    QCOMPARE(vp->divider().fraction().value_or(-1.0f), 0.5f);
    const int y = vp->height() / 2, width = vp->width();
    const scene::CameraSpec camera = vp->camera().pose().spec();
    // Grabbed at the line (within the grab zone), dropped at a quarter of the width.
    QTest::mousePress(vp, Qt::LeftButton, Qt::NoModifier, QPoint(width / 2 + 3, y));
    QTest::mouseMove(vp, QPoint(width / 3, y));
    QTest::mouseMove(vp, QPoint(width / 4, y));
    QTest::mouseRelease(vp, Qt::LeftButton, Qt::NoModifier, QPoint(width / 4, y));
    QVERIFY(std::abs(c.comparison().divider - 0.25f) < 0.01f);
    QCOMPARE(vp->camera().pose().spec().eye, camera.eye); // the camera did not orbit
    // Ctrl+drag from anywhere.
    QTest::mousePress(vp, Qt::LeftButton, Qt::ControlModifier, QPoint(width * 3 / 4, y));
    QTest::mouseMove(vp, QPoint(width * 7 / 10, y));
    QTest::mouseMove(vp, QPoint(width * 4 / 5, y));
    QTest::mouseRelease(vp, Qt::LeftButton, Qt::ControlModifier, QPoint(width * 4 / 5, y));
    QVERIFY(std::abs(c.comparison().divider - 0.8f) < 0.01f);
    QCOMPARE(vp->camera().pose().spec().eye, camera.eye);
    // The frame follows: B (uv0) now starts at 80% of the width.
    const QImage split = test::viewport_shot(w);
    c.setMode(ViewportMode::Raster);
    const QImage a = test::viewport_shot(w);
    const int at = split.width() * 4 / 5;
    QVERIFY(differing(split, a, 0, at - 4) <= at * split.height() / 200);
    // Without a split, a drag orbits again.
    QVERIFY(!vp->divider().fraction());
    QTest::mousePress(vp, Qt::LeftButton, Qt::NoModifier, QPoint(width / 2, y));
    QTest::mouseMove(vp, QPoint(width / 2 + 40, y));
    QTest::mouseMove(vp, QPoint(width / 2 + 80, y));
    QTest::mouseRelease(vp, Qt::LeftButton, Qt::NoModifier, QPoint(width / 2 + 80, y));
    QVERIFY(vp->camera().pose().spec().eye != camera.eye);
    checkValidation();
}

void CompareModeTests::differenceOfASceneWithItselfIsZero() {
    MainWindow& w = *window_;
    const QString file = test::asset(QStringLiteral("BoxTextured"));
    QVERIFY(test::load(w, file));
    QVERIFY(w.views().setDebugView(QStringLiteral("base-color"), false));
    CompareState& c = w.comparison().state();
    c.setMode(ViewportMode::Difference);
    // Side B: the same file, loaded again as another file is.
    w.comparison().compareWithFile(file);
    QTRY_VERIFY_WITH_TIMEOUT(test::compare_session(w) != nullptr, 30000);
    QCOMPARE(c.comparison().side, SideB::OtherFile);
    QVERIFY(test::compare_session(w) != w.context().sharedSession()); // a second scene
    DifferenceLegend& legend = test::difference_legend(w);
    QVERIFY(legend.isVisible());
    // The numbers are those of the latest completed frame: a few frames later (and
    // at the viewport's size with the legend beside it).
    const auto current = [&w] {
        const DifferenceNumbers& d = w.frames().lastReport().difference;
        return d.valid && d.pixels == std::uint64_t(w.frames().lastFrame().request.width) *
                                          w.frames().lastFrame().request.height;
    };
    QElapsedTimer t;
    t.start();
    while (!current() && t.elapsed() < 30000) {
        w.frames().renderer()->renderAndWait(w.frames().lastFrame(), w.viewport()->vulkanSurface());
        QCoreApplication::processEvents();
    }
    const DifferenceNumbers& n = w.frames().lastReport().difference;
    QVERIFY(n.valid);
    QCOMPARE(n.pixels, std::uint64_t(w.frames().lastFrame().request.width) *
                           w.frames().lastFrame().request.height);
    QCOMPARE(n.mean, 0.0);
    QCOMPARE(n.max, 0.0);
    QCOMPARE(n.over_threshold_percent, 0.0);
    QVERIFY(std::isinf(n.psnr_db));
    const QString text = legend.numbersText();
    QVERIFY2(text.contains(QStringLiteral("mean 0.00")) &&
                 text.contains(QStringLiteral("max 0.00")) && text.contains(QStringLiteral("∞")) &&
                 text.contains(QStringLiteral("0.00%")),
             qPrintable(text));
    // The colour bar is the engine's heat scale: full heat on top, none at the bottom.
    const QImage bar = legend.colourBar();
    const auto top = render::heat_colour(1.0), bottom = render::heat_colour(0.0);
    QCOMPARE(bar.pixel(0, 0), qRgb(top[0], top[1], top[2]));
    QCOMPARE(bar.pixel(0, bar.height() - 1), qRgb(bottom[0], bottom[1], bottom[2]));
    // The same file with its source textures (no BC7): the compression's error, small.
    const SharedSession bc7 = test::compare_session(w);
    w.comparison().compareWithFile(file, true);
    QTRY_VERIFY_WITH_TIMEOUT(test::compare_session(w) != bc7, 30000);
    t.restart();
    double psnr = std::numeric_limits<double>::infinity();
    while (std::isinf(psnr) && t.elapsed() < 30000) {
        w.frames().renderer()->renderAndWait(w.frames().lastFrame(), w.viewport()->vulkanSurface());
        QCoreApplication::processEvents();
        if (current()) psnr = w.frames().lastReport().difference.psnr_db;
    }
    qInfo("BoxTextured base colour, BC7 against source textures: PSNR %.2f dB, max %.1f/255", psnr,
          w.frames().lastReport().difference.max * 255.0);
    QVERIFY2(psnr > 30.0 && psnr < 80.0, qPrintable(QString::number(psnr)));
    QVERIFY(w.frames().lastReport().difference.max > 0.0);
    // Against another view instead: not identical, and the numbers say so.
    c.setSide(SideB::OtherView, view("normal"));
    t.restart();
    double max = 0.0;
    while (max == 0.0 && t.elapsed() < 30000) {
        w.frames().renderer()->renderAndWait(w.frames().lastFrame(), w.viewport()->vulkanSurface());
        QCoreApplication::processEvents();
        max = w.frames().lastReport().difference.max;
    }
    QVERIFY(max > 0.0);
    QVERIFY(!legend.numbersText().contains(QStringLiteral("∞")));
    QCOMPARE(legend.scaleText(), QStringLiteral("≥ 16.0"));
    // The automatic heat scale: the 99.9th percentile of the differing pixels, named.
    c.setHeatScale(0.0f);
    QCOMPARE(legend.scaleText(), QStringLiteral("auto"));
    for (int i = 0; i < 10 && !legend.scaleText().contains(QStringLiteral("(auto)")); ++i) {
        w.frames().renderer()->renderAndWait(w.frames().lastFrame(), w.viewport()->vulkanSurface());
        QCoreApplication::processEvents();
    }
    QVERIFY2(legend.scaleText().contains(QStringLiteral("(auto)")), qPrintable(legend.scaleText()));
    QVERIFY(w.frames().lastReport().difference.heat_max > 0.0);
    QVERIFY(w.frames().lastReport().difference.heat_max <= w.frames().lastReport().difference.max);
    c.setHeatScale(16.0f / 255.0f);
    // Leaving the comparison frees the other file.
    c.setMode(ViewportMode::Raster);
    QVERIFY(!test::compare_session(w));
    QVERIFY(!legend.isVisible());
    checkValidation();
}

QTEST_MAIN(CompareModeTests)
#include "compare_mode_tests.moc"
