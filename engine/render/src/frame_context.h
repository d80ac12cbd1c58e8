#pragma once
// What one frame's passes share (private to the render layer): the per-frame-in-
// flight resources (FrameSlot), the per-scene culling data (SceneCulling), and the
// FrameContext every pass records from. A pass is a class with
// `void record(FrameContext&)`; the Renderer orders them (frame_recorder.h).
#include "pipelines.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/frame_source.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/gpu_culling.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/culling_passes.h>
#include <sherpa/scene/shadow_cascades.h>

namespace sherpa::render {

class EnvironmentMap;
struct SceneLights;

// Timestamps written between passes; pass i spans [i, i + 1].
inline constexpr const char* kPassNames[] = {
    "shadows", "transmission", "depth_prepass", "opaque", "alpha_mask", "alpha_blend", "overlays"};
inline constexpr std::uint32_t kTimestampCount = std::size(kPassNames) + 1;

// Culled views a frame can have: the camera and each shadow cascade in use.
inline constexpr std::uint32_t kMaxCullPasses = 1 + kShadowCascades;

// One culled view of a frame (the camera or one shadow cascade).
struct PassCull {
    scene::Frustum frustum;
    std::vector<std::uint8_t> visible;        // per GPU instance, where the CPU test ran
    std::vector<std::uint32_t> group_visible; // per draw group (CPU test)
    bool cpu_tested = false;                  // `visible` holds every instance of the pass
    scene::CullStats stats;
    VkDeviceSize ids_offset = 0; // CPU path: this view's region of FrameSlot::cull_ids
    GpuCuller* gpu = nullptr;    // GPU path: this view's culler
    VkDeviceSize readback = 0;   // GPU path: offset of this view in FrameSlot::cull_readback
};

// The culling of one frame: the camera, then the cascades re-rendered this frame.
struct FrameCulling {
    CullPath path = CullPath::None;
    bool check = false;
    std::vector<PassCull> views; // [camera, cascade 0, ..]: see camera() and cascade()
    std::uint32_t count = 0;     // views with statistics this frame
    scene::CullStats unused;     // tally of draws no view counts (no scene)
    // The culling that limits the camera's draws, or null when culling is off.
    PassCull* camera() { return path != CullPath::None && count > 0 ? &views[0] : nullptr; }
    // The same for shadow cascade `c`: null when off or the cascade is not culled.
    PassCull* cascade(std::uint32_t c) {
        return path != CullPath::None && 1 + c < count ? &views[1 + c] : nullptr;
    }
    // Where the draws of the camera / cascade `c` are tallied.
    scene::CullStats& camera_stats() { return count > 0 ? views[0].stats : unused; }
    scene::CullStats& cascade_stats(std::uint32_t c) { return views.at(1 + c).stats; }
};

// Resources of one frame in flight.
struct FrameSlot {
    explicit FrameSlot(gpu::Context& context) : recorder(context) {}
    gpu::CommandRecorder recorder;
    gpu::BufferHandle frame_data;          // GPUFrameData, host-visible uniform buffer
    VkDescriptorSet set = VK_NULL_HANDLE;  // set 1: frame data + the scene's materials
    std::uint64_t set_generation = ~0ull;  // scene generation the set's materials belong to
    std::uint64_t set_environment = ~0ull; // environment generation the set's maps belong to
    gpu::BufferHandle lines;               // overlay line vertices, host-visible, grown on demand
    VkDeviceSize lines_capacity = 0, lines_used = 0; // lines_used: bytes written this frame
    gpu::UniqueQueryPool timestamps, statistics;
    std::uint64_t submission = 0; // timeline value of the last frame recorded here
    bool has_results = false;
    bool shadows_rendered = false;
    std::uint64_t draw_calls = 0;
    CameraView camera;
    GPUPushConstants push_base{};   // scene-wide addresses for this frame
    scene::ShadowCascades cascades; // fitted this frame (see frame_data.cpp)
    FrameCulling culling;           // see culling_pass.cpp
    scene::CullStats prepass;       // draws and triangles of the depth prepass
    gpu::BufferHandle cull_ids;     // CPU path: compacted ids per view, host-visible
    VkDeviceSize cull_ids_capacity = 0;
    gpu::BufferHandle cull_readback; // GPU path: indirect commands (+ visible flags when checking)
    VkDeviceSize cull_readback_capacity = 0;
    gpu::UniqueQueryPool cull_timestamps; // two per view around the GPU culling dispatch
    bool history_pushed = false;
    // The frame was ray traced (record_side): two timestamps, no culling or statistics.
    bool ray_traced = false;
    bool path_traced = false; // a ray-traced side of the path tracer (its PathTraceFrame)
    // Scenes that move (PosePass): this frame's instances, joint matrices, morph
    // weights and joint highlights, host-visible; and each GPU instance's world bounds
    // in the frame's pose, which culling, sorting and overlays use instead of the
    // scene's static ones.
    gpu::BufferHandle pose;
    VkDeviceSize pose_capacity = 0;
    bool posed = false;
    std::vector<core::Aabb> posed_bounds;
    std::uint64_t pose_key = 0; // hash of the pose drawn (the shadow cache's key)
    VkDeviceAddress posed_instances = 0, pose_address = 0; // push constants of posed frames
    std::uint32_t highlight_base = 0;
    // What this slot's pose buffer holds (PosePass): the pose (null: the default one),
    // the selected joint and the scene's load; a frame asking for the same again
    // (paused, or a file's default pose) reuses it without rewriting.
    std::shared_ptr<const scene::Pose> pose_written;
    std::optional<std::uint32_t> joint_written;
    std::uint64_t pose_generation = 0; // 0: nothing written
    gpu::BufferHandle cull_objects;    // GPU path while posed: GPUCullObjects of the posed bounds
    VkDeviceSize cull_objects_capacity = 0;
    // The pose (pose_generation, pose_key) whose bounds cull_objects holds.
    std::uint64_t cull_objects_generation = 0, cull_objects_pose = 0;
    std::uint64_t cull_objects_version = 0; // SceneCulling::objects_version written
};

// Culling data of the loaded scene.
struct SceneCulling {
    gpu::BufferHandle identity;        // gl_InstanceIndex -> itself, per scene
    scene::BoxesSoA boxes;             // instance bounds, GPU instance order
    std::vector<std::uint8_t> invalid; // per GPU instance: box not valid (never culled)
    std::vector<std::uint8_t> blended; // per GPU instance: alpha mode BLEND
    std::uint32_t casters = 0;         // instances not blended (the shadow passes)
    // GPU path, built on first use: one culler per view (camera, each cascade), all
    // over the non-blended groups, one batch per group.
    std::vector<std::unique_ptr<GpuCuller>> gpu;
    std::vector<std::uint32_t> group_batch;      // draw group -> GPU batch (~0u: blended)
    std::vector<std::uint32_t> gpu_object_batch; // per GPU culler object: its batch
    // The FrameSlot::pose_key whose posed bounds `boxes` holds; none: the bounds as loaded.
    std::optional<std::uint64_t> boxes_pose;
    // Visibility (SceneSetup::hidden_nodes, subtree rule applied), per GPU
    // instance: hidden instances are drawn by no pass. While any is hidden, `shown`
    // holds per draw group its shown instances compacted at the group's first
    // instance (what unculled draws and overlays index) and group_shown their count.
    std::vector<std::uint8_t> hidden;
    std::uint32_t hidden_count = 0, hidden_casters = 0; // all; not blended
    gpu::BufferHandle shown;
    std::vector<std::uint32_t> group_shown;
    std::uint64_t objects_version = 1; // bumped when the GPU cullers' objects change
    bool is_hidden(std::uint32_t gpu_instance) const {
        return hidden_count > 0 && hidden[gpu_instance] != 0;
    }
};

// Everything a pass records from. References live for one record_frame() call.
struct FrameContext {
    VkCommandBuffer cmd;
    FrameSlot& slot;
    std::uint32_t slot_index; // which frame in flight: the GPU cullers' block
    Pipelines& pipelines;
    const FrameRequest& settings;
    const gpu::RenderTarget& target;
    gpu::Context& context;
    gpu::ResourceManager& resources;
    const GpuScene* scene;                       // null: nothing loaded
    SceneCulling* culling;                       // null: nothing loaded
    const SceneLights& lighting;                 // bounds, lights and cameras of the loaded scene
    const EnvironmentMap* environment = nullptr; // null: no environment loaded
    std::uint32_t cascades = 0; // shadow cascades re-rendered this frame (0: reused or none)
    bool prepass = false;       // the depth prepass runs this frame
    float aspect() const { return float(target.width) / float(target.height); }
};

// World bounds per GPU instance in this frame: posed when the scene moves.
inline const std::vector<core::Aabb>& instance_bounds(const FrameContext& f) {
    return f.slot.posed ? f.slot.posed_bounds : f.scene->instance_bounds();
}

} // namespace sherpa::render
