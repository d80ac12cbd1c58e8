#include "scene_load_job.h"

#include <QElapsedTimer>
#include <QtConcurrent/QtConcurrentRun>

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
    QImage full;
    if (!image.pixels.empty() && image.width > 0 && image.height > 0) {
        // Built-in scenes generate raw RGBA8; wrap it without copying, scale copies.
        full = QImage(image.pixels.data(), static_cast<int>(image.width),
                      static_cast<int>(image.height), static_cast<int>(image.width) * 4,
                      QImage::Format_RGBA8888);
    } else if (!image.encoded.empty()) {
        full = QImage::fromData(image.encoded.data(), static_cast<int>(image.encoded.size()));
    }
    if (full.isNull()) return {};
    source_size = full.size();
    return full.scaled(kThumbnailSize, kThumbnailSize, Qt::KeepAspectRatio,
                       Qt::SmoothTransformation);
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
    extras->image_sizes.resize(scene.images.size());
    for (std::size_t i = 0; i < scene.textures.size() && !state->cancel; ++i) {
        QSize size;
        extras->thumbnails[i] = decode_thumbnail(scene, scene.textures[i], size);
        const std::int32_t image = scene.textures[i].image;
        if (image >= 0 && static_cast<std::size_t>(image) < extras->image_sizes.size())
            extras->image_sizes[static_cast<std::size_t>(image)] = size;
        state->done = static_cast<int>(i + 1);
    }
    extras->thumbnails_ms = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    out.scene = std::move(result.scene);
    out.extras = std::move(extras);
    return out;
}

} // namespace

} // namespace sherpa::editor
