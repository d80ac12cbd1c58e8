// Side B = this file with tangents by another method (issue 18 item 3), under Xvfb
// with the validation layer: the Difference mode's numbers in the tangent view against
// the Lab's tangent family, which counts the corners where each method differs from
// exact MikkTSpace on the same file.
// The engine's headers first: Qt's QVulkanInstance defines VK_NO_PROTOTYPES.
#include <sherpa/lab/family.h>
#include <sherpa/scene/scene_loader.h>

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QVulkanInstance>
#include <QtTest>

#include "command_line.h"
#include "compare_controls.h"
#include "log_dock.h"
#include "main_window.h"
#include "test_assets.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

namespace {

// The tangent family's corners where `method` differs from exact MikkTSpace.
double differing_corners(const QString& file, scene::TangentMethod method) {
    const scene::LoadResult loaded = scene::load_scene(file.toStdString(), lab::lab_load_options());
    if (!loaded) return -1.0;
    const lab::FamilyReport report = lab::make_family("tangents")->run(*loaded.scene, {});
    for (const lab::MethodResult& m : report.methods)
        if (m.method.name == to_string(method))
            if (const lab::ErrorFigure* f = m.error("differing_corners")) return f->value;
    return -1.0;
}

// Duck (no TANGENT, no normal texture: side A would have no tangents) copied with a
// flat normal texture added, so that the glTF rule gives side A exact MikkTSpace.
// The family finds hundreds of corners where welded MikkTSpace differs on it.
QString normal_mapped_duck(const QTemporaryDir& dir) {
    const QString from = QStringLiteral(SHERPA_ASSETS_DIR "/gltf/Duck/glTF/");
    for (const char* name : {"Duck0.bin", "DuckCM.png"})
        if (!QFile::copy(from + QLatin1String(name), dir.filePath(QLatin1String(name)))) return {};
    QImage flat(4, 4, QImage::Format_RGB32);
    flat.fill(qRgb(128, 128, 255));
    if (!flat.save(dir.filePath(QStringLiteral("flat_normal.png")))) return {};
    QFile in(from + QStringLiteral("Duck.gltf"));
    if (!in.open(QIODevice::ReadOnly)) return {};
    QJsonObject gltf = QJsonDocument::fromJson(in.readAll()).object();
    QJsonArray images = gltf[QStringLiteral("images")].toArray();
    images.append(QJsonObject{{QStringLiteral("uri"), QStringLiteral("flat_normal.png")}});
    QJsonArray textures = gltf[QStringLiteral("textures")].toArray();
    textures.append(QJsonObject{{QStringLiteral("source"), images.size() - 1}});
    QJsonArray materials = gltf[QStringLiteral("materials")].toArray();
    QJsonObject material = materials[0].toObject();
    material[QStringLiteral("normalTexture")] =
        QJsonObject{{QStringLiteral("index"), textures.size() - 1}};
    materials[0] = material;
    gltf[QStringLiteral("images")] = images;
    gltf[QStringLiteral("textures")] = textures;
    gltf[QStringLiteral("materials")] = materials;
    const QString path = dir.filePath(QStringLiteral("DuckNormalMapped.gltf"));
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(QJsonDocument(gltf).toJson()) <= 0) return {};
    return path;
}

} // namespace

class TangentCompareTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void commandLineTakesTangents();
    void methodsDifferWhereTheFamilySaysTheyDo_data();
    void methodsDifferWhereTheFamilySaysTheyDo();
    void tangentSideFollowsTheFile();

private:
    // Side B loaded with `method`, then the numbers of a frame at the viewport's size.
    DifferenceNumbers differenceWith(scene::TangentMethod method);
    DifferenceNumbers currentNumbers(); // of a frame drawn after this call
    void checkValidation();

    QTemporaryDir dir_;
    QString duck_; // normal_mapped_duck()
    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_ = 0;
};

void TangentCompareTests::initTestCase() {
    window_ = test::open_validated_window(vulkan_);
    QVERIFY(window_);
    if (!window_->frames().renderer()) QSKIP("no Vulkan device");
    duck_ = normal_mapped_duck(dir_);
    QVERIFY(!duck_.isEmpty());
}

void TangentCompareTests::cleanupTestCase() {
    if (window_) checkValidation();
    window_.reset();
}

void TangentCompareTests::checkValidation() {
    const QString fresh = test::fresh_validation_messages(*window_, seen_);
    QVERIFY2(fresh.isEmpty(), qPrintable(fresh));
}

void TangentCompareTests::commandLineTakesTangents() {
    CommandLine cl;
    QString error;
    for (const scene::TangentMethod m : scene::kAllTangentMethods) {
        const QString side = QStringLiteral("tangents:") + CompareControls::tangentMethodName(m);
        QVERIFY(parse_command_line(
            {QStringLiteral("sherpa"), QStringLiteral("--compare-with"), side}, cl, error));
        QCOMPARE(cl.compare_with, side);
    }
    QVERIFY(!parse_command_line({QStringLiteral("sherpa"), QStringLiteral("--compare-with"),
                                 QStringLiteral("tangents:nope")},
                                cl, error));
    QVERIFY2(error.contains(QStringLiteral("mikktspace-welded")), qPrintable(error));
}

DifferenceNumbers TangentCompareTests::differenceWith(scene::TangentMethod method) {
    MainWindow& w = *window_;
    const SharedSession before = test::compare_session(w);
    w.comparison().compareWithTangents(method);
    QElapsedTimer t;
    t.start();
    SharedSession now = before;
    while ((now == before || !now) && t.elapsed() < 60000) {
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
        now = test::compare_session(w);
    }
    if (now == before) return {};
    // The first load (from Raster) switches to Split with side B set.
    if (!before && w.comparison().state().comparison().mode != ViewportMode::Split) return {};
    w.comparison().state().setMode(ViewportMode::Difference);
    return currentNumbers();
}

DifferenceNumbers TangentCompareTests::currentNumbers() {
    MainWindow& w = *window_;
    // The numbers are those of the latest completed frame: a few frames later.
    const auto current = [&w] {
        const DifferenceNumbers& d = w.frames().lastReport().difference;
        return d.valid && d.pixels == std::uint64_t(w.frames().lastFrame().request.width) *
                                          w.frames().lastFrame().request.height;
    };
    QElapsedTimer t;
    t.start();
    for (int i = 0; i < 4 || (!current() && t.elapsed() < 60000); ++i) {
        w.frames().renderer()->renderAndWait(w.frames().lastFrame(), w.viewport()->vulkanSurface());
        QCoreApplication::processEvents();
    }
    return w.frames().lastReport().difference;
}

void TangentCompareTests::methodsDifferWhereTheFamilySaysTheyDo_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("authored"); // the file has TANGENT: side A keeps it
    QTest::newRow("NormalTangentTest") << test::asset(QStringLiteral("NormalTangentTest")) << false;
    QTest::newRow("NormalTangentMirrorTest")
        << test::asset(QStringLiteral("NormalTangentMirrorTest")) << true;
    QTest::newRow("Duck, normal-mapped") << duck_ << false;
}

void TangentCompareTests::methodsDifferWhereTheFamilySaysTheyDo() {
    QFETCH(QString, file);
    QFETCH(bool, authored);
    MainWindow& w = *window_;
    const QString model = QFileInfo(file).baseName();
    QVERIFY(test::load(w, file));
    QVERIFY(w.views().setDebugView(QStringLiteral("tangent"), false));
    CompareState& c = w.comparison().state();
    QCOMPARE(c.comparison().mode, ViewportMode::Raster); // side B chosen outside a comparison
    // Exact MikkTSpace on side B. Without TANGENT in the file side A is exact
    // MikkTSpace too (the glTF rule): identical. With it, A is the file's tangents,
    // which MikkTSpace reproduces to a small fraction of a degree: under a 1/255 step.
    const DifferenceNumbers exact = differenceWith(scene::TangentMethod::MikkTSpace);
    QVERIFY(exact.valid);
    QCOMPARE(c.comparison().side, SideB::OtherFile);
    // The log says what side A's tangents are (each of these files has one primitive).
    const QString a = authored ? QStringLiteral("1 primitive(s) authored, 0 exact MikkTSpace")
                               : QStringLiteral("0 primitive(s) authored, 1 exact MikkTSpace");
    const QString log = w.docks().log->text();
    const QString last = log.mid(log.lastIndexOf(QStringLiteral("Side A's tangents")));
    QVERIFY2(last.startsWith(QStringLiteral("Side A's tangents: ") + a), qPrintable(last));
    qInfo("%s, tangent view, A (%s) vs B exact MikkTSpace: mean %.5f max %.4f, %.3f%% over 2/255",
          qPrintable(model), authored ? "authored" : "exact MikkTSpace", exact.mean, exact.max,
          exact.over_threshold_percent);
    if (!authored) {
        QCOMPARE(exact.max, 0.0);
        QVERIFY(std::isinf(exact.psnr_db));
    }
    QCOMPARE(exact.over_threshold_percent, 0.0);
    for (const scene::TangentMethod m :
         {scene::TangentMethod::MikkTSpaceWelded, scene::TangentMethod::Lengyel}) {
        const DifferenceNumbers d = differenceWith(m);
        QVERIFY(d.valid);
        const double corners = differing_corners(file, m);
        QVERIFY(corners >= 0.0);
        const double pixels = d.over_threshold_percent / 100.0 * double(d.pixels);
        qInfo("%s, tangent view, A vs B %s: %.0f pixels over 2/255 (%.3f%%), max %.3f; "
              "Lab tangent family: %.0f corners differ from exact MikkTSpace",
              qPrintable(model), qPrintable(CompareControls::tangentMethodName(m)), pixels,
              d.over_threshold_percent, d.max, corners);
        // Nonzero on screen exactly where the family finds differing corners.
        QCOMPARE(pixels > 0.0, corners > 0.0);
        // The bitangent (cross(N, T) * w) moves with the tangent.
        QVERIFY(w.views().setDebugView(QStringLiteral("bitangent"), false));
        const DifferenceNumbers bitangent = currentNumbers();
        QVERIFY(w.views().setDebugView(QStringLiteral("tangent"), false));
        qInfo("  bitangent view: %.3f%% over 2/255", bitangent.over_threshold_percent);
        QCOMPARE(bitangent.over_threshold_percent > 0.0, corners > 0.0);
    }
    // Leaving the comparison frees side B.
    c.setMode(ViewportMode::Raster);
    QVERIFY(!test::compare_session(w));
    checkValidation();
}

void TangentCompareTests::tangentSideFollowsTheFile() {
    MainWindow& w = *window_;
    QVERIFY(test::load(w, test::asset(QStringLiteral("NormalTangentTest"))));
    QVERIFY(differenceWith(scene::TangentMethod::MikkTSpaceWelded).valid);
    // Another scene opened while comparing: side B is that file with the same method.
    QVERIFY(test::load(w, duck_));
    QTRY_VERIFY_WITH_TIMEOUT(test::compare_session(w) && test::compare_session(w)->spec == duck_,
                             30000);
    QVERIFY(w.comparison().state().comparison().comparing());
    QCOMPARE(w.comparison().state().comparison().side, SideB::OtherFile);
    w.comparison().state().setMode(ViewportMode::Raster);
    QVERIFY(!test::compare_session(w));
    checkValidation();
}

QTEST_MAIN(TangentCompareTests)
#include "tangent_compare_tests.moc"
