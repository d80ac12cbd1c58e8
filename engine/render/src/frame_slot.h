#pragma once
// Per-frame-in-flight resources of the Renderer (private to the GPU layer).
#include <sherpa/render/camera.h>
#include <sherpa/gpu/commands.h>
#include <sherpa/render/gpu_culling.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/shadow_cascades.h>

namespace sherpa::gpu {

// Timestamps written between passes; pass i spans [i, i + 1].
inline constexpr const char* kPassNames[] = {"shadows",    "depth_prepass", "opaque",
                                             "alpha_mask", "alpha_blend",   "overlays"};
inline constexpr std::uint32_t kTimestampCount = std::size(kPassNames) + 1;

// Culled passes a frame can have: the camera and each shadow cascade in use.
inline constexpr std::uint32_t kMaxCullPasses = 1 + kShadowCascades;

// One culled pass of a frame.
struct PassCull {
    Frustum frustum;
    std::vector<std::uint8_t> visible;        // per GPU instance, where the CPU test ran
    std::vector<std::uint32_t> group_visible; // per draw group (CPU test)
    bool cpu_tested = false;                  // `visible` holds every instance of the pass
    CullStats stats;
    VkDeviceSize readback = 0; // GPU path: offset of this pass in FrameSlot::cull_readback
};
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
    ShadowCascades cascades;      // fitted this frame (see frame_data.cpp)
    // Culling of this frame (see frame_culling.cpp): pass 0 the camera, pass 1 + c
    // shadow cascade c (only in frames that render the cascades).
    CullPath cull = CullPath::None;
    bool cull_check = false;
    std::vector<PassCull> passes;
    std::uint32_t pass_count = 0;
    CullStats prepass;     // draws and triangles of the depth prepass
    BufferHandle cull_ids; // CPU path: compacted ids per pass, host-visible
    VkDeviceSize cull_ids_capacity = 0;
    BufferHandle cull_readback; // GPU path: indirect commands (+ visible flags when checking)
    VkDeviceSize cull_readback_capacity = 0;
    UniqueQueryPool cull_timestamps; // two per pass around the GPU culling dispatch
    bool history_pushed = false;
};

struct Renderer::Culling {
    BufferHandle identity;             // gl_InstanceIndex -> itself, per scene
    BoxesSoA boxes;                    // instance bounds, GPU instance order
    std::vector<std::uint8_t> invalid; // per GPU instance: box not valid (never culled)
    std::vector<std::uint8_t> blended; // per GPU instance: alpha mode BLEND
    std::uint32_t casters = 0;         // instances not blended (the shadow passes)
    // GPU path, built on first use: one culler per pass (camera, each cascade), all
    // over the non-blended groups, one batch per group.
    std::vector<std::unique_ptr<GpuCuller>> gpu;
    std::vector<std::uint32_t> group_batch; // draw group -> GPU batch (~0u: blended)
};

struct Renderer::Lighting {
    // Only bounds, lights and cameras: what camera and light resolution needs.
    Scene info;
};

} // namespace sherpa::gpu
