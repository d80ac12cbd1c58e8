#pragma once
// The scene on the viewport's GPU: the session the renderer has uploaded, with the
// stream policy, missing-texture mode and environment it was uploaded and lit with.
// Side B of a comparison (ViewportPresenter) is loaded and lit alike from them.
#include <QStringList>

#include <memory>
#include <string>
#include <vector>

#include <sherpa/render/environment.h>
#include <sherpa/render/scene_setup.h>

#include "scene_session.h"

namespace sherpa::scene {
struct Scene;
} // namespace sherpa::scene

namespace sherpa::render {
struct AccelerationStats;
class Renderer;
} // namespace sherpa::render

namespace sherpa::editor {

struct ViewportRequest;

// What an upload put on the GPU, for the docks.
struct UploadedScene {
    std::uint64_t textureBytes = 0; // the scene's textures
    // A copy of the scene's BLAS/TLAS statistics; null without ray tracing or a scene.
    std::shared_ptr<const render::AccelerationStats> acceleration;
    // Why the path tracer samples some or all of the scene's emitters by BSDF sampling
    // only (render::EmissiveLightStats::warnings); empty without ray tracing.
    std::vector<std::string> lightWarnings;
};

class ViewportScene {
public:
    explicit ViewportScene(render::Renderer& renderer);
    ~ViewportScene();
    ViewportScene(const ViewportScene&) = delete;
    ViewportScene& operator=(const ViewportScene&) = delete;

    // Uploads the session's scene with the textures the loader prepared for it (none:
    // uploaded without textures), the previous scene unloaded first; null unloads. The
    // streams are those the view and overlays of `frame` read (useStreamsFor()); slots
    // whose texture is missing or undecodable show a magenta/black checker in colour
    // slots (`missing_checker`) or the glTF defaults. The session stays alive while its
    // scene is on the GPU. (GpuViewport::load() is the way in: it drops what the
    // docks read back of the old scene first.)
    UploadedScene load(SharedSession session, const ViewportRequest& frame, bool missing_checker);
    // The streams the view and overlays of `frame` read: a debug view of streams no
    // material reads uploads the scene again with every stream (when the view changes,
    // never per frame).
    void useStreamsFor(const ViewportRequest& frame);
    // The environment lighting lit frames: made on the GPU now (prefiltered), replacing
    // the one before; Kind::None removes it. Returns the warnings (an unreadable file
    // and the room used instead, NaN texels, ...).
    QStringList setEnvironment(const render::EnvironmentChoice& choice);

    // The session on the GPU (null: none) and its scene.
    const SharedSession& session() const { return session_; }
    const scene::Scene* scene() const { return session_ ? session_->scene.get() : nullptr; }
    // Every stream uploaded (a view asked for more than the materials read).
    bool allStreams() const { return all_streams_; }
    render::MissingTextures missingTextures() const { return missing_; }
    // The environment image lit frames are lit by (null: none).
    const std::shared_ptr<const render::EnvironmentImage>& environment() const {
        return environment_;
    }

private:
    void upload();

    render::Renderer& renderer_;
    SharedSession session_; // on the GPU: its scene and prepared textures
    bool all_streams_ = false;
    render::MissingTextures missing_ = render::MissingTextures::Checker; // load()
    std::shared_ptr<const render::EnvironmentImage> environment_;
};

// Loads `session` into `renderer` (side A's upload and side B's): every stream with
// `all_streams`, else those its materials use; missing textures drawn as `missing`.
void load_session(render::Renderer& renderer, const SceneSession& session, bool all_streams,
                  render::MissingTextures missing);

} // namespace sherpa::editor
