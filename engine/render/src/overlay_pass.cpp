// Overlays drawn over the shaded image: wireframe, per-vertex normal / tangent /
// bitangent glyphs (generated in the vertex shader from the mesh streams) and
// instance world AABBs and the skeleton (CPU-built line lists).
#include "draw.h"
#include "passes.h"
#include "scene_state.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/gpu_structs.h>

#include <algorithm>
#include <cstring>

namespace sherpa::render {

void OverlayPass::record(FrameContext& f) {
    if (!f.scene) return;
    f.slot.lines_used = 0;
    const FrameRequest& s = f.settings;
    if (s.overlays == 0) return;
    VkCommandBuffer cmd = f.cmd;
    Pipelines& p = f.pipelines;
    FrameSlot& slot = f.slot;
    const GpuScene* scene = f.scene;
    const VkPipelineLayout layout = p.layout();
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    // Overlays sit on top of the surface they describe: test, never write depth.
    vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_GREATER_OR_EQUAL);
    vkCmdSetDepthWriteEnable(cmd, VK_FALSE);
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
    vkCmdSetFrontFace(cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);

    auto for_each_group = [&](auto&& fn) {
        for (std::size_t gi = 0; gi < scene->groups().size(); ++gi) {
            const DrawGroup& g = scene->groups()[gi];
            const std::uint32_t count = shown_count(f, gi);
            if (count == 0) continue; // every instance hidden
            GPUPushConstants pc = slot.push_base;
            pc.instance_ids = shown_ids(f, pc.instance_ids);
            const GpuMesh& m = scene->meshes()[g.mesh];
            set_mesh(pc, m, g.material);
            pc.cascade = kNoCascade;
            fn(g, m, pc, count);
        }
    };

    if (s.overlays & kOverlayWireframe) {
        VkPipeline bound = VK_NULL_HANDLE;
        // Reverse-Z: a positive bias pulls the lines towards the camera, off the fill.
        vkCmdSetDepthBiasEnable(cmd, VK_TRUE);
        vkCmdSetDepthBias(cmd, 1.0f, 0.0f, 1.0f);
        for_each_group(
            [&](const DrawGroup& g, const GpuMesh& m, GPUPushConstants& pc, std::uint32_t count) {
                if (!is_triangle_mesh(m.flags)) return; // lines and points are their own wireframe
                bind_for_mesh(f, PipelineId::Wireframe, m, bound);
                pc.color = glm::vec4(0.25f, 0.85f, 1.0f, 1.0f);
                vkCmdPushConstants(cmd, layout, stages, 0, sizeof(pc), &pc);
                vkCmdDrawIndexed(cmd, m.index_count, count, m.first_index, 0, g.first_instance);
                ++slot.draw_calls;
            });
    }
    vkCmdSetDepthBiasEnable(cmd, VK_FALSE);

    const std::pair<Overlay, glm::vec4> glyphs[] = {
        {kOverlayNormals, {0.2f, 0.45f, 1.0f, 1.0f}},
        {kOverlayTangents, {1.0f, 0.2f, 0.2f, 1.0f}},
        {kOverlayBitangents, {0.2f, 1.0f, 0.3f, 1.0f}},
    };
    for (std::uint32_t kind = 0; kind < 3; ++kind) {
        if (!(s.overlays & glyphs[kind].first)) continue;
        VkPipeline bound = VK_NULL_HANDLE;
        for_each_group([&](const DrawGroup& g, const GpuMesh& m, GPUPushConstants& pc,
                           std::uint32_t count) {
            bind_for_mesh(f, PipelineId::Glyphs, m, bound);
            pc.mesh_flags |= kind << kGlyphKindShift;
            pc.color = glyphs[kind].second;
            pc.glyph_length = s.glyph_length > 0.0f
                                  ? s.glyph_length
                                  : 0.02f * (f.lighting.cameras.bounds.valid()
                                                 ? glm::length(f.lighting.cameras.bounds.extent())
                                                 : 1.0f);
            vkCmdPushConstants(cmd, layout, stages, 0, sizeof(pc), &pc);
            vkCmdDraw(cmd, 2 * m.vertex_count, count, 0, g.first_instance);
            ++slot.draw_calls;
        });
    }

    if (s.overlays & kOverlayBounds) {
        std::vector<GPULineVertex> lines;
        const auto& bounds = instance_bounds(f);
        for (std::uint32_t i = 0; i < bounds.size(); ++i)
            if (!f.culling || !f.culling->is_hidden(i))
                append_box(lines, bounds[i], glm::vec4(1.0f, 0.85f, 0.1f, 1.0f));
        draw_lines(f, lines);
    }
    if (s.overlays & kOverlayCullBoxes) draw_cull_boxes(f);
    if (s.overlays & kOverlaySkeleton) draw_skeleton(f);
}

// Joints inside the skin they move: drawn through every surface, posed as the meshes
// are (PosePass).
void OverlayPass::draw_skeleton(FrameContext& f) {
    const core::Aabb& bounds = f.lighting.cameras.bounds;
    std::vector<GPULineVertex> lines;
    pose_.append_skeleton_lines(lines, f.settings,
                                0.015f * (bounds.valid() ? glm::length(bounds.extent()) : 1.0f));
    if (lines.empty()) return;
    vkCmdSetDepthCompareOp(f.cmd, VK_COMPARE_OP_ALWAYS);
    draw_lines(f, lines);
    vkCmdSetDepthCompareOp(f.cmd, VK_COMPARE_OP_GREATER_OR_EQUAL);
}

// Culling made visible: instance boxes green (visible), red (culled) or yellow
// (kept by the conservative test though the exact test rejects it: its false
// positives); the culling frustum's edges in white (a frozen culling camera shows
// where culling happened from) and each shadow cascade's volume in blue.
void OverlayPass::draw_cull_boxes(FrameContext& f) {
    const PassCull* camera = f.slot.culling.camera();
    if (!camera) return;
    std::vector<GPULineVertex> lines;
    const auto& bounds = instance_bounds(f);
    for (std::size_t i = 0; i < bounds.size(); ++i) {
        glm::vec4 color(0.9f, 0.15f, 0.1f, 1.0f);
        if (f.culling && f.culling->is_hidden(i)) continue; // drawn by no pass
        if (camera->visible[i])
            color = scene::exact_visible(camera->frustum, bounds[i])
                        ? glm::vec4(0.2f, 0.9f, 0.3f, 1.0f)
                        : glm::vec4(1.0f, 0.9f, 0.1f, 1.0f);
        append_box(lines, bounds[i], color);
    }
    // Corners at infinity (infinite far plane) end at twice the scene's size.
    const float reach = 2.0f * glm::length(f.scene->bounds().extent()) + 1.0f;
    auto append_frustum = [&](const scene::Frustum& frustum, glm::vec4 color) {
        auto corner = [&](int i) {
            const glm::vec4 c = frustum.corners[static_cast<std::size_t>(i)];
            if (c.w != 0.0f) return glm::vec4(glm::vec3(c), 1.0f);
            const glm::vec4 apex = frustum.corners[static_cast<std::size_t>(i ^ 4)]; // near corner
            return glm::vec4(glm::vec3(apex) + glm::normalize(glm::vec3(c)) * reach, 1.0f);
        };
        for (int i = 0; i < 8; ++i)
            for (int bit = 1; bit < 8; bit <<= 1)
                if (!(i & bit)) {
                    lines.push_back({corner(i), color});
                    lines.push_back({corner(i | bit), color});
                }
    };
    append_frustum(camera->frustum, glm::vec4(1.0f));
    const auto* frame = static_cast<const GPUFrameData*>(f.resources.get(f.slot.frame_data).mapped);
    for (std::uint32_t c = 0; c < std::min(frame->params.z, kMaxCascades); ++c)
        append_frustum(scene::frustum_from_view_projection(frame->shadow_view_proj[c]),
                       glm::vec4(0.3f, 0.5f, 1.0f, 1.0f));
    draw_lines(f, lines);
}

} // namespace sherpa::render
