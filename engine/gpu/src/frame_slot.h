#pragma once
// Per-frame-in-flight resources of the Renderer (private to the GPU layer).
#include <sherpa/gpu/camera.h>
#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_structs.h>
#include <sherpa/gpu/renderer.h>

namespace sherpa::gpu {

// Timestamps written between passes; pass i spans [i, i + 1].
inline constexpr const char* kPassNames[] = {"shadows",    "depth_prepass", "opaque",
                                             "alpha_mask", "alpha_blend",   "overlays"};
inline constexpr std::uint32_t kTimestampCount = std::size(kPassNames) + 1;

struct Renderer::FrameSlot {
    explicit FrameSlot(Context& context) : recorder(context) {}
    CommandRecorder recorder;
    BufferHandle frame_data; // GPUFrameData, host-visible
    BufferHandle lines;      // overlay line vertices, host-visible, grown on demand
    VkDeviceSize lines_capacity = 0;
    UniqueQueryPool timestamps, statistics;
    std::uint64_t submission = 0; // timeline value of the last frame recorded here
    bool has_results = false;
    bool shadows_rendered = false;
    std::uint64_t draw_calls = 0;
    CameraView camera;
    GPUPushConstants push_base{}; // scene-wide addresses for this frame
};

struct Renderer::Lighting {
    // Only bounds, lights and cameras: what camera and light resolution needs.
    Scene info;
};

} // namespace sherpa::gpu
