#pragma once
// Every graphics pipeline of the renderer, built for one colour format (offscreen
// RGBA8 sRGB or a swapchain's format). All share one layout: descriptor set 0
// (shadow map + bindless textures), set 1 (frame constants + materials) and
// GPUPushConstants. Cull mode, winding, depth
// compare/write and depth bias are dynamic state, so draw groups differing only in
// those share a pipeline.
#include <array>
#include <cstdint>
#include <map>
#include <utility>

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/unique_handle.h>

namespace sherpa::gpu {

enum class PipelineId : std::uint32_t {
    PrepassOpaque, // depth only, camera
    PrepassMask,   // depth only with alpha test
    Wireframe,     // polygon mode LINE, flat colour
    Glyphs,        // per-vertex normal/tangent/bitangent lines
    BoxLines,      // CPU-built world-space lines (instance AABBs)
    Floor,         // benchmark floor: positions and one constant colour
    ShadowOpaque,  // shadow cascades (depth-only rendering, no colour attachment)
    ShadowMask,
    Count,
};

inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

class Pipelines {
public:
    Pipelines(const Context& context, VkDescriptorSetLayout textures_layout,
              VkDescriptorSetLayout frame_layout, VkFormat color_format);
    VkPipeline get(PipelineId id) const { return pipelines_[static_cast<std::size_t>(id)].get(); }
    // Forward shading for one debug view (a specialization constant of
    // forward.frag), blended or not; built on first use.
    VkPipeline forward(std::uint32_t view, bool blend);
    VkPipelineLayout layout() const { return layout_.get(); }
    VkFormat color_format() const { return color_format_; }

private:
    VkFormat color_format_;
    UniquePipelineLayout layout_;
    std::array<UniquePipeline, static_cast<std::size_t>(PipelineId::Count)> pipelines_;
    VkDevice device_;
    UniqueShaderModule mesh_vert_, forward_frag_; // kept for forward() variants
    std::map<std::pair<std::uint32_t, bool>, UniquePipeline> forward_;
};

} // namespace sherpa::gpu
