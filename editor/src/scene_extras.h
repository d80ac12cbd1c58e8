#pragma once
// What the editor computes along with a scene, off the UI thread: texture thumbnails
// (QImage is safe outside the GUI thread, QPixmap is not) and load timings.
#include <QImage>
#include <QString>

#include <functional>
#include <memory>
#include <vector>

#include <sherpa/core/progress.h>
#include <sherpa/scene/scene.h>

namespace sherpa::tex {
struct PreparedTextureSet;
struct PreparedTexture;
} // namespace sherpa::tex

namespace sherpa::editor {

// The texture pipeline's result for one scene (levels for the GPU, and per texture
// its cache state, hash, format, bytes, timings and PSNR).
using PreparedTextures = std::shared_ptr<const tex::PreparedTextureSet>;
// Prepares a scene's textures (see GpuViewport::texturePreparer); null when cancelled.
using TexturePreparer =
    std::function<PreparedTextures(const Scene&, const ProgressCallback&, const CancelToken*)>;

struct SceneExtras {
    std::vector<QImage> thumbnails; // per Scene::textures; null when undecodable
    std::vector<QSize> image_sizes; // per Scene::images, pixel size of the source (0x0 unknown)
    double load_ms = 0.0;           // engine load_scene (parse, geometry, tangents)
    double thumbnails_ms = 0.0;
    // Prepared on the loader thread when the renderer was there to say how; else
    // null and the viewport prepares them when it uploads the scene.
    PreparedTextures textures;
    double textures_ms = 0.0;
};

inline constexpr int kThumbnailSize = 64;

} // namespace sherpa::editor
