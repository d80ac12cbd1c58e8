#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/renderer.h>
#include <sherpa/texture/texture_pipeline.h>

#include "viewport_request.h"
#include "viewport_scene.h"

namespace sherpa::editor {

ViewportScene::ViewportScene(render::Renderer& renderer) : renderer_(renderer) {}

ViewportScene::~ViewportScene() = default;

UploadedScene ViewportScene::load(SharedSession session, const ViewportRequest& frame,
                                  bool missing_checker) {
    // The old scene leaves first (its memory is free for the new one), and the stream
    // policy and missing-texture mode are set before the one upload.
    session_.reset();
    renderer_.unload();
    missing_ =
        missing_checker ? render::MissingTextures::Checker : render::MissingTextures::Neutral;
    all_streams_ = render::needs_all_streams(frame.request);
    session_ = std::move(session);
    upload();
    UploadedScene out;
    if (const render::GpuScene* scene = renderer_.scene())
        out.textureBytes = scene->materials().textures().gpu_bytes();
    if (const render::AccelerationStats* stats = renderer_.resident().acceleration)
        out.acceleration = std::make_shared<const render::AccelerationStats>(*stats);
    out.lightWarnings = renderer_.resident().emissive.warnings;
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

void load_session(render::Renderer& renderer, const SceneSession& session, bool all_streams,
                  render::MissingTextures missing) {
    // No textures prepared (cancelled, no plan): an empty set, so that load() does
    // not run the texture pipeline on this thread.
    PreparedTextures textures = session.textures;
    if (!textures) textures = std::make_shared<const tex::PreparedTextureSet>();
    render::SceneSetup setup;
    setup.streams =
        all_streams ? render::StreamPolicy::AllPresent : render::StreamPolicy::UsedByMaterials;
    setup.missing_textures = missing;
    renderer.load(*session.scene, std::move(textures), setup); // hidden nodes: per present()
}

QStringList ViewportScene::setEnvironment(const render::EnvironmentChoice& choice) {
    std::vector<std::string> warnings;
    auto image = render::make_environment(choice, warnings);
    environment_ =
        image ? std::make_shared<const render::EnvironmentImage>(std::move(*image)) : nullptr;
    renderer_.set_environment(environment_.get());
    // A comparison's side B is lit alike at its next frame (ViewportPresenter).
    QStringList out;
    for (const std::string& w : warnings) out << QString::fromStdString(w);
    return out;
}

void ViewportScene::useStreamsFor(const ViewportRequest& frame) {
    const bool all = render::needs_all_streams(frame.request);
    if (all == all_streams_) return;
    all_streams_ = all;
    upload();
}

} // namespace sherpa::editor
