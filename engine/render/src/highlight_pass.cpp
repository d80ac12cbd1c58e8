// The selection highlight (FrameRequest::highlight_*), drawn after every other
// overlay. A selected instance is outlined, not tinted: a tint (even a light one)
// changes the colours the user selected the object to judge, and over the
// missing-texture checker it turned magenta pink and black olive. The outline is
// the mesh's edges drawn as wide lines behind its own surface, depth tested
// against the frame: only where a line leaves the silhouette does it show, so the
// ring follows the visible outline, the interior keeps its shaded pixels, and an
// object in front still hides it.
// - single-sided meshes draw their back faces' edges (front faces culled): those lie
//   behind the surface, exactly, with no bias;
// - double-sided meshes (a card, a leaf) have no back to draw: all edges, pushed
//   back by a slope-scaled depth bias so that the surface itself hides them.
// A selected triangle is filled and a selected vertex gets a normal/tangent/bitangent
// tripod, both magenta and never hidden by depth. Lines and points meshes have no
// silhouette: their world box is drawn instead.
#include "draw.h"
#include "passes.h"

#include <algorithm>

namespace sherpa::render {

namespace {

// The GPU instance (index into the draw order) of a scene instance and its draw
// group; null group when it is not drawn (not uploaded, empty mesh, hidden).
struct DrawnInstance {
    std::uint32_t gpu_instance = 0;
    const DrawGroup* group = nullptr;
};

DrawnInstance find_drawn(const FrameContext& f, std::uint32_t scene_instance) {
    const GpuScene& scene = *f.scene;
    const auto& ids = scene.scene_instances();
    const auto found = std::find(ids.begin(), ids.end(), scene_instance);
    if (found == ids.end()) return {};
    const auto gpu_instance = static_cast<std::uint32_t>(found - ids.begin());
    if (f.culling->is_hidden(gpu_instance)) return {}; // hidden: no pixels to point at
    const auto group =
        std::find_if(scene.groups().begin(), scene.groups().end(), [&](const DrawGroup& g) {
            return gpu_instance >= g.first_instance &&
                   gpu_instance < g.first_instance + g.instance_count;
        });
    if (group == scene.groups().end()) return {};
    return {gpu_instance, &*group};
}

// The outline of one drawn triangle-mesh instance (see the file comment).
void draw_outline(FrameContext& f, const DrawnInstance& d, GPUPushConstants pc) {
    VkCommandBuffer cmd = f.cmd;
    const GpuMesh& m = f.scene->meshes()[d.group->mesh];
    set_mesh(pc, m, d.group->material); // depth.vert reads the UVs too
    pc.color = kHighlightColor;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                      f.pipelines.get(PipelineId::Outline, m.flags));
    vkCmdSetFrontFace(cmd, d.group->mirrored ? VK_FRONT_FACE_CLOCKWISE
                                             : VK_FRONT_FACE_COUNTER_CLOCKWISE);
    const bool two_sided = d.group->double_sided;
    vkCmdSetCullMode(cmd, two_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_FRONT_BIT);
    vkCmdSetDepthBiasEnable(cmd, two_sided ? VK_TRUE : VK_FALSE);
    // Reverse-Z: a negative bias moves the lines away from the camera.
    if (two_sided) vkCmdSetDepthBias(cmd, -4.0f, 0.0f, -2.0f);
    vkCmdPushConstants(cmd, f.pipelines.layout(),
                       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(pc),
                       &pc);
    vkCmdDrawIndexed(cmd, m.index_count, 1, m.first_index, 0, d.gpu_instance);
    ++f.slot.draw_calls;
    vkCmdSetDepthBiasEnable(cmd, VK_FALSE);
}

} // namespace

void HighlightPass::record(FrameContext& f) {
    const FrameRequest& s = f.settings;
    const GpuScene* scene = f.scene;
    if (!scene || !f.culling || !f.culling->identity.valid()) return;
    if (!s.highlight_instance && s.highlight_outline.empty()) return;
    VkCommandBuffer cmd = f.cmd;
    Pipelines& p = f.pipelines;
    FrameSlot& slot = f.slot;
    const VkPipelineLayout layout = p.layout();
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    GPUPushConstants pc = slot.push_base;
    // Identity ids: gl_InstanceIndex (the draw's first instance) is the GPU instance.
    pc.instance_ids = f.resources.get(f.culling->identity).address;
    pc.cascade = kNoCascade;
    vkCmdSetDepthWriteEnable(cmd, VK_FALSE);
    vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_GREATER_OR_EQUAL);

    // Outlines first (depth tested), then boxes of what has no silhouette.
    std::vector<GPULineVertex> lines;
    std::vector<std::uint32_t> outlined = s.highlight_outline;
    if (s.highlight_instance) outlined.push_back(*s.highlight_instance);
    std::sort(outlined.begin(), outlined.end());
    outlined.erase(std::unique(outlined.begin(), outlined.end()), outlined.end());
    for (const std::uint32_t instance : outlined) {
        const DrawnInstance d = find_drawn(f, instance);
        if (!d.group) continue;
        if (is_triangle_mesh(scene->meshes()[d.group->mesh].flags))
            draw_outline(f, d, pc);
        else
            append_box(lines, instance_bounds(f)[d.gpu_instance], kHighlightColor);
    }

    // Detail of the selected instance that must never hide behind other surfaces.
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
    vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_ALWAYS);
    if (s.highlight_instance) {
        const DrawnInstance d = find_drawn(f, *s.highlight_instance);
        const GpuMesh* m = d.group ? &scene->meshes()[d.group->mesh] : nullptr;
        if (m) set_mesh(pc, *m, d.group->material);
        if (m && is_triangle_mesh(m->flags) && s.highlight_triangle &&
            *s.highlight_triangle < m->index_count / 3) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                              p.get(PipelineId::Floor, m->flags));
            pc.color = kHighlightDetailColor;
            vkCmdPushConstants(cmd, layout, stages, 0, sizeof(pc), &pc);
            vkCmdDrawIndexed(cmd, 3, 1, m->first_index + 3 * *s.highlight_triangle, 0,
                             d.gpu_instance);
            ++slot.draw_calls;
        }
        if (m && s.highlight_vertex && *s.highlight_vertex < m->vertex_count) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                              p.get(PipelineId::Glyphs, m->flags));
            const core::Aabb& box = instance_bounds(f)[d.gpu_instance];
            pc.glyph_length = 0.15f * (box.valid() ? glm::length(box.extent()) : 1.0f);
            pc.color = kHighlightDetailColor;
            for (std::uint32_t kind = 0; kind < 3; ++kind) {
                pc.mesh_flags = m->flags | kind << kGlyphKindShift;
                vkCmdPushConstants(cmd, layout, stages, 0, sizeof(pc), &pc);
                vkCmdDraw(cmd, 2, 1, 2 * *s.highlight_vertex, d.gpu_instance);
                ++slot.draw_calls;
            }
        }
    }
    if (!lines.empty()) draw_lines(f, lines); // binds its own pipeline; compare op ALWAYS
    vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_GREATER_OR_EQUAL);
}

} // namespace sherpa::render
