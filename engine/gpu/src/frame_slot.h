#pragma once
// Per-frame-in-flight resources of the Renderer (private to the GPU layer).
#include <sherpa/gpu/camera.h>
#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_culling.h>
#include <sherpa/gpu/gpu_structs.h>
#include <sherpa/gpu/renderer.h>
#include <sherpa/scene/culling_passes.h>

namespace sherpa::gpu {

// Timestamps written between passes; pass i spans [i, i + 1].
inline constexpr const char* kPassNames[] = {"shadows",    "depth_prepass", "opaque",
                                             "alpha_mask", "alpha_blend",   "overlays"};
inline constexpr std::uint32_t kTimestampCount = std::size(kPassNames) + 1;

// The 12 edges of a world box as a line list (overlays.cpp).
void append_box(std::vector<GPULineVertex>& out, const Aabb& box, glm::vec4 color);

struct Renderer::FrameSlot {
    explicit FrameSlot(Context& context) : recorder(context) {}
    CommandRecorder recorder;
    BufferHandle frame_data;              // GPUFrameData, host-visible uniform buffer
    VkDescriptorSet set = VK_NULL_HANDLE; // set 1: frame data + the scene's materials
    std::uint64_t set_generation = ~0ull; // scene generation the set's materials belong to
    BufferHandle lines;                   // overlay line vertices, host-visible, grown on demand
    VkDeviceSize lines_capacity = 0, lines_used = 0; // lines_used: bytes written this frame
    UniqueQueryPool timestamps, statistics;
    std::uint64_t submission = 0; // timeline value of the last frame recorded here
    bool has_results = false;
    bool shadows_rendered = false;
    std::uint64_t draw_calls = 0;
    CameraView camera;
    GPUPushConstants push_base{}; // scene-wide addresses for this frame
    // Camera culling of this frame (see frame_culling.cpp).
    CullPath cull = CullPath::None;
    std::uint32_t gpu_params = 0; // which GpuCuller parameter block
    BufferHandle cull_ids;        // CPU path: compacted ids, host-visible
    VkDeviceSize cull_ids_capacity = 0;
    std::vector<std::uint8_t> visible;        // per GPU instance (CPU test)
    std::vector<std::uint32_t> group_visible; // per draw group: visible instances
    CullStats cull_stats;
    Frustum cull_frustum;
};

struct Renderer::Culling {
    BufferHandle identity;                  // gl_InstanceIndex -> itself, per scene
    BoxesSoA boxes;                         // instance bounds, GPU instance order
    std::unique_ptr<GpuCuller> gpu;         // built on first use
    std::vector<std::uint32_t> group_batch; // draw group -> GPU batch (~0u: blended)
};

struct Renderer::Lighting {
    // Only bounds, lights and cameras: what camera and light resolution needs.
    Scene info;
};

} // namespace sherpa::gpu
