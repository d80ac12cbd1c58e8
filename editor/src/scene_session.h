#pragma once
// A loaded scene as one value: the engine's Scene with everything the editor made for
// it off the UI thread (the textures prepared for the device, thumbnails, source image
// sizes, timings). The loader builds it, EditorContext owns the current one and its
// one sceneReady signal hands it to the docks (they read it) and to the viewport (it
// uploads it and keeps it alive while on the GPU). Immutable once made: shared, never
// copied, and swapped in one step.
#include <QImage>
#include <QString>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <sherpa/core/progress.h>
#include <sherpa/scene/scene.h>
#include <sherpa/texture/texture_target.h>

namespace sherpa::tex {
struct PreparedTextureSet;
struct PreparedTexture;
} // namespace sherpa::tex

namespace sherpa::editor {

// The texture pipeline's result for one scene (levels for the GPU, and per texture
// its cache state, hash, format, bytes, timings and PSNR).
using PreparedTextures = std::shared_ptr<const tex::PreparedTextureSet>;
// Where a load's time went (the log says it after each load).
struct LoadTimings {
    double engine_ms = 0.0;     // engine load_scene (parse, geometry, tangents)
    double textures_ms = 0.0;   // the texture pipeline (cache, BC7/BC5) for the device
    double thumbnails_ms = 0.0; // thumbnails and source sizes
    double total_ms = 0.0;      // SceneLoadJob::start() to the loaded scene on the GUI thread
};

struct SceneSession {
    QString spec;                              // what was opened: a path or a built-in spec
    std::shared_ptr<const scene::Scene> scene; // never null
    // Prepared on the loader thread for the viewport's device (its
    // tex::TextureTarget); null without a device.
    PreparedTextures textures;
    std::vector<QImage> thumbnails; // per Scene::textures; null when undecodable
    std::vector<QSize> image_sizes; // per Scene::images, pixel size of the source (0x0 unknown)
    LoadTimings timings;
};
using SharedSession = std::shared_ptr<const SceneSession>;

inline constexpr int kThumbnailSize = 64;

} // namespace sherpa::editor
