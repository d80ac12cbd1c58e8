// Camera-pass culling inside the renderer. Both paths fill the same indirection
// (gl_InstanceIndex -> GPU instance, see common.glsl): the CPU path writes the
// visible instances of each draw group, compacted at the group's first instance,
// into a per-frame host-visible buffer; the GPU path runs shaders/cull.comp, which
// fills the indirect commands drawn with vkCmdDrawIndexedIndirectCount. Blended
// instances are drawn one by one in sorted order and use the CPU test in both.
#include "frame_slot.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>

#include <chrono>
#include <cstring>
#include <numeric>

namespace sherpa::gpu {

void Renderer::build_culling() {
    culling_ = std::make_unique<Culling>();
    const auto& bounds = scene_->instance_bounds();
    culling_->boxes.assign(bounds);
    if (bounds.empty()) return;
    std::vector<std::uint32_t> identity(bounds.size());
    std::iota(identity.begin(), identity.end(), 0u);
    const VkDeviceSize bytes = identity.size() * sizeof(std::uint32_t);
    culling_->identity = resources_->create_buffer(
        {bytes,
         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
             VK_BUFFER_USAGE_TRANSFER_DST_BIT,
         MemoryUsage::DeviceLocal, "instance ids (identity)"});
    UploadBatch upload(*resources_);
    upload.upload_buffer(culling_->identity, 0, identity.data(), bytes);
    upload.submit_and_wait();
}

void Renderer::cull_camera(VkCommandBuffer cmd, FrameSlot& slot, const RenderSettings& settings,
                           float aspect) {
    slot.cull = CullPath::None;
    slot.cull_stats = CullStats{};
    if (!scene_ || !culling_ || !culling_->identity.valid()) return;
    slot.push_base.instance_ids = resources_->get(culling_->identity).address;
    if (settings.cull == CullPath::None) return;
    const auto t0 = std::chrono::steady_clock::now();
    glm::mat4 view_proj = slot.camera.proj * slot.camera.view;
    if (settings.freeze_cull) {
        const CameraView frozen = resolve_camera(*settings.freeze_cull, lighting_->info, aspect);
        view_proj = frozen.proj * frozen.view;
    }
    slot.cull_frustum = frustum_from_view_projection(view_proj);
    const BoxesSoA& boxes = culling_->boxes;
    slot.visible.resize(boxes.size());
    const CullCounts counts =
        cull_boxes(slot.cull_frustum, boxes, settings.cull_method, SimdLevel::Avx512, slot.visible);
    const auto& groups = scene_->groups();
    slot.group_visible.assign(groups.size(), 0);
    CullStats& st = slot.cull_stats;
    st.pass = "camera";
    st.method = settings.cull_method;
    st.total = st.tested = counts.tested;
    st.visible = counts.visible;
    st.culled = counts.culled;
    st.invalid = counts.invalid;
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (std::uint32_t k = 0; k < groups[g].instance_count; ++k)
            slot.group_visible[g] += slot.visible[groups[g].first_instance + k];

    if (settings.cull == CullPath::Gpu) {
        if (!culling_->gpu) { // objects of the non-blended groups, one batch per group
            std::vector<GPUCullObject> objects;
            std::vector<VkDrawIndexedIndirectCommand> draws;
            std::vector<std::uint32_t> instances;
            culling_->group_batch.assign(groups.size(), ~0u);
            for (std::size_t g = 0; g < groups.size(); ++g) {
                if (groups[g].alpha == AlphaMode::Blend) continue;
                const GpuMesh& mesh = scene_->meshes()[groups[g].mesh];
                culling_->group_batch[g] = static_cast<std::uint32_t>(draws.size());
                // Objects of a batch sit at their GPU instance indices, so each
                // batch's ids start at the group's first instance.
                draws.push_back(
                    {mesh.index_count, 0, mesh.first_index, 0, groups[g].first_instance});
                for (std::uint32_t k = 0; k < groups[g].instance_count; ++k) {
                    const std::uint32_t inst = groups[g].first_instance + k;
                    objects.push_back(make_cull_object(scene_->instance_bounds()[inst],
                                                       culling_->group_batch[g], inst));
                    instances.push_back(inst);
                }
            }
            culling_->gpu = std::make_unique<GpuCuller>(context_, *resources_, kFramesInFlight);
            culling_->gpu->build(objects, draws, std::move(instances));
        }
        std::uint32_t block = 0;
        for (std::uint32_t i = 0; i < slots_.size(); ++i)
            if (slots_[i].get() == &slot) block = i % kFramesInFlight;
        culling_->gpu->record(cmd, slot.cull_frustum, settings.cull_method, block, false);
        st.gpu = true;
        slot.cull = CullPath::Gpu;
    } else {
        const VkDeviceSize bytes = std::max<VkDeviceSize>(boxes.size() * sizeof(std::uint32_t), 4);
        if (bytes > slot.cull_ids_capacity) {
            resources_->destroy(slot.cull_ids);
            slot.cull_ids_capacity = bytes;
            slot.cull_ids = resources_->create_buffer(
                {bytes,
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                 MemoryUsage::Upload, "culled instance ids"});
        }
        auto* ids = static_cast<std::uint32_t*>(resources_->get(slot.cull_ids).mapped);
        for (const DrawGroup& g : groups) {
            std::uint32_t* out = ids + g.first_instance;
            for (std::uint32_t k = 0; k < g.instance_count; ++k)
                if (slot.visible[g.first_instance + k]) *out++ = g.first_instance + k;
        }
        slot.cull = CullPath::Cpu;
    }
    st.cpu_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool Renderer::draw_culled(VkCommandBuffer cmd, FrameSlot& slot, VkPipelineLayout layout,
                           std::size_t group, GPUPushConstants& pc) {
    const DrawGroup& g = scene_->groups()[group];
    const GpuMesh& mesh = scene_->meshes()[g.mesh];
    if (slot.cull == CullPath::Gpu && culling_->group_batch[group] != ~0u) {
        const std::uint32_t batch = culling_->group_batch[group];
        pc.instance_ids = culling_->gpu->instance_ids();
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                           0, sizeof(pc), &pc);
        vkCmdDrawIndexedIndirectCount(cmd, culling_->gpu->draws(),
                                      batch * sizeof(VkDrawIndexedIndirectCommand),
                                      culling_->gpu->draw_counts(), batch * sizeof(std::uint32_t),
                                      1, sizeof(VkDrawIndexedIndirectCommand));
        slot.cull_stats.triangles +=
            std::uint64_t{slot.group_visible[group]} * mesh.index_count / 3;
        ++slot.cull_stats.draw_calls;
        return true;
    }
    const std::uint32_t n = slot.group_visible[group];
    if (n == 0) return false;
    pc.instance_ids = resources_->get(slot.cull_ids).address;
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(pc), &pc);
    vkCmdDrawIndexed(cmd, mesh.index_count, n, mesh.first_index, 0, g.first_instance);
    slot.cull_stats.triangles += std::uint64_t{n} * mesh.index_count / 3;
    ++slot.cull_stats.draw_calls;
    return true;
}

} // namespace sherpa::gpu
