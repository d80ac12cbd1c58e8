#include "scene_load_job.h"

#include "gpu_viewport.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QImageReader>
#include <QPointer>
#include <QtConcurrent/QtConcurrentMap>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/bc5_normal.h>
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/prepared_levels.h>
#include <sherpa/texture/texel_budget.h>
#include <sherpa/texture/texture_pipeline.h>

namespace sherpa::editor {

struct SceneLoadJob::State {
    core::CancelToken cancel;
    QElapsedTimer clock;
    // Where the worker is; report() posts a progress signal when it changes enough.
    std::atomic<int> step{static_cast<int>(LoadStep::Parse)}, done{0}, total{0};
    std::function<void(LoadStep, int, int)> post; // null for synchronous loads

    void report(LoadStep s, std::size_t d, std::size_t t) {
        const int di = static_cast<int>(d), ti = static_cast<int>(t);
        const int old_step = step.exchange(static_cast<int>(s));
        const int old_done = done.exchange(di);
        total = ti;
        // Stage changes and ends always; counts in steps of about 1%.
        const bool changed = old_step != static_cast<int>(s) || di == ti || di == 0 ||
                             (ti > 0 && di * 100 / ti != old_done * 100 / ti);
        if (post && changed) post(s, di, ti);
    }
    // The whole load, from start() to the answer, into the session's timings.
    void stamp(const LoadOutcome& out) const {
        if (out.session)
            out.session->timings.total_ms = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    }
};

namespace {
std::atomic<int> g_in_flight{0};
} // namespace

namespace {

QImage decode_thumbnail(const scene::Scene& scene, const scene::TextureRecord& texture,
                        QSize& source_size) {
    if (texture.image < 0 || static_cast<std::size_t>(texture.image) >= scene.images.size())
        return {};
    const scene::ImageRecord& image = scene.images[static_cast<std::size_t>(texture.image)];
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
    // A header declaring more than the texel budget is a bomb, named by the texture
    // pipeline; Qt's own allocation limit may not apply to a scaled JPEG decode.
    std::string too_large;
    if (source_size.isValid() &&
        !tex::check_texel_budget(std::uint64_t(source_size.width()),
                                 std::uint64_t(source_size.height()), {}, too_large)) {
        source_size = {};
        return {};
    }
    if (source_size.isValid())
        // JPEG decodes straight to a reduced size (DCT scaling): 2048² in a few ms.
        reader.setScaledSize(
            source_size.scaled(kThumbnailSize, kThumbnailSize, Qt::KeepAspectRatio));
    QImage thumb = reader.read();
    if (thumb.isNull()) source_size = {};
    return thumb;
}

// The thumbnail from the prepared (cached) texture that texture `t` reaches: its
// smallest mip level at least kThumbnailSize wide or high, decoded from its blocks
// if need be. Null when the texture was not prepared (no material uses it) or failed.
QImage prepared_thumbnail(const tex::PreparedTextureSet* set, std::int32_t t, QSize& source_size) {
    if (!set) return {};
    for (const tex::PreparedTexture& p : set->textures) {
        if (p.failed || p.levels.empty() ||
            std::find(p.textures.begin(), p.textures.end(), t) == p.textures.end())
            continue;
        std::uint32_t level = 0;
        while (level + 1 < p.levels.size() &&
               std::max(tex::mip_extent(p.width, level + 1),
                        tex::mip_extent(p.height, level + 1)) >= std::uint32_t(kThumbnailSize))
            ++level;
        const std::uint32_t w = tex::mip_extent(p.width, level),
                            h = tex::mip_extent(p.height, level);
        const std::vector<std::uint8_t> rgba = tex::decode_level_rgba8(p, level);
        if (rgba.empty()) return {};
        source_size = QSize(static_cast<int>(p.width), static_cast<int>(p.height));
        // copy(): scaled() to the size it already has would share `rgba`, freed on return.
        return QImage(rgba.data(), int(w), int(h), int(w) * 4, QImage::Format_RGBA8888)
            .copy()
            .scaled(kThumbnailSize, kThumbnailSize, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    }
    return {};
}

LoadOutcome run_load(const QString& spec, const std::optional<tex::TextureTarget>& target,
                     const tex::PipelineOptions& textures, SceneLoadJob::State* state,
                     std::optional<scene::TangentMethod> tangents = std::nullopt);

} // namespace

SceneLoadJob::SceneLoadJob(QObject* parent) : QObject(parent) {}

SceneLoadJob::~SceneLoadJob() {
    if (watcher_) {
        if (state_) state_->cancel.cancel();
        watcher_->disconnect(this);
        watcher_->waitForFinished();
    }
}

int SceneLoadJob::workersInFlight() {
    return g_in_flight.load();
}

void SceneLoadJob::start(const QString& spec, const std::optional<tex::TextureTarget>& target,
                         const tex::PipelineOptions& textures,
                         std::optional<scene::TangentMethod> tangents) {
    cancel();
    spec_ = spec;
    state_ = std::make_shared<State>();
    state_->clock.start();
    // A fresh watcher per load: the one of a cancelled load may still be running and
    // deletes itself when its worker ends.
    watcher_ = new QFutureWatcher<LoadOutcome>(this);
    connect(watcher_, &QFutureWatcher<LoadOutcome>::finished, this, &SceneLoadJob::onFinished);
    std::shared_ptr<State> state = state_;
    // Reports travel as queued calls; those of a load cancelled meanwhile are dropped.
    QPointer<SceneLoadJob> self(this);
    State* raw = state.get();
    state->post = [self, raw](LoadStep step, int done, int total) {
        // Posted to the application (always alive), checked there: the job may be gone.
        QMetaObject::invokeMethod(qApp, [self, raw, step, done, total] {
            if (self && self->state_.get() == raw) Q_EMIT self->progress(step, done, total);
        });
    };
    ++g_in_flight;
    watcher_->setFuture(QtConcurrent::run([spec, state, target, textures, tangents] {
        LoadOutcome out;
        // Nothing may escape the worker: the future would rethrow it in the UI thread.
        try {
            out = run_load(spec, target, textures, state.get(), tangents);
        } catch (const std::exception& e) {
            out = {};
            out.error = spec + QStringLiteral(": ") + QString::fromUtf8(e.what());
        }
        --g_in_flight;
        return out;
    }));
    Q_EMIT progress(LoadStep::Parse, 0, 1);
}

void SceneLoadJob::cancel() {
    if (!state_) return;
    state_->cancel.cancel();
    QFutureWatcher<LoadOutcome>* old = watcher_;
    old->disconnect(this);
    connect(old, &QFutureWatcher<LoadOutcome>::finished, old, &QObject::deleteLater);
    if (old->isFinished()) old->deleteLater();
    watcher_ = nullptr;
    state_.reset();
    Q_EMIT progress(LoadStep::Idle, 0, 0);
    Q_EMIT canceled(spec_);
}

void SceneLoadJob::onFinished() {
    const LoadOutcome outcome = watcher_->result();
    state_->stamp(outcome);
    watcher_->deleteLater();
    watcher_ = nullptr;
    state_.reset();
    Q_EMIT progress(LoadStep::Idle, 0, 0);
    if (outcome.cancelled)
        Q_EMIT canceled(spec_);
    else if (outcome.session)
        Q_EMIT loaded(outcome.session);
    else
        Q_EMIT failed(spec_, outcome.error);
}

LoadOutcome SceneLoadJob::loadNow(const QString& spec) {
    State state;
    state.clock.start();
    LoadOutcome out = run_load(spec, std::nullopt, {}, &state);
    state.stamp(out);
    return out;
}

namespace {

LoadOutcome run_load(const QString& spec, const std::optional<tex::TextureTarget>& target,
                     const tex::PipelineOptions& textures, SceneLoadJob::State* state,
                     std::optional<scene::TangentMethod> tangents) {
    LoadOutcome out;
    QElapsedTimer clock;
    clock.start();
    scene::LoadOptions options;
    // From the file's own vertices: regenerating on a loaded scene would see the
    // vertices exact MikkTSpace already split, where a welded method welds nothing.
    if (tangents) {
        options.tangents.method = *tangents;
        options.tangents.regenerate = true;
    }
    options.cancel = &state->cancel;
    options.progress = [state](sherpa::scene::LoadStage stage, std::size_t done,
                               std::size_t total) {
        const LoadStep step = stage == sherpa::scene::LoadStage::Parse      ? LoadStep::Parse
                              : stage == sherpa::scene::LoadStage::Geometry ? LoadStep::Geometry
                                                                            : LoadStep::Tangents;
        state->report(step, done, total);
    };
    scene::LoadResult result = scene::load_scene(spec.toStdString(), options);
    if (!result) {
        out.cancelled = result.cancelled;
        out.error = QString::fromStdString(result.error);
        return out;
    }
    auto session = std::make_shared<SceneSession>();
    session->spec = spec;
    session->timings.engine_ms = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    const scene::Scene& scene = *result.scene;
    // GPU textures first (texture cache, BC7/BC5), counted per prepared texture: the
    // thumbnails then come from their small mip levels instead of decoding sources.
    clock.restart();
    if (target && !state->cancel.cancelled()) {
        state->report(LoadStep::Textures, 0, 1);
        tex::PipelineOptions pipeline = textures;
        pipeline.progress = [state](std::size_t done, std::size_t total) {
            state->report(LoadStep::Textures, done, total);
        };
        pipeline.cancel = &state->cancel;
        PreparedTextures set = tex::prepare_scene_textures(scene, *target, std::move(pipeline));
        if (!set->cancelled) session->textures = std::move(set);
        session->timings.textures_ms = static_cast<double>(clock.nsecsElapsed()) / 1e6;
        clock.restart();
        if (state->cancel.cancelled()) {
            out.cancelled = true; // the scene and textures are dropped here
            out.error = QStringLiteral("cancelled");
            return out;
        }
    }
    state->report(LoadStep::Textures, 0, scene.textures.size());
    std::atomic<std::size_t> textures_done{0};
    session->thumbnails.resize(scene.textures.size());
    std::vector<QSize> sizes(scene.textures.size());
    // Textures decode independently: spread them over the pool, counting as they finish.
    std::vector<int> order(scene.textures.size());
    std::iota(order.begin(), order.end(), 0);
    QtConcurrent::blockingMap(order, [&](int i) {
        if (state->cancel.cancelled()) return;
        const auto t = static_cast<std::size_t>(i);
        QImage thumb = prepared_thumbnail(session->textures.get(), i, sizes[t]);
        session->thumbnails[t] =
            thumb.isNull() ? decode_thumbnail(scene, scene.textures[t], sizes[t]) : thumb;
        state->report(LoadStep::Textures, ++textures_done, scene.textures.size());
    });
    if (state->cancel.cancelled()) {
        out.cancelled = true; // the scene and thumbnails are dropped here
        out.error = QStringLiteral("cancelled");
        return out;
    }
    session->image_sizes.resize(scene.images.size());
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        const std::int32_t image = scene.textures[t].image;
        if (image >= 0 && static_cast<std::size_t>(image) < session->image_sizes.size())
            session->image_sizes[static_cast<std::size_t>(image)] = sizes[t];
    }
    session->timings.thumbnails_ms = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    session->scene = std::move(result.scene);
    out.session = std::move(session);
    return out;
}

} // namespace

} // namespace sherpa::editor
