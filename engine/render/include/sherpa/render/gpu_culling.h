#pragma once
// GPU-driven culling of one mesh pass: a compute shader culls every pass object
// and appends the visible ones to their indirect batch (instance count + compacted
// instance-id array); the renderer then draws each batch with
// vkCmdDrawIndexedIndirectCount. A check mode reads back the GPU's visible set so
// it can be compared with the CPU path for the same method.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/mesh_pass.h>

namespace sherpa::render {

// GPUCullObject, GPUCullParams: gpu_structs.h, with the engine's other GPU twins.
GPUCullObject make_cull_object(const core::Aabb& box, std::uint32_t batch, std::uint32_t instance);
GPUCullParams cull_params(const scene::Frustum& frustum, scene::CullMethod method,
                          std::uint32_t object_count);

// Results of one culling run, read back (check mode).
struct GpuCullReadback {
    std::vector<std::uint8_t> visible;          // per pass object, flat-batch order
    std::vector<std::uint32_t> instance_counts; // per indirect batch
    std::vector<std::uint32_t> instance_ids;    // compacted, valid within each batch's count
    double gpu_ms = -1.0;                       // timestamped dispatch (-1: no timestamps)
};

// shaders/cull.comp as a compute pipeline, with its layouts. Cullers made with the
// same one share it: lavapipe compiles a pipeline at its first dispatch (~170 ms for
// this one), so a renderer with a culler per pass makes it once.
class GpuCullPipeline {
public:
    explicit GpuCullPipeline(const gpu::Context& context);
    VkPipeline pipeline() const { return pipeline_.get(); }
    VkPipelineLayout layout() const { return layout_.get(); }
    VkDescriptorSetLayout set_layout() const { return set_layout_.get(); }

private:
    gpu::UniqueDescriptorSetLayout set_layout_;
    gpu::UniquePipelineLayout layout_;
    gpu::UniquePipeline pipeline_;
};

class GpuCuller {
public:
    // `parameter_blocks`: one per frame in flight, so that writing a frame's
    // parameters never races a frame still running on the GPU. `pipeline`: shared
    // with other cullers; null makes one for this culler.
    GpuCuller(gpu::Context& context, gpu::ResourceManager& resources,
              std::uint32_t parameter_blocks = 1,
              std::shared_ptr<const GpuCullPipeline> pipeline = nullptr);
    ~GpuCuller();
    GpuCuller(const GpuCuller&) = delete;
    GpuCuller& operator=(const GpuCuller&) = delete;

    // Builds the GPU arrays for `pass` (after MeshPass::update()). `bounds` are the
    // scene's instance world boxes; `gpu_instance` maps a scene instance to the GPU
    // instance index the draws read; `meshes` give each batch's index range.
    // Lower level: objects (batch index per object, objects of a batch contiguous
    // from its draw's firstInstance) and one indirect draw per batch.
    // `object_instance` names each object's scene instance (check mode, reports).
    void build(std::span<const GPUCullObject> objects,
               std::span<const VkDrawIndexedIndirectCommand> draws,
               std::vector<std::uint32_t> object_instance);
    // For culling without a GpuScene (CLI, tests, benchmarks): the scene's instance
    // bounds, GPU instance index = scene instance index, index ranges laid out mesh
    // after mesh in one buffer.
    void build(const scene::MeshPass& pass, const scene::Scene& scene);
    void build(const scene::MeshPass& pass, std::span<const core::Aabb> bounds,
               std::span<const std::uint32_t> gpu_instance, std::span<const GpuMesh> meshes);

    // Records: reset the indirect commands from their clear copy, write the frame's
    // parameters, dispatch, and make the results visible to indirect draws, vertex
    // shaders and transfers. `objects`: this frame's objects instead of the built
    // ones (the same order, batches and count; e.g. boxes of a moving scene's pose).
    void record(VkCommandBuffer cmd, const scene::Frustum& frustum, scene::CullMethod method,
                std::uint32_t parameter_block = 0, bool timestamps = true,
                VkDeviceAddress objects = 0);

    // One synchronous run with readback (tests, CLI, benchmarks).
    GpuCullReadback run(const scene::Frustum& frustum, scene::CullMethod method);

    std::uint32_t object_count() const { return objects_count_; }
    std::uint32_t batch_count() const { return batch_count_; }
    VkBuffer draws() const;
    VkBuffer draw_counts() const; // one uint per batch: 1 (each batch is one draw)
    VkDeviceAddress instance_ids() const;
    VkBuffer visible_flags() const; // one uint per object, flat-batch order
    // Scene instance of each pass object, flat-batch order.
    const std::vector<std::uint32_t>& object_instances() const { return object_instance_; }

private:
    void release();
    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    std::shared_ptr<const GpuCullPipeline> pipeline_;
    gpu::UniqueDescriptorPool pool_;
    std::vector<VkDescriptorSet> param_sets_; // one per parameter block (uniform buffer)
    gpu::UniqueQueryPool timestamps_;
    gpu::CommandRecorder recorder_;
    std::vector<gpu::BufferHandle> params_;
    gpu::BufferHandle objects_, draws_, draws_clear_, counts_, ids_, visible_, readback_;
    std::uint32_t objects_count_ = 0, batch_count_ = 0;
    std::vector<std::uint32_t> object_instance_;
};

} // namespace sherpa::render
