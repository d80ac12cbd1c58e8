#include "scene_load_job.h"

#include <QBuffer>
#include <QElapsedTimer>
#include <QImageReader>
#include <QtConcurrent/QtConcurrentMap>
#include <QtConcurrent/QtConcurrentRun>
#include <numeric>

#include <sherpa/scene/scene_loader.h>

namespace sherpa::editor {

struct SceneLoadJob::State {
    std::atomic<bool> cancel{false};
    std::atomic<int> stage{static_cast<int>(LoadStage::Loading)};
    std::atomic<int> done{0}, total{0};
    QElapsedTimer clock;
};

namespace {

QImage decode_thumbnail(const Scene& scene, const TextureRecord& texture, QSize& source_size) {
    if (texture.image < 0 || static_cast<std::size_t>(texture.image) >= scene.images.size())
        return {};
    const ImageRecord& image = scene.images[static_cast<std::size_t>(texture.image)];
    if (!image.pixels.empty() && image.width > 0 && image.height > 0) {
        // Built-in scenes generate raw RGBA8; wrap it without copying, scale copies.
        source_size = QSize(static_cast<int>(image.width), static_cast<int>(image.height));
        return QImage(image.pixels.data(), source_size.width(), source_size.height(),
                      source_size.width() * 4, QImage::Format_RGBA8888)
            .scaled(kThumbnailSize, kThumbnailSize, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    }
    if (image.encoded.empty()) return {};
    const QByteArray bytes =
        QByteArray::fromRawData(reinterpret_cast<const char*>(image.encoded.data()),
                                static_cast<qsizetype>(image.encoded.size()));
    QBuffer buffer;
    buffer.setData(bytes);
    buffer.open(QIODevice::ReadOnly);
    QImageReader reader(&buffer);
    source_size = reader.size(); // from the header, no decode
    if (source_size.isValid())
        // JPEG decodes straight to a reduced size (DCT scaling): 2048² in a few ms.
        reader.setScaledSize(
            source_size.scaled(kThumbnailSize, kThumbnailSize, Qt::KeepAspectRatio));
    QImage thumb = reader.read();
    if (thumb.isNull()) source_size = {};
    return thumb;
}

LoadOutcome run_load(const QString& spec, SceneLoadJob::State* state);

} // namespace

SceneLoadJob::SceneLoadJob(QObject* parent) : QObject(parent) {
    poll_.setInterval(50);
    connect(&poll_, &QTimer::timeout, this, &SceneLoadJob::pollProgress);
}

SceneLoadJob::~SceneLoadJob() {
    if (watcher_) {
        if (state_) state_->cancel = true;
        watcher_->disconnect(this);
        watcher_->waitForFinished();
    }
}

void SceneLoadJob::start(const QString& spec) {
    cancel();
    spec_ = spec;
    state_ = std::make_shared<State>();
    state_->clock.start();
    // A fresh watcher per load: the one of a cancelled load may still be running and
    // deletes itself when its worker ends.
    watcher_ = new QFutureWatcher<LoadOutcome>(this);
    connect(watcher_, &QFutureWatcher<LoadOutcome>::finished, this, &SceneLoadJob::onFinished);
    std::shared_ptr<State> state = state_;
    watcher_->setFuture(QtConcurrent::run([spec, state] { return run_load(spec, state.get()); }));
    poll_.start();
    Q_EMIT progress(LoadStage::Loading, 0, 0);
}

void SceneLoadJob::cancel() {
    if (!state_) return;
    state_->cancel = true;
    QFutureWatcher<LoadOutcome>* old = watcher_;
    old->disconnect(this);
    connect(old, &QFutureWatcher<LoadOutcome>::finished, old, &QObject::deleteLater);
    if (old->isFinished()) old->deleteLater();
    watcher_ = nullptr;
    state_.reset();
    poll_.stop();
    Q_EMIT canceled(spec_);
}

void SceneLoadJob::pollProgress() {
    if (!state_) return;
    Q_EMIT progress(static_cast<LoadStage>(state_->stage.load()), state_->done.load(),
                    state_->total.load());
}

void SceneLoadJob::onFinished() {
    poll_.stop();
    const LoadOutcome outcome = watcher_->result();
    const double ms = static_cast<double>(state_->clock.nsecsElapsed()) / 1e6;
    watcher_->deleteLater();
    watcher_ = nullptr;
    state_.reset();
    Q_EMIT progress(LoadStage::Idle, 0, 0);
    if (outcome.scene)
        Q_EMIT loaded(spec_, outcome, ms);
    else
        Q_EMIT failed(spec_, outcome.error);
}

LoadOutcome SceneLoadJob::loadNow(const QString& spec) {
    State state;
    state.clock.start();
    return run_load(spec, &state);
}

namespace {

LoadOutcome run_load(const QString& spec, SceneLoadJob::State* state) {
    LoadOutcome out;
    QElapsedTimer clock;
    clock.start();
    LoadResult result = load_scene(spec.toStdString());
    if (!result) {
        out.error = QString::fromStdString(result.error);
        return out;
    }
    auto extras = std::make_shared<SceneExtras>();
    extras->load_ms = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    const Scene& scene = *result.scene;
    state->stage = static_cast<int>(LoadStage::Textures);
    state->total = static_cast<int>(scene.textures.size());
    clock.restart();
    extras->thumbnails.resize(scene.textures.size());
    std::vector<QSize> sizes(scene.textures.size());
    // Textures decode independently: spread them over the pool, counting as they finish.
    std::vector<int> order(scene.textures.size());
    std::iota(order.begin(), order.end(), 0);
    QtConcurrent::blockingMap(order, [&](int i) {
        if (state->cancel) return;
        const auto t = static_cast<std::size_t>(i);
        extras->thumbnails[t] = decode_thumbnail(scene, scene.textures[t], sizes[t]);
        ++state->done;
    });
    extras->image_sizes.resize(scene.images.size());
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        const std::int32_t image = scene.textures[t].image;
        if (image >= 0 && static_cast<std::size_t>(image) < extras->image_sizes.size())
            extras->image_sizes[static_cast<std::size_t>(image)] = sizes[t];
    }
    extras->thumbnails_ms = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    out.scene = std::move(result.scene);
    out.extras = std::move(extras);
    return out;
}

} // namespace

} // namespace sherpa::editor
