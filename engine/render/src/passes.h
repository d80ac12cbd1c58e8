#pragma once
// One class per pass of a frame. Each records into FrameContext::cmd; the Renderer
// (frame_recorder.h) owns them and calls them in frame order. A new pass is a class
// here (with `void record(FrameContext&)`) and one line in FrameRecorder::record_passes.
#include "frame_context.h"

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace sherpa::render {

// Scenes that move (skins, morph targets, animations): each frame, the pose
// (FrameRequest::pose, else the scene's default pose) into the frame's pose buffer
// (posed instances, joint matrices, morph weights, joint-influence highlights) and
// each instance's conservative world bounds (culling_bounds()) into
// FrameSlot::posed_bounds, which culling, sorting and overlays use. Static scenes
// skip it: no buffer, no work (pose_pass.cpp).
class PosePass {
public:
    // The skeleton overlay's lines: the loaded scene's skins posed as the meshes are
    // (pose_of()); nothing without skins. Built for any scene with skins, moving or not.
    void append_skeleton_lines(std::vector<GPULineVertex>& out, const FrameRequest& settings,
                               float joint_size) const;
    PosePass(gpu::ResourceManager& resources) : resources_(resources) {}
    void build(const scene::Scene& scene, const GpuScene& gpu); // a scene was loaded
    void reset();                                               // the scene is unloaded
    void record(FrameContext& f) { record(f.slot, f.settings, f.scene != nullptr); }
    // The same for a frame without a FrameContext (the ray tracer's).
    void record(FrameSlot& slot, const FrameRequest& settings, bool scene_loaded);
    // The scene skins, morphs or animates: slots get a pose buffer.
    bool active() const { return active_; }
    // settings.pose where it fits the scene, else the scene's default pose.
    const scene::Pose& pose_of(const FrameRequest& settings) const;

private:
    struct Instance {
        std::uint32_t node = 0, mesh = 0, material = 0;
        std::int32_t primitive = -1; // into scene_.primitives when it skins or morphs
        std::int32_t skin = -1;      // the node's skin when the mesh is skinned
        std::uint32_t targets = 0;   // morph weights it reads
        glm::mat4 world{1.0f};       // as loaded
        glm::mat4 row{1.0f};         // EXT_mesh_gpu_instancing row transform (T * R * S)
        core::Aabb local, bounds;    // mesh bounds; world bounds as loaded
    };
    void write(FrameSlot& slot, const FrameRequest& settings, const scene::Pose& pose);

    gpu::ResourceManager& resources_;
    bool active_ = false;
    scene::Scene scene_; // nodes, skins, motions and primitives: what culling_bounds() and
                         // the skeleton read
    scene::Pose default_;
    std::vector<Instance> instances_;        // per GPU instance
    std::vector<std::uint32_t> skin_base_;   // first joint matrix of each skin
    std::vector<std::uint32_t> skin_slots_;  // matrices each skin takes
    std::uint32_t joints_ = 0, weights_ = 0; // totals per frame
    std::uint64_t generation_ = 0;           // counts build(): a slot's pose is of this scene
};

// Culling of the camera and of each shadow cascade re-rendered this frame, on the
// CPU or with shaders/cull.comp (culling_pass.cpp); its statistics once the frame
// completed (culling_stats.cpp). Owns the loaded scene's culling data.
class CullingPass {
public:
    static constexpr std::size_t kHistory = 240;
    CullingPass(gpu::Context& context, gpu::ResourceManager& resources);
    ~CullingPass();
    void build(const GpuScene& scene); // a scene was loaded
    void reset();                      // the scene is unloaded
    // Per GPU instance of `scene` (the loaded one): 1 hides it from every pass. No
    // frame may be in flight (the GPU cullers are rebuilt without hidden objects).
    void set_hidden(std::vector<std::uint8_t> hidden, const GpuScene& scene);
    SceneCulling* scene_culling() { return culling_.get(); }
    void record(FrameContext& f);
    // Statistics of the completed frame in `slot` into `out`; pushes it to history().
    void read_stats(FrameSlot& slot, const GpuScene* scene, FrameStats& out);
    const scene::RingHistory<CullFrame>& history() const { return history_; }

private:
    void build_gpu(const GpuScene& scene);
    void test_cpu(FrameContext& f, PassCull& view, bool caster_view, bool blended_only);
    void prepare_buffers(FrameContext& f, std::uint32_t instances);
    void use_posed_bounds(FrameContext& f);
    VkDeviceAddress write_posed_objects(FrameContext& f);
    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    std::unique_ptr<SceneCulling> culling_;
    std::vector<scene::CullStats> cascade_stats_; // of the last frame that rendered the cascades
    scene::RingHistory<CullFrame> history_{kHistory};
};

// The shadow cascades of the main directional light, depth only, into one layered
// map that every camera pass samples; re-rendered only when their inputs change.
class ShadowPass {
public:
    ShadowPass(gpu::Context& context, gpu::ResourceManager& resources, std::uint32_t resolution);
    ~ShadowPass();
    // Whether cascades `c` must be drawn this frame (not `cache` or their inputs
    // changed since the map was last drawn); remembers the inputs when so.
    bool needs_render(const scene::ShadowCascades& c, std::uint64_t scene_generation, bool cache);
    void invalidate() { key_.clear(); } // the scene changed
    VkDescriptorImageInfo descriptor() const;
    std::uint64_t bytes() const;
    std::uint32_t resolution() const { return resolution_; }
    void record(FrameContext& f);

private:
    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    std::uint32_t resolution_;
    gpu::ImageHandle map_;
    gpu::SamplerHandle sampler_;
    bool valid_ = false;            // drawn at least once
    std::vector<std::uint8_t> key_; // inputs of the cached cascades
};

// FrameRequest::floor_only: every triangle in one constant colour (what the
// rasterizer costs by itself), instead of the prepass and shading.
class FloorPass {
public:
    void record(FrameContext& f);
};

// Depth of the opaque, then alpha-tested masked, surfaces (FrameContext::prepass).
class DepthPrepass {
public:
    void record(FrameContext& f);
};

// Shading of the draw groups of one alpha mode in the frame's debug view; blended
// instances sorted back to front.
class ForwardPass {
public:
    explicit ForwardPass(scene::AlphaMode alpha) : alpha_(alpha) {}
    void record(FrameContext& f);

private:
    scene::AlphaMode alpha_;
};

// The environment behind the surfaces (background_pass.cpp), drawn before them in its
// own rendering over every pixel; while the view holds still it is kept in an image of
// the target's size and copied into the target instead.
class BackgroundPass {
public:
    BackgroundPass();
    ~BackgroundPass();
    // Before the camera's rendering: true when the target now holds the background
    // (left in COLOR_ATTACHMENT_OPTIMAL layout), which the camera's rendering then
    // loads instead of clearing.
    bool prepare(FrameContext& f);
    static bool active(const FrameContext& f);
    // Bytes of the kept image (0 when none).
    std::uint64_t bytes() const;
    // Frees the kept image (once the frames using it are done).
    void release();

    // Everything the background's pixels depend on.
    struct Key {
        glm::mat4 view_proj{0.0f};
        glm::vec4 camera_position{0.0f}, environment{0.0f}, display{0.0f};
        std::uint64_t environment_generation = ~0ull;
        VkFormat format = VK_FORMAT_UNDEFINED;
        std::uint32_t width = 0, height = 0;
        bool operator==(const Key&) const = default;
    };

private:
    VkPipeline pipeline(FrameContext& f);
    void draw_whole(FrameContext& f, VkImageView view);
    void build_kept(FrameContext& f);
    void copy_kept(FrameContext& f);
    gpu::UniqueShaderModule vert_, frag_;
    std::map<VkFormat, gpu::UniquePipeline> pipelines_;
    gpu::ResourceManager* resources_ = nullptr;
    gpu::ImageHandle kept_;       // the background of `kept_key_`, TRANSFER_SRC layout
    std::optional<Key> kept_key_; // what kept_ holds
    std::optional<Key> last_key_; // the last frame's with a background, into a blit target
};

// FrameRequest::overlays: wireframe, normal/tangent/bitangent glyphs, instance
// bounds, the culling boxes and the skeleton.
class OverlayPass {
public:
    explicit OverlayPass(const PosePass& pose) : pose_(pose) {}
    void record(FrameContext& f);

private:
    void draw_cull_boxes(FrameContext& f);
    void draw_skeleton(FrameContext& f);
    const PosePass& pose_; // the skins and the frame's pose (the skeleton)
};

// The selection (FrameRequest::highlight_*), over everything else.
class HighlightPass {
public:
    void record(FrameContext& f);
};

} // namespace sherpa::render
