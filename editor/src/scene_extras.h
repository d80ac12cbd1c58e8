#pragma once
// What the editor computes along with a scene, off the UI thread: texture thumbnails
// (QImage is safe outside the GUI thread, QPixmap is not) and load timings.
#include <QImage>
#include <QString>

#include <vector>

namespace sherpa::editor {

struct SceneExtras {
    std::vector<QImage> thumbnails; // per Scene::textures; null when undecodable
    std::vector<QSize> image_sizes; // per Scene::images, pixel size of the source (0x0 unknown)
    double load_ms = 0.0;           // engine load_scene (parse, geometry, tangents)
    double thumbnails_ms = 0.0;
};

inline constexpr int kThumbnailSize = 64;

} // namespace sherpa::editor
