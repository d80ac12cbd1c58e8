#pragma once
// The comparison's compositing pass (sherpa/render/comparison.h): two side images
// of one size in, the target out. record_stats() dispatches shaders/compare.comp,
// which reduces the per-pixel differences into the slot's statistics buffer;
// record_composite() draws one fullscreen triangle (compare.vert/.frag) writing side
// A alone (a presented ray-traced frame), Split or Difference into the target.
// Private to the render layer; a Renderer owns one (frame_recorder.h), made on first
// use, with a descriptor set and statistics buffer per frame slot.
#include <sherpa/gpu/frame_source.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/render/gpu_structs.h>

#include <map>
#include <optional>
#include <vector>

namespace sherpa::render {

// One side's image, readable by shaders: an RGBA8 UNORM view of the sRGB-encoded
// bytes (the raster target's alias view, the ray tracer's storage image).
struct SideImage {
    VkImageView view = VK_NULL_HANDLE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
};

struct CompositeInputs {
    SideImage a, b;
    std::uint32_t width = 0, height = 0; // both sides
};

// What one frame of the pass left in its slot: what compare.comp reduced over
// `pixels` pixels (when it ran), and the GPU time of the dispatch and of the draw
// (0 where not recorded or the device has no timestamps).
struct ReducedStats {
    std::optional<GPUCompareStats> raw;
    std::uint64_t pixels = 0;
    double reduce_ms = 0.0, composite_ms = 0.0;
};

enum class CompositeMode : std::uint32_t { SideA = 0, Split = 1, Difference = 2 };

class ComparisonPass {
public:
    ComparisonPass(gpu::Context& context, gpu::ResourceManager& resources, std::uint32_t slots);
    ~ComparisonPass();
    ComparisonPass(const ComparisonPass&) = delete;
    ComparisonPass& operator=(const ComparisonPass&) = delete;

    // Points the slot's set at the sides (the slot's previous frame has completed);
    // call before record_stats / record_composite of this frame.
    void bind(std::uint32_t slot, const CompositeInputs& in);
    // Clears the slot's statistics and reduces the differences into them.
    void record_stats(VkCommandBuffer cmd, std::uint32_t slot, const CompositeInputs& in);
    // Writes the target (left in target.final_layout). `divider` is a fraction of the
    // width, `heat_max` a difference in 0..1.
    void record_composite(VkCommandBuffer cmd, std::uint32_t slot, const CompositeInputs& in,
                          const gpu::RenderTarget& target, CompositeMode mode, float divider,
                          float heat_max);
    // What was recorded in `slot` since the last call, once its submission completed.
    ReducedStats take_stats(std::uint32_t slot);

private:
    VkPipeline pipeline_for(VkFormat format);
    // Timestamps of `slot`: [4 slot, +1] around the dispatch, [+2, +3] around the draw.
    void timestamp(VkCommandBuffer cmd, std::uint32_t query, VkPipelineStageFlags2 stage);
    double elapsed_ms(std::uint32_t first_query) const;

    gpu::Context& context_;
    gpu::ResourceManager& resources_;
    gpu::UniqueDescriptorSetLayout set_layout_;
    gpu::UniqueDescriptorPool pool_;
    gpu::UniquePipelineLayout layout_;
    gpu::UniquePipeline stats_pipeline_;
    gpu::UniqueShaderModule vert_, frag_;
    std::map<VkFormat, gpu::UniquePipeline> composite_;
    gpu::SamplerHandle sampler_;
    gpu::UniqueQueryPool timestamps_; // null without device timestamps
    struct Slot {
        VkDescriptorSet set = VK_NULL_HANDLE;
        gpu::BufferHandle stats; // GPUCompareStats, host-visible
        bool stats_pending = false, composite_pending = false;
        std::uint64_t pixels = 0;
    };
    std::vector<Slot> slots_;
};

} // namespace sherpa::render
