// Loading a scene end to end under Xvfb: the progress of every stage, a cancelled
// load that keeps the previous scene and leaks nothing, the texture cache's actions and
// a missing texture named in the dock and the log. (The viewport's inspection features
// are in viewport_tests.cpp.)
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QVulkanInstance>
#include <QtTest>

#include "editor_settings.h"
#include "format_values.h"
#include "log_dock.h"
#include "main_window.h"
#include "reload_controller.h"
#include "render_thread.h"
#include "scene_load_job.h"
#include "test_assets.h"
#include "texture_dock.h"
#include "texture_table_model.h"
#include "window_test_support.h"

using namespace sherpa;
using namespace sherpa::editor;

using test::kLoadTimeoutMs;
using test::load;

class LoadingTests : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        window_ = test::open_validated_window(vulkan_);
        QVERIFY(window_);
        QCoreApplication::processEvents();
    }
    void cleanup() {
        // Every test here runs under the Khronos validation layer: any message fails it.
        if (!window_) return;
        const QString fresh = test::fresh_validation_messages(*window_, seen_validation_);
        QVERIFY2(fresh.isEmpty(), qPrintable(fresh));
    }
    void cleanupTestCase() { window_.reset(); }
    void progressReportsEveryStage();
    void cancelDropsTheLoadAndLeaksNothing();
    void textureCacheActions();
    void missingTextureIsNamedInTheDockAndLog();
    void changedFilesAreOfferedOrReloaded();

private:
    bool hasGpu() const { return window_->frames().renderer() != nullptr; }
    QVulkanInstance vulkan_;
    std::unique_ptr<MainWindow> window_;
    qsizetype seen_validation_ = 0;
};

void LoadingTests::progressReportsEveryStage() {
    QSignalSpy progress(&test::scene_loader(*window_), &SceneLoadJob::progress);
    QVERIFY(load(*window_, test::asset(QStringLiteral("DamagedHelmet"))));
    QList<LoadStep> steps;
    int last_textures_done = -1, textures_total = -1;
    for (const QList<QVariant>& args : progress) {
        const auto step = args.at(0).value<LoadStep>();
        if (steps.isEmpty() || steps.back() != step) steps << step;
        if (step == LoadStep::Textures) {
            last_textures_done = args.at(1).toInt();
            textures_total = args.at(2).toInt();
        }
    }
    const QList<LoadStep> expected = {LoadStep::Parse, LoadStep::Geometry, LoadStep::Tangents,
                                      LoadStep::Textures, LoadStep::Idle};
    QCOMPARE(steps, expected);
    QVERIFY(textures_total > 0);
    QCOMPARE(last_textures_done, textures_total); // the per-texture count reaches the end
    if (!hasGpu()) return;
    // The renderer was there: the loader thread prepared the GPU textures (cache,
    // BC7/BC5), and the texture dock shows their records.
    const SceneSession* session = window_->context().session();
    QVERIFY(session && session->textures);
    QCOMPARE(textures_total, 5); // DamagedHelmet: five images in five roles
    const TextureTableModel* m = window_->docks().textures->model();
    const auto cell = [m](int row, int column) { return m->index(row, column).data().toString(); };
    const QStringList states = {QStringLiteral("hit"), QStringLiteral("miss")};
    for (int row = 0; row < m->rowCount(); ++row) {
        QVERIFY2(states.contains(cell(row, TextureTableModel::CacheStateColumn)),
                 qPrintable(cell(row, TextureTableModel::CacheStateColumn)));
        QVERIFY(cell(row, TextureTableModel::FormatColumn).startsWith(QStringLiteral("BC")) ||
                cell(row, TextureTableModel::FormatColumn).startsWith(QStringLiteral("R8G8B8A8")));
        // The hash elided in the middle; all 32 digits on hover and on copy.
        const QString hash = cell(row, TextureTableModel::HashColumn);
        const QString full =
            m->index(row, TextureTableModel::HashColumn).data(format::kExactTextRole).toString();
        QCOMPARE(full.size(), 32);
        QCOMPARE(hash, full.left(8) + QChar(0x2026) + full.right(8));
        QCOMPARE(m->index(row, TextureTableModel::HashColumn).data(Qt::ToolTipRole).toString(),
                 full);
        QVERIFY(cell(row, TextureTableModel::GpuBytesColumn) != QStringLiteral("—"));
        QCOMPARE(cell(row, TextureTableModel::MipsColumn), QStringLiteral("12")); // 2048² chain
    }
    // Loaded again: every texture now comes out of the cache.
    QVERIFY(load(*window_, test::asset(QStringLiteral("DamagedHelmet"))));
    for (int row = 0; row < m->rowCount(); ++row)
        QCOMPARE(cell(row, TextureTableModel::CacheStateColumn), QStringLiteral("hit"));
}

void LoadingTests::cancelDropsTheLoadAndLeaksNothing() {
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    const scene::Scene* before = window_->context().scene();
    // Per-frame buffers (overlay lines, culled ids) are made on first use, per frame
    // in flight: draw a few frames first.
    for (int f = 0; hasGpu() && f < 3; ++f) QVERIFY(test::next_frame(*window_));
    const std::int64_t objects = hasGpu() ? test::gpu_objects(*window_) : -1;
    QSignalSpy loaded(&window_->loads(), &LoadController::sceneLoaded);
    QSignalSpy canceled(&window_->loads(), &LoadController::loadCanceled);
    std::vector<std::uint64_t> heap;
    for (int i = 0; i < 12; ++i) {
        // Cancel as soon as the engine reports its first stage: the worker stops there.
        QMetaObject::Connection c = connect(
            &test::scene_loader(*window_), &SceneLoadJob::progress, this, [this](LoadStep step) {
                if (step == LoadStep::Geometry || step == LoadStep::Tangents)
                    window_->loads().cancelLoad();
            });
        window_->loads().openScene(test::asset(QStringLiteral("DamagedHelmet")));
        QTRY_VERIFY_WITH_TIMEOUT(!test::scene_loader(*window_).running(), kLoadTimeoutMs);
        disconnect(c);
        QTRY_COMPARE_WITH_TIMEOUT(SceneLoadJob::workersInFlight(), 0, kLoadTimeoutMs);
        QCoreApplication::processEvents();
        heap.push_back(test::heap_in_use_kib());
    }
    QCOMPARE(canceled.count(), 12);
    QCOMPARE(loaded.count(), 0);
    QCOMPARE(window_->context().scene(), before); // rolled back: the old scene stays
    QVERIFY(test::progress_text(*window_).contains(QStringLiteral("/4")));
    if (objects >= 0) {
        for (int f = 0; f < 3; ++f) QVERIFY(test::next_frame(*window_));
        QCOMPARE(test::gpu_objects(*window_), objects);
    }
    // Floors of samples, not single samples (see heap_in_use_kib): a DamagedHelmet left
    // behind per cancel is tens of MiB each.
    QVERIFY2(test::floor_of(heap, 8, 12) < test::floor_of(heap, 2, 6) + 32 * 1024,
             "cancelled loads leave memory behind");
    QVERIFY(load(*window_, QStringLiteral("builtin:grid?n=10"))); // and loading still works
}

void LoadingTests::textureCacheActions() {
    if (!hasGpu()) QSKIP("no Vulkan device: no texture upload");
    QTemporaryDir dir; // a cache of this test alone
    const QString before = EditorSettings().get(setting::kCacheDirectory);
    EditorSettings().set(setting::kCacheDirectory, dir.path());
    const TextureTableModel* m = window_->docks().textures->model();
    const auto state = [m](int row) {
        return m->index(row, TextureTableModel::CacheStateColumn).data().toString();
    };
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    QCOMPARE(m->rowCount(), 3);
    for (int row = 0; row < 3; ++row) QCOMPARE(state(row), QStringLiteral("miss"));
    QVERIFY(window_->docks().textures->recompressButton()->isEnabled());
    QVERIFY(window_->docks().textures->clearCacheButton()->isEnabled());
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    for (int row = 0; row < 3; ++row) QCOMPARE(state(row), QStringLiteral("hit"));

    // Recompress texture 0: its file goes, the reload compresses only it again.
    QSignalSpy loaded(&window_->loads(), &LoadController::sceneLoaded);
    window_->loads().recompressTexture(0);
    QVERIFY(loaded.wait(kLoadTimeoutMs));
    QCOMPARE(state(0), QStringLiteral("miss"));
    QCOMPARE(state(1), QStringLiteral("hit"));
    QCOMPARE(state(2), QStringLiteral("hit"));

    // Clear: every KTX2 file of the directory is gone.
    QCOMPARE(window_->loads().clearTextureCache(), 3);
    QVERIFY(QDir(dir.path()).entryList({QStringLiteral("*.ktx2")}, QDir::Files).isEmpty());
    EditorSettings().set(setting::kCacheDirectory, before);
}

// A base-colour image that does not exist: the dock says "missing: FILE" (not a
// cache state), the log names the file and the material slots.
void LoadingTests::missingTextureIsNamedInTheDockAndLog() {
    if (!hasGpu()) QSKIP("no Vulkan device: textures are prepared for the GPU");
    QVERIFY(load(*window_, QStringLiteral(SHERPA_TEST_DATA_DIR "/missing_texture.gltf")));
    QVERIFY(test::next_frame(*window_));
    const TextureTableModel* m = window_->docks().textures->model();
    QCOMPARE(m->rowCount(), 1);
    QCOMPARE(m->index(0, TextureTableModel::CacheStateColumn).data().toString(),
             QStringLiteral("missing: does_not_exist.png"));
    QCOMPARE(m->index(0, TextureTableModel::SizeColumn).data().toString(),
             QStringLiteral("missing: does_not_exist.png"));
    const QString tip =
        m->index(0, TextureTableModel::CacheStateColumn).data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(QStringLiteral("material 'Quad' baseColorTexture, occlusionTexture")),
             qPrintable(tip));
    QVERIFY2(window_->docks().log->text().contains(
                 QStringLiteral("texture missing: " SHERPA_TEST_DATA_DIR "/does_not_exist.png")),
             qPrintable(window_->docks().log->text()));
}

// Reload on change: a copy of BoxTextured (its .gltf, .bin and PNG) open; a change
// of its buffer brings the offer to reload, whose Reload button reloads it with the
// camera kept; with Reload Automatically, a change of its image reloads at once.
void LoadingTests::changedFilesAreOfferedOrReloaded() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QDir source(QFileInfo(test::asset(QStringLiteral("BoxTextured"))).absolutePath());
    for (const QString& f : source.entryList(QDir::Files))
        QVERIFY(QFile::copy(source.filePath(f), dir.filePath(f)));
    const QString gltf = dir.filePath(QStringLiteral("BoxTextured.gltf"));
    QVERIFY(load(*window_, gltf));
    const QStringList watched = test::reload_controller(*window_).watchedFiles();
    const QString bin =
        QFileInfo(dir.filePath(QStringLiteral("BoxTextured0.bin"))).absoluteFilePath();
    const QString png =
        QFileInfo(dir.filePath(QStringLiteral("CesiumLogoFlat.png"))).absoluteFilePath();
    QVERIFY2(watched.contains(QFileInfo(gltf).absoluteFilePath()) && watched.contains(bin) &&
                 watched.contains(png),
             qPrintable(watched.join(QLatin1Char(' '))));

    test::reload_controller(*window_).setReloadAutomatically(false);
    window_->viewport()->camera().orbit(30.0f, 10.0f);
    const glm::vec3 eye = window_->viewport()->camera().pose().eye();
    QSignalSpy loaded(&window_->loads(), &LoadController::sceneLoaded);
    const auto touch = [](const QString& path) { // rewritten as an exporter does
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly)) return false;
        const QByteArray bytes = f.readAll();
        f.close();
        QFile out(path);
        return out.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
               out.write(bytes) == bytes.size();
    };
    QVERIFY(touch(bin));
    QMessageBox* offer = nullptr;
    QTRY_VERIFY_WITH_TIMEOUT(
        (offer = window_->findChild<QMessageBox*>(QStringLiteral("reloadOffer"))) &&
            offer->isVisible(),
        10000);
    QVERIFY(offer->text().contains(QStringLiteral("BoxTextured0.bin")));
    QCOMPARE(loaded.count(), 0); // offered, not done
    QAbstractButton* reload = nullptr;
    for (QAbstractButton* b : offer->buttons())
        if (offer->buttonRole(b) == QMessageBox::AcceptRole) reload = b;
    QVERIFY(reload);
    reload->click();
    QTRY_VERIFY_WITH_TIMEOUT(loaded.count() == 1, kLoadTimeoutMs);
    QCOMPARE(window_->viewport()->camera().pose().eye(), eye); // the view kept

    test::reload_controller(*window_).setReloadAutomatically(true);
    QVERIFY(EditorSettings().get(setting::kReloadAutomatically)); // remembered
    QVERIFY(touch(png));
    QTRY_VERIFY_WITH_TIMEOUT(loaded.count() == 2, kLoadTimeoutMs);
    QVERIFY(!window_->findChild<QMessageBox*>(QStringLiteral("reloadOffer")) ||
            !window_->findChild<QMessageBox*>(QStringLiteral("reloadOffer"))->isVisible());
    test::reload_controller(*window_).setReloadAutomatically(false);
    QVERIFY(load(*window_, QStringLiteral("builtin:default")));
    QVERIFY(test::reload_controller(*window_).watchedFiles().isEmpty()); // nothing on disk to watch
}

QTEST_MAIN(LoadingTests)
#include "loading_tests.moc"
