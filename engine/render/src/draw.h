#pragma once
// Draw helpers the passes share: dynamic state, the draw-group loops (culled or
// not), back-to-front blended draws and CPU-built line lists.
#include "frame_context.h"

#include <vector>

namespace sherpa::render {

// Whose draws these are: the camera, or one shadow cascade; with the culling that
// limits them (null: every instance).
struct DrawView {
    std::uint32_t cascade = kNoCascade; // the shader's cascade index (push constant)
    PassCull* cull = nullptr;
};
inline DrawView camera_view(FrameContext& f) {
    return {kNoCascade, f.slot.culling.camera()};
}
inline DrawView cascade_view(FrameContext& f, std::uint32_t c) {
    return {c, f.slot.culling.cascade(c)};
}

// What may still read a frame's colour target from earlier frames, which its first
// write this frame waits on: a readback copy or blit, a comparison's shaders that read
// this side image, an earlier frame's drawing.
inline constexpr VkPipelineStageFlags2 kColorTargetReaders =
    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT |
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

void set_viewport(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height);
void set_depth(VkCommandBuffer cmd, VkCompareOp op, bool write, float bias_constant = 0.0f,
               float bias_slope = 0.0f);
// Triangles one instance of the mesh draws (0 for lines and points).
inline std::uint32_t triangles_of(const GpuMesh& mesh) {
    return is_triangle_mesh(mesh.flags) ? mesh.index_count / 3 : 0;
}
// The mesh's streams, flags and motion record and the material, into `pc`.
void set_mesh(GPUPushConstants& pc, const GpuMesh& mesh, std::uint32_t material);
// Binds fixed pipeline `id` for `mesh` (its MOTION twin for a moving mesh) unless
// `bound` already is it.
void bind_for_mesh(FrameContext& f, PipelineId id, const GpuMesh& mesh, VkPipeline& bound);

// Unculled draws of draw group `group`: its instance count, or while nodes are hidden
// (SceneCulling::hidden_count) its shown instances, indexed through shown_ids() (else
// through `all`, the identity).
std::uint32_t shown_count(const FrameContext& f, std::size_t group);
VkDeviceAddress shown_ids(const FrameContext& f, VkDeviceAddress all);

// Every draw group of `alpha`, single-sided ones with back faces culled; draws and
// triangles go to `tally`.
void draw_groups(FrameContext& f, DrawPipeline pipeline, scene::AlphaMode alpha,
                 const DrawView& view, scene::CullStats& tally);
// Blended instances back to front, one draw each; draws and triangles go to `tally`.
void draw_blended(FrameContext& f, DrawPipeline pipeline, scene::CullStats& tally);
// A line list in world space, in its own range of the frame's line buffer.
void draw_lines(FrameContext& f, const std::vector<GPULineVertex>& lines);
// The 12 edges of a world box as a line list.
void append_box(std::vector<GPULineVertex>& out, const core::Aabb& box, glm::vec4 color);

} // namespace sherpa::render
