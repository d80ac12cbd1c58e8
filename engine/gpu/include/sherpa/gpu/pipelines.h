#pragma once
// Every graphics pipeline of the renderer, built for one colour format (offscreen
// RGBA8 sRGB or a swapchain's format). All share one layout: descriptor set 0
// (shadow map + bindless textures) and GPUPushConstants. Cull mode, winding, depth
// compare/write and depth bias are dynamic state, so draw groups differing only in
// those share a pipeline.
#include <array>
#include <cstdint>

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/unique_handle.h>

namespace sherpa::gpu {

enum class PipelineId : std::uint32_t {
    PrepassOpaque, // depth only, camera
    PrepassMask,   // depth only with alpha test
    ForwardOpaque, // shading (opaque and masked materials), every debug view
    ForwardBlend,  // shading with alpha blending, no depth writes
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
    Pipelines(const Context& context, VkDescriptorSetLayout set_layout, VkFormat color_format);
    VkPipeline get(PipelineId id) const { return pipelines_[static_cast<std::size_t>(id)].get(); }
    VkPipelineLayout layout() const { return layout_.get(); }
    VkFormat color_format() const { return color_format_; }

private:
    VkFormat color_format_;
    UniquePipelineLayout layout_;
    std::array<UniquePipeline, static_cast<std::size_t>(PipelineId::Count)> pipelines_;
};

} // namespace sherpa::gpu
