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
#include <string>
#include <tuple>
#include <utility>

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/gpu/unique_handle.h>
#include <sherpa/render/gpu_structs.h>

namespace sherpa::render {

enum class PipelineId : std::uint32_t {
    PrepassOpaque, // depth only, camera
    PrepassMask,   // depth only with alpha test
    Wireframe,     // polygon mode LINE, flat colour
    Glyphs,        // per-vertex normal/tangent/bitangent lines
    BoxLines,      // CPU-built world-space lines (instance AABBs)
    Floor,         // benchmark floor: positions and one constant colour
    Tint,          // the Floor's constant colour, alpha-blended over the frame
    Outline,       // polygon mode LINE at kOutlineWidthPixels, flat colour (selection)
    ShadowOpaque,  // shadow cascades (depth-only rendering, no colour attachment)
    ShadowMask,
    Count,
};

inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// A depth attachment of the frame's format (the main target's, the transmission
// background's): drawn into, never sampled.
inline gpu::ImageDesc depth_attachment_desc(std::uint32_t width, std::uint32_t height,
                                            std::string name) {
    gpu::ImageDesc d;
    d.format = kDepthFormat;
    d.width = width;
    d.height = height;
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    d.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    d.name = std::move(name);
    return d;
}

// The optional vertex streams forward shading is specialised for (bits of
// GpuMesh::flags, HAS_TANGENT | HAS_UV0 | HAS_UV1 | HAS_COLOR in common.glsl).
inline constexpr std::uint32_t kForwardStreamBits = 0x3cu;
// Forward pipelines also differ by topology (MESH_LINES / MESH_POINTS: line or
// point list, shaded unlit) and by motion (kMeshMotionBit: the vertex stage skins
// and morphs); the bits ride along in the streams key.
inline constexpr std::uint32_t forward_streams(std::uint32_t mesh_flags) {
    return mesh_flags & (kForwardStreamBits | kMeshTopologyBits | kMeshMotionBit);
}
inline constexpr bool is_moving_mesh(std::uint32_t mesh_flags) {
    return (mesh_flags & kMeshMotionBit) != 0;
}
// Lines and points meshes are drawn only by forward shading; the fixed pipelines
// (depth prepass, shadows, floor, wireframe) rasterize triangle lists.
inline constexpr bool is_triangle_mesh(std::uint32_t mesh_flags) {
    return (mesh_flags & kMeshTopologyBits) == 0;
}

// How one pipeline is built (pipelines.cpp).
struct PipelineDesc {
    VkShaderModule vert = VK_NULL_HANDLE;
    VkShaderModule frag = VK_NULL_HANDLE; // null: depth only
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPolygonMode polygon = VK_POLYGON_MODE_FILL;
    bool color = true; // has the colour attachment (false: shadow rendering)
    bool write_color = true;
    bool blend = false;
    const VkSpecializationInfo* frag_constants = nullptr;
    const VkSpecializationInfo* vert_constants = nullptr;
    float line_width = 1.0f; // overlays and wireframe stay 1 px
    // Last, after the fields the pipelines' positional initialisers give: has the
    // depth attachment and the scene's dynamic rasterizer state (cull mode, winding,
    // depth compare/write/bias). False: a full-screen colour pass whose only dynamic
    // state is viewport and scissor.
    bool depth = true;
};

// One graphics pipeline of `d`'s stages ("main"), vertex pulling (no vertex input),
// dynamic rendering to `color_format` (and kDepthFormat where d.depth).
gpu::UniquePipeline make_graphics_pipeline(VkDevice device, VkPipelineLayout layout,
                                           VkFormat color_format, const PipelineDesc& d,
                                           const char* what = "vkCreateGraphicsPipelines");

// The pipeline of a run of draws: a fixed one, or forward shading of a view, chosen
// per mesh for the streams it holds.
struct DrawPipeline {
    PipelineId fixed = PipelineId::Count; // Count: forward shading
    std::uint32_t view = 0;
    bool blend = false;
};

class Pipelines {
public:
    // `transmission_background`: forward shading writes linear radiance and leaves
    // transmissive materials out (TransmissionPass's target; forward.frag constant 2).
    Pipelines(const gpu::Context& context, VkDescriptorSetLayout textures_layout,
              VkDescriptorSetLayout frame_layout, VkFormat color_format,
              bool transmission_background = false);
    VkPipeline get(PipelineId id) const { return pipelines_[static_cast<std::size_t>(id)].get(); }
    // The same for meshes of `mesh_flags`: moving meshes get the pipeline's MOTION
    // twin (skinning and morphing in the vertex stage), built on first use.
    VkPipeline get(PipelineId id, std::uint32_t mesh_flags);
    // Forward shading for one debug view and the optional streams a mesh holds
    // (specialization constants of forward.frag; absent streams drop their
    // varyings), blended or not; built on first use.
    VkPipeline forward(std::uint32_t view, bool blend, std::uint32_t streams = kForwardStreamBits);
    VkPipeline resolve(const DrawPipeline& d, std::uint32_t mesh_flags) {
        return d.fixed != PipelineId::Count ? get(d.fixed, mesh_flags)
                                            : forward(d.view, d.blend, forward_streams(mesh_flags));
    }
    VkPipelineLayout layout() const { return layout_.get(); }
    VkFormat color_format() const { return color_format_; }

private:
    VkFormat color_format_;
    VkBool32 transmission_background_ = VK_FALSE;
    // Point size forward shading gives points: kPointSizePixels, or 1 on a device
    // without largePoints.
    float point_size_ = 1.0f;
    float line_width_ = 1.0f;
    float outline_width_ = 1.0f;
    gpu::UniquePipelineLayout layout_;
    static constexpr std::size_t kFixedCount = static_cast<std::size_t>(PipelineId::Count);
    std::array<gpu::UniquePipeline, kFixedCount> pipelines_, motion_;
    VkDevice device_;
    // Kept for the forward() variants and the MOTION twins of the fixed pipelines.
    gpu::UniqueShaderModule mesh_vert_, forward_frag_, depth_vert_, glyph_vert_, lines_vert_,
        depth_mask_frag_, flat_frag_, floor_frag_;
    std::array<PipelineDesc, kFixedCount> descs_{};
    std::map<std::tuple<std::uint32_t, bool, std::uint32_t>, gpu::UniquePipeline> forward_;
};

} // namespace sherpa::render
