#pragma once
// What a scene's textures are prepared for: the three facts of a device that texture
// preparation depends on, as plain data, so that preparation runs on any thread
// (a loader thread) without the device.
#include <memory>
#include <string>

#include <sherpa/scene/scene.h>
#include <sherpa/texture/texture_pipeline.h>

namespace sherpa::tex {

struct TextureTarget {
    // The device samples BC7/BC5: colour and data textures become BC7, normal maps
    // BC5. False: uncompressed RGBA8, and a warning naming the device.
    bool bc = true;
    // BC7 blocks are decoded to RGBA8 after preparation (the same pixels, 4x the
    // memory): a CPU device decodes a whole BC7 block for every texel it fetches
    // (measured 5-7x the frame time of RGBA8 for DamagedHelmet at 720p on lavapipe).
    // BC5 costs the same either way and stays compressed.
    bool cpu_decode = false;
    std::string name; // the device, named in warnings and notices
};

// Runs the texture pipeline for `scene` on the calling thread for `target`: BC7/BC5
// where the target samples them and `options.device_supports_bc` allows (false there
// forces RGBA8 on a device that samples BC: a notice, not a warning), then BC7 decoded
// for a CPU target. Never null; `cancelled` when options.cancel stopped it.
std::shared_ptr<const PreparedTextureSet> prepare_scene_textures(const scene::Scene& scene,
                                                                 const TextureTarget& target,
                                                                 PipelineOptions options);

} // namespace sherpa::tex
