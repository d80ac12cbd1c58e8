// The selection highlight (RenderSettings::highlight_*): drawn after every other
// overlay. The instance's visible surface is tinted translucent orange (depth
// tested, pulled towards the camera like the wireframe overlay), so its shading
// still shows, and its world box is drawn through everything in orange; a selected triangle is
// filled and a selected vertex gets a normal/tangent/bitangent tripod, both magenta and never
// hidden by depth.
#include "draw.h"
#include "passes.h"

#include <algorithm>

namespace sherpa::gpu {

void HighlightPass::record(FrameContext& f) {
    const RenderSettings& s = f.settings;
    const GpuScene* scene = f.scene;
    if (!scene || !s.highlight_instance || !f.culling || !f.culling->identity.valid()) return;
    VkCommandBuffer cmd = f.cmd;
    Pipelines& p = f.pipelines;
    FrameSlot& slot = f.slot;
    const auto& ids = scene->scene_instances();
    const auto found = std::find(ids.begin(), ids.end(), *s.highlight_instance);
    if (found == ids.end()) return; // not drawn: nothing to highlight
    const auto gpu_instance = static_cast<std::uint32_t>(found - ids.begin());
    if (f.culling->is_hidden(gpu_instance)) return; // hidden: no pixels to point at
    const auto group =
        std::find_if(scene->groups().begin(), scene->groups().end(), [&](const DrawGroup& g) {
            return gpu_instance >= g.first_instance &&
                   gpu_instance < g.first_instance + g.instance_count;
        });
    if (group == scene->groups().end()) return;
    const GpuMesh& m = scene->meshes()[group->mesh];

    const VkPipelineLayout layout = p.layout();
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    GPUPushConstants pc = slot.push_base;
    // Identity ids: gl_InstanceIndex (the draw's first instance) is the GPU instance.
    pc.instance_ids = f.resources.get(f.culling->identity).address;
    set_mesh(pc, m, group->material); // depth.vert reads the UVs too
    pc.cascade = kNoCascade;
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
    vkCmdSetDepthWriteEnable(cmd, VK_FALSE);

    // The instance: a translucent tint on its visible surface (not a wireframe: on a
    // dense mesh that is solid orange and hides what the user selected it to see).
    // Lines and points have no surface to tint: their box and vertex show them.
    const bool triangles = is_triangle_mesh(m.flags);
    if (triangles) {
        vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_GREATER_OR_EQUAL);
        vkCmdSetDepthBiasEnable(cmd, VK_TRUE);
        vkCmdSetDepthBias(cmd, 1.0f, 0.0f, 1.0f);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.get(PipelineId::Tint, m.flags));
        pc.color = kHighlightTint;
        vkCmdPushConstants(cmd, layout, stages, 0, sizeof(pc), &pc);
        vkCmdDrawIndexed(cmd, m.index_count, 1, m.first_index, 0, gpu_instance);
        ++slot.draw_calls;
        vkCmdSetDepthBiasEnable(cmd, VK_FALSE);
    }

    // Detail that must never hide behind other surfaces.
    vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_ALWAYS);
    if (triangles && s.highlight_triangle && *s.highlight_triangle < m.index_count / 3) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.get(PipelineId::Floor, m.flags));
        pc.color = kHighlightDetailColor;
        vkCmdPushConstants(cmd, layout, stages, 0, sizeof(pc), &pc);
        vkCmdDrawIndexed(cmd, 3, 1, m.first_index + 3 * *s.highlight_triangle, 0, gpu_instance);
        ++slot.draw_calls;
    }
    if (s.highlight_vertex && *s.highlight_vertex < m.vertex_count) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.get(PipelineId::Glyphs, m.flags));
        const Aabb& box = instance_bounds(f)[gpu_instance];
        pc.glyph_length = 0.15f * (box.valid() ? glm::length(box.extent()) : 1.0f);
        pc.color = kHighlightDetailColor;
        for (std::uint32_t kind = 0; kind < 3; ++kind) {
            pc.mesh_flags = m.flags | kind << kGlyphKindShift;
            vkCmdPushConstants(cmd, layout, stages, 0, sizeof(pc), &pc);
            vkCmdDraw(cmd, 2, 1, 2 * *s.highlight_vertex, gpu_instance);
            ++slot.draw_calls;
        }
    }
    std::vector<GPULineVertex> lines;
    append_box(lines, instance_bounds(f)[gpu_instance], kHighlightColor);
    draw_lines(f, lines); // binds its own pipeline; compare op stays ALWAYS
    vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_GREATER_OR_EQUAL);
}

} // namespace sherpa::gpu
