#include "draw.h"

#include <algorithm>
#include <cstring>

namespace sherpa::render {

namespace {

void push(VkCommandBuffer cmd, VkPipelineLayout layout, const GPUPushConstants& pc) {
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(pc), &pc);
}

// Draw of one group limited by `cull`, tallied into `tally`; false: nothing to draw.
bool draw_culled(FrameContext& f, std::size_t group, const PassCull& cull, GPUPushConstants& pc,
                 scene::CullStats& tally) {
    const DrawGroup& g = f.scene->groups()[group];
    const GpuMesh& mesh = f.scene->meshes()[g.mesh];
    const VkPipelineLayout layout = f.pipelines.layout();
    if (cull.gpu && f.culling->group_batch[group] != ~0u) {
        const std::uint32_t batch = f.culling->group_batch[group];
        const GpuCuller& culler = *cull.gpu;
        // Every object hidden: the culler holds no buffers and there is nothing to draw.
        if (culler.object_count() == 0) return false;
        pc.instance_ids = culler.instance_ids();
        push(f.cmd, layout, pc);
        vkCmdDrawIndexedIndirectCount(f.cmd, culler.draws(),
                                      batch * sizeof(VkDrawIndexedIndirectCommand),
                                      culler.draw_counts(), batch * sizeof(std::uint32_t), 1,
                                      sizeof(VkDrawIndexedIndirectCommand));
        ++tally.draw_calls; // triangles: from the indirect commands read back
        return true;
    }
    const std::uint32_t n = cull.group_visible[group];
    if (n == 0) return false;
    pc.instance_ids = f.resources.get(f.slot.cull_ids).address + cull.ids_offset;
    push(f.cmd, layout, pc);
    vkCmdDrawIndexed(f.cmd, mesh.index_count, n, mesh.first_index, 0, g.first_instance);
    tally.triangles += std::uint64_t{n} * triangles_of(mesh);
    ++tally.draw_calls;
    return true;
}

// The pipeline for `mesh` (bound when it differs from `bound`), the group's face
// culling (back faces unless double sided) and winding, and the mesh into `pc`.
// False: the pipeline does not draw this mesh (a fixed, triangle-only pipeline and
// a lines or points mesh).
bool set_group_state(FrameContext& f, const DrawPipeline& pipeline, const DrawGroup& g,
                     const GpuMesh& mesh, VkPipeline& bound, GPUPushConstants& pc) {
    if (pipeline.fixed != PipelineId::Count && !is_triangle_mesh(mesh.flags)) return false;
    if (const VkPipeline want = f.pipelines.resolve(pipeline, mesh.flags); want != bound) {
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, want);
        bound = want;
    }
    vkCmdSetCullMode(f.cmd, g.double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
    vkCmdSetFrontFace(f.cmd,
                      g.mirrored ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
    // The depth prepass draws triangles only: after it, opaque lines and points write
    // their own depth, or the background (depth EQUAL to the far plane) and blended
    // surfaces would be drawn over them.
    if (f.prepass && pipeline.fixed == PipelineId::Count && !pipeline.blend)
        vkCmdSetDepthWriteEnable(f.cmd, is_triangle_mesh(mesh.flags) ? VK_FALSE : VK_TRUE);
    set_mesh(pc, mesh, g.material);
    return true;
}

} // namespace

void set_viewport(VkCommandBuffer cmd, std::uint32_t width, std::uint32_t height) {
    // Negative height flips Y so clip-space +Y is up (see camera.h).
    VkViewport vp{0.0f, float(height), float(width), -float(height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {width, height}};
    vkCmdSetViewport(cmd, 0, 1, &vp);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void set_depth(VkCommandBuffer cmd, VkCompareOp op, bool write, float bias_constant,
               float bias_slope) {
    vkCmdSetDepthCompareOp(cmd, op);
    vkCmdSetDepthWriteEnable(cmd, write ? VK_TRUE : VK_FALSE);
    const bool bias = bias_constant != 0.0f || bias_slope != 0.0f;
    vkCmdSetDepthBiasEnable(cmd, bias ? VK_TRUE : VK_FALSE);
    if (bias) vkCmdSetDepthBias(cmd, bias_constant, 0.0f, bias_slope);
}

void set_mesh(GPUPushConstants& pc, const GpuMesh& mesh, std::uint32_t material) {
    pc.positions = mesh.stream[std::size_t(scene::VertexAttribute::Position)];
    pc.normals = mesh.stream[std::size_t(scene::VertexAttribute::Normal)];
    pc.tangents = mesh.stream[std::size_t(scene::VertexAttribute::Tangent)];
    pc.uv0 = mesh.stream[std::size_t(scene::VertexAttribute::TexCoord0)];
    pc.uv1 = mesh.stream[std::size_t(scene::VertexAttribute::TexCoord1)];
    pc.colors = mesh.stream[std::size_t(scene::VertexAttribute::Color0)];
    pc.material_id = material;
    pc.mesh_flags = mesh.flags;
    pc.motion = mesh.motion;
}

void bind_for_mesh(FrameContext& f, PipelineId id, const GpuMesh& mesh, VkPipeline& bound) {
    if (const VkPipeline want = f.pipelines.get(id, mesh.flags); want != bound) {
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, want);
        bound = want;
    }
}

std::uint32_t shown_count(const FrameContext& f, std::size_t group) {
    const DrawGroup& g = f.scene->groups()[group];
    return f.culling && f.culling->hidden_count > 0 ? f.culling->group_shown[group]
                                                    : g.instance_count;
}

VkDeviceAddress shown_ids(const FrameContext& f, VkDeviceAddress all) {
    return f.culling && f.culling->hidden_count > 0 ? f.resources.get(f.culling->shown).address
                                                    : all;
}

void draw_groups(FrameContext& f, DrawPipeline pipeline, scene::AlphaMode alpha,
                 const DrawView& view, scene::CullStats& tally) {
    if (!f.scene) return;
    VkCommandBuffer cmd = f.cmd;
    Pipelines& p = f.pipelines;
    VkPipeline bound = VK_NULL_HANDLE;
    GPUPushConstants pc = f.slot.push_base;
    pc.cascade = view.cascade;
    for (std::size_t gi = 0; gi < f.scene->groups().size(); ++gi) {
        const DrawGroup& g = f.scene->groups()[gi];
        if (g.alpha != alpha) continue;
        const GpuMesh& mesh = f.scene->meshes()[g.mesh];
        // Groups are sorted by mesh: consecutive groups mostly share a pipeline.
        if (!set_group_state(f, pipeline, g, mesh, bound, pc)) continue;
        if (view.cull) {
            if (draw_culled(f, gi, *view.cull, pc, tally)) ++f.slot.draw_calls;
            continue;
        }
        // Unculled: every instance, or while nodes are hidden the shown ones.
        const std::uint32_t count = shown_count(f, gi);
        if (count == 0) continue;
        pc.instance_ids = shown_ids(f, f.slot.push_base.instance_ids);
        push(cmd, p.layout(), pc);
        vkCmdDrawIndexed(cmd, mesh.index_count, count, mesh.first_index, 0, g.first_instance);
        ++f.slot.draw_calls;
        ++tally.draw_calls;
        tally.triangles += std::uint64_t{count} * triangles_of(mesh);
    }
}

void draw_blended(FrameContext& f, DrawPipeline pipeline, scene::CullStats& tally) {
    if (!f.scene) return;
    VkCommandBuffer cmd = f.cmd;
    Pipelines& p = f.pipelines;
    // Back to front by the view depth of each instance's bounds centre.
    struct Item {
        float depth;
        std::uint32_t group, instance;
    };
    std::vector<Item> items;
    const auto& groups = f.scene->groups();
    for (std::uint32_t gi = 0; gi < groups.size(); ++gi) {
        if (groups[gi].alpha != scene::AlphaMode::Blend) continue;
        for (std::uint32_t k = 0; k < groups[gi].instance_count; ++k) {
            const std::uint32_t inst = groups[gi].first_instance + k;
            const glm::vec3 c = instance_bounds(f)[inst].center();
            items.push_back({(f.slot.camera.view * glm::vec4(c, 1.0f)).z, gi, inst});
        }
    }
    if (items.empty()) return;
    std::stable_sort(items.begin(), items.end(),
                     [](const Item& a, const Item& b) { return a.depth < b.depth; });
    VkPipeline bound = VK_NULL_HANDLE;
    GPUPushConstants pc = f.slot.push_base;
    pc.cascade = kNoCascade;
    const PassCull* cull = f.slot.culling.camera();
    for (const Item& it : items) {
        if (cull ? !cull->visible[it.instance] : f.culling && f.culling->is_hidden(it.instance))
            continue;
        const DrawGroup& g = groups[it.group];
        const GpuMesh& mesh = f.scene->meshes()[g.mesh];
        if (!set_group_state(f, pipeline, g, mesh, bound, pc)) continue;
        push(cmd, p.layout(), pc);
        vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, 0, it.instance);
        ++f.slot.draw_calls;
        ++tally.draw_calls;
        tally.triangles += triangles_of(mesh);
    }
}

void draw_lines(FrameContext& f, const std::vector<GPULineVertex>& lines) {
    if (lines.empty()) return;
    FrameSlot& slot = f.slot;
    // Several line draws per frame: each gets its own range of the frame's buffer.
    const VkDeviceSize bytes = lines.size() * sizeof(GPULineVertex);
    VkDeviceSize offset = slot.lines_used;
    if (offset + bytes > slot.lines_capacity) {
        // Earlier draws of this frame keep the old buffer: destruction is deferred.
        f.resources.destroy(slot.lines);
        slot.lines_capacity = std::max<VkDeviceSize>(2 * (offset + bytes), 4096);
        slot.lines = f.resources.create_buffer(
            {slot.lines_capacity,
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
             gpu::MemoryUsage::Upload, "overlay lines"});
        offset = 0;
    }
    const gpu::Buffer& buf = f.resources.get(slot.lines);
    std::memcpy(static_cast<std::uint8_t*>(buf.mapped) + offset, lines.data(), bytes);
    slot.lines_used = offset + bytes;
    GPUPushConstants pc = slot.push_base;
    pc.lines = buf.address + offset;
    vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                      f.pipelines.get(PipelineId::BoxLines));
    push(f.cmd, f.pipelines.layout(), pc);
    vkCmdDraw(f.cmd, static_cast<std::uint32_t>(lines.size()), 1, 0, 0);
    ++slot.draw_calls;
}

void append_box(std::vector<GPULineVertex>& out, const core::Aabb& b, glm::vec4 color) {
    if (!b.valid()) return;
    auto corner = [&](int i) {
        return glm::vec4((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                         (i & 4) ? b.max.z : b.min.z, 1.0f);
    };
    // The 12 edges join corners that differ in exactly one coordinate bit.
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(i & bit)) {
                out.push_back({corner(i), color});
                out.push_back({corner(i | bit), color});
            }
}

} // namespace sherpa::render
