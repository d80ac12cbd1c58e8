#pragma once
// What the editor computes along with a scene, off the UI thread: texture thumbnails
// (QImage is safe outside the GUI thread, QPixmap is not) and load timings.
#include <QImage>
#include <QString>

#include <functional>
#include <memory>
#include <string>
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
// How the loader prepares a scene's textures: for which device, with which cache
// settings (GpuViewport::texturePlan(); run by prepareTextures()). Plain data; a
// plan without a device prepares nothing (the viewport cannot draw then).
struct TexturePlan {
    bool device = false;      // a device exists
    std::string device_name;  // named in the warning when it cannot sample BC
    bool bc_textures = false; // the device samples BC7/BC5
    bool cpu_device = false;  // a CPU device: BC7 is decoded to RGBA8 before upload
    std::string cache_dir;    // the texture cache; empty: none
    int bc7_level = 0;        // BC7 encoder quality level
};

struct SceneExtras {
    std::vector<QImage> thumbnails; // per Scene::textures; null when undecodable
    std::vector<QSize> image_sizes; // per Scene::images, pixel size of the source (0x0 unknown)
    double load_ms = 0.0;           // engine load_scene (parse, geometry, tangents)
    double thumbnails_ms = 0.0;
    // Prepared on the loader thread for the viewport's device (TexturePlan); null
    // without a device.
    PreparedTextures textures;
    double textures_ms = 0.0;
};

inline constexpr int kThumbnailSize = 64;

} // namespace sherpa::editor
