#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/renderer.h>
#include <sherpa/texture/texture_pipeline.h>

#include "viewport_request.h"
#include "viewport_scene.h"

namespace sherpa::editor {

ViewportScene::ViewportScene(gpu::Renderer& renderer) : renderer_(renderer) {}

ViewportScene::~ViewportScene() = default;

UploadedScene ViewportScene::load(SharedSession session, const ViewportRequest& frame,
                                  bool missing_checker) {
    // The old scene leaves first (its memory is free for the new one), and the stream
    // policy and missing-texture mode are set before the one upload.
    session_.reset();
    renderer_.unload();
    missing_ = missing_checker ? gpu::MissingTextures::Checker : gpu::MissingTextures::Neutral;
    all_streams_ = gpu::needs_all_streams(frame.request);
    session_ = std::move(session);
    upload();
    UploadedScene out;
    if (const gpu::GpuScene* scene = renderer_.scene())
        out.textureBytes = scene->materials().textures().gpu_bytes();
    if (const gpu::AccelerationStats* stats = renderer_.resident().acceleration)
        out.acceleration = std::make_shared<const gpu::AccelerationStats>(*stats);
    return out;
}

// The current scene to the GPU with the current stream policy.
void ViewportScene::upload() {
    if (!session_) {
        renderer_.unload();
        return;
    }
    load_session(renderer_, *session_, all_streams_, missing_);
}

void load_session(gpu::Renderer& renderer, const SceneSession& session, bool all_streams,
                  gpu::MissingTextures missing) {
    // No textures prepared (cancelled, no plan): an empty set, so that load() does
    // not run the texture pipeline on this thread.
    PreparedTextures textures = session.textures;
    if (!textures) textures = std::make_shared<const tex::PreparedTextureSet>();
    gpu::SceneSetup setup;
    setup.streams =
        all_streams ? gpu::StreamPolicy::AllPresent : gpu::StreamPolicy::UsedByMaterials;
    setup.missing_textures = missing;
    renderer.load(*session.scene, std::move(textures), setup); // hidden nodes: per present()
}

QStringList ViewportScene::setEnvironment(const gpu::EnvironmentChoice& choice) {
    std::vector<std::string> warnings;
    auto image = gpu::make_environment(choice, warnings);
    environment_ =
        image ? std::make_shared<const gpu::EnvironmentImage>(std::move(*image)) : nullptr;
    renderer_.set_environment(environment_.get());
    // A comparison's side B is lit alike at its next frame (ViewportPresenter).
    QStringList out;
    for (const std::string& w : warnings) out << QString::fromStdString(w);
    return out;
}

void ViewportScene::useStreamsFor(const ViewportRequest& frame) {
    const bool all = gpu::needs_all_streams(frame.request);
    if (all == all_streams_) return;
    all_streams_ = all;
    upload();
}

} // namespace sherpa::editor
