// Culling inside the renderer: the camera pass and each shadow cascade (against
// the cascade's culling volume, extended toward the light to the scene bounds).
// Both paths fill the same indirection (gl_InstanceIndex -> GPU instance, see
// common.glsl): the CPU path writes the visible instances of each draw group,
// compacted at the group's first instance, into a per-frame host-visible buffer
// (one region per pass); the GPU path runs shaders/cull.comp once per pass (one
// GpuCuller each), which fills indirect commands drawn with
// vkCmdDrawIndexedIndirectCount, and does no per-object CPU work: its statistics
// come from the indirect commands read back after the frame. Blended instances
// (drawn one by one in sorted order, never in shadows) use the CPU test in both.
// Check mode (RenderSettings::cull_check) also runs the CPU test on the GPU path,
// reads back the GPU's visible flags and counts the differences.
#include "frame_slot.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>

#include <chrono>
#include <cstring>
#include <numeric>

namespace sherpa::gpu {

namespace {

bool box_visible(const Frustum& f, const Aabb& box, CullMethod m) {
    switch (m) {
    case CullMethod::Sphere:
        return sphere_visible(f, box);
    case CullMethod::PVertex:
        return pvertex_visible(f, box);
    default:
        return exact_visible(f, box);
    }
}

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

void Renderer::build_culling() {
    culling_ = std::make_unique<Culling>();
    const auto& bounds = scene_->instance_bounds();
    culling_->boxes.assign(bounds);
    culling_->invalid.assign(bounds.size(), 0);
    for (std::uint32_t i : culling_->boxes.invalid) culling_->invalid[i] = 1;
    culling_->blended.assign(bounds.size(), 0);
    culling_->casters = static_cast<std::uint32_t>(bounds.size());
    for (const DrawGroup& g : scene_->groups())
        if (g.alpha == AlphaMode::Blend) {
            std::fill_n(culling_->blended.begin() + g.first_instance, g.instance_count, 1);
            culling_->casters -= g.instance_count;
        }
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

// Objects of the non-blended groups, one batch per group; the same objects for the
// camera and every cascade (blended instances cast no shadow).
void Renderer::build_gpu_culling() {
    const auto& groups = scene_->groups();
    std::vector<GPUCullObject> objects;
    std::vector<VkDrawIndexedIndirectCommand> draws;
    std::vector<std::uint32_t> instances;
    culling_->group_batch.assign(groups.size(), ~0u);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (groups[g].alpha == AlphaMode::Blend) continue;
        const GpuMesh& mesh = scene_->meshes()[groups[g].mesh];
        culling_->group_batch[g] = static_cast<std::uint32_t>(draws.size());
        // Objects of a batch sit at their GPU instance indices, so each batch's ids
        // start at the group's first instance.
        draws.push_back({mesh.index_count, 0, mesh.first_index, 0, groups[g].first_instance});
        for (std::uint32_t k = 0; k < groups[g].instance_count; ++k) {
            const std::uint32_t inst = groups[g].first_instance + k;
            objects.push_back(
                make_cull_object(scene_->instance_bounds()[inst], culling_->group_batch[g], inst));
            instances.push_back(inst);
        }
    }
    const auto pipeline = std::make_shared<const GpuCullPipeline>(context_); // one for all passes
    for (std::uint32_t p = 0; p < kMaxCullPasses; ++p) {
        auto culler = std::make_unique<GpuCuller>(context_, *resources_, kFramesInFlight, pipeline);
        culler->build(objects, draws, instances);
        culling_->gpu.push_back(std::move(culler));
    }
}

// CPU test of pass `pass` into slot.passes[pass]: visible flags, visible count per
// draw group, counts. `blended_only`: only the blended instances (GPU path).
void Renderer::cull_pass_cpu(FrameSlot& slot, std::uint32_t pass, CullMethod method,
                             bool blended_only) {
    PassCull& pc = slot.passes[pass];
    const auto& groups = scene_->groups();
    const BoxesSoA& boxes = culling_->boxes;
    pc.group_visible.assign(groups.size(), 0);
    if (blended_only) { // writes only the blended instances' flags: no O(instances) work
        pc.visible.resize(boxes.size());
        for (std::size_t g = 0; g < groups.size(); ++g) {
            if (groups[g].alpha != AlphaMode::Blend) continue;
            for (std::uint32_t k = 0; k < groups[g].instance_count; ++k) {
                const std::uint32_t i = groups[g].first_instance + k;
                pc.visible[i] = culling_->invalid[i] ||
                                box_visible(pc.frustum, scene_->instance_bounds()[i], method);
                pc.group_visible[g] += pc.visible[i];
            }
        }
        return;
    }
    pc.visible.resize(boxes.size());
    cull_boxes(pc.frustum, boxes, method, SimdLevel::Avx512, pc.visible);
    pc.cpu_tested = true;
    CullStats& st = pc.stats;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (pass > 0 && groups[g].alpha == AlphaMode::Blend) continue; // casts no shadow
        for (std::uint32_t k = 0; k < groups[g].instance_count; ++k) {
            const std::uint32_t i = groups[g].first_instance + k;
            pc.group_visible[g] += pc.visible[i];
            st.invalid += culling_->invalid[i];
        }
        st.visible += pc.group_visible[g];
    }
    st.culled = st.tested - st.visible;
}

void Renderer::cull_frame(VkCommandBuffer cmd, FrameSlot& slot, const RenderSettings& settings,
                          float aspect, std::uint32_t cascades) {
    slot.cull = CullPath::None;
    slot.cull_check = false;
    slot.pass_count = 0;
    slot.prepass = CullStats{};
    slot.prepass.pass = "depth_prepass";
    slot.history_pushed = false;
    if (!scene_ || !culling_) return;
    if (culling_->identity.valid())
        slot.push_base.instance_ids = resources_->get(culling_->identity).address;
    const std::uint32_t n = static_cast<std::uint32_t>(culling_->boxes.size());
    const std::uint32_t casters = culling_->casters;
    slot.pass_count = 1 + cascades;
    if (slot.passes.size() < slot.pass_count) slot.passes.resize(slot.pass_count);
    glm::mat4 camera_vp = slot.camera.proj * slot.camera.view;
    if (settings.freeze_cull) {
        const CameraView frozen = resolve_camera(*settings.freeze_cull, lighting_->info, aspect);
        camera_vp = frozen.proj * frozen.view;
    }
    for (std::uint32_t p = 0; p < slot.pass_count; ++p) {
        PassCull& pc = slot.passes[p];
        pc.cpu_tested = false;
        pc.stats = CullStats{};
        pc.stats.pass = p == 0 ? "camera" : "cascade" + std::to_string(p - 1);
        pc.stats.method = settings.cull_method;
        pc.stats.simd = std::min(SimdLevel::Avx512, best_simd_level());
        pc.stats.total = p == 0 ? n : casters;
        pc.stats.view_projection = p == 0 ? camera_vp : slot.cascades.cull_view_proj[p - 1];
        pc.frustum = frustum_from_view_projection(pc.stats.view_projection);
    }
    if (settings.cull == CullPath::None || n == 0) {
        for (std::uint32_t p = 0; p < slot.pass_count; ++p)
            slot.passes[p].stats.visible = slot.passes[p].stats.total;
        return;
    }
    const bool gpu = settings.cull == CullPath::Gpu;
    slot.cull = gpu ? CullPath::Gpu : CullPath::Cpu;
    slot.cull_check = settings.cull_check;
    // The cull-boxes overlay colours the camera pass's CPU result.
    const bool camera_cpu = !gpu || settings.cull_check || (settings.overlays & kOverlayCullBoxes);

    const VkDeviceSize id_bytes = std::max<VkDeviceSize>(VkDeviceSize{n} * 4 * kMaxCullPasses, 4);
    if (id_bytes > slot.cull_ids_capacity) {
        resources_->destroy(slot.cull_ids);
        slot.cull_ids_capacity = id_bytes;
        slot.cull_ids = resources_->create_buffer(
            {id_bytes,
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
             MemoryUsage::Upload, "culled instance ids"});
    }
    auto* ids = static_cast<std::uint32_t*>(resources_->get(slot.cull_ids).mapped);
    if (gpu && culling_->gpu.empty()) build_gpu_culling();
    const GpuCuller* any = gpu ? culling_->gpu.front().get() : nullptr;
    const VkDeviceSize draw_bytes =
        any ? VkDeviceSize{any->batch_count()} * sizeof(VkDrawIndexedIndirectCommand) : 0;
    const VkDeviceSize flag_bytes =
        any && slot.cull_check ? VkDeviceSize{any->object_count()} * 4 : 0;
    if (gpu) {
        const VkDeviceSize bytes =
            std::max<VkDeviceSize>((draw_bytes + flag_bytes) * kMaxCullPasses, 4);
        if (bytes > slot.cull_readback_capacity) {
            resources_->destroy(slot.cull_readback);
            slot.cull_readback_capacity = bytes;
            slot.cull_readback = resources_->create_buffer(
                {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback, "cull readback"});
        }
        if (!slot.cull_timestamps && context_.info().timestamps) {
            auto qi = vk_init<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
            qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
            qi.queryCount = 2 * kMaxCullPasses;
            VkQueryPool pool = VK_NULL_HANDLE;
            vk_check(vkCreateQueryPool(context_.device(), &qi, nullptr, &pool),
                     "vkCreateQueryPool");
            slot.cull_timestamps = UniqueQueryPool(context_.device(), pool);
        }
        if (slot.cull_timestamps)
            vkResetQueryPool(context_.device(), slot.cull_timestamps.get(), 0, 2 * kMaxCullPasses);
    }
    std::uint32_t block = 0;
    for (std::uint32_t i = 0; i < slots_.size(); ++i)
        if (slots_[i].get() == &slot) block = i % kFramesInFlight;

    const auto& groups = scene_->groups();
    for (std::uint32_t p = 0; p < slot.pass_count; ++p) {
        PassCull& pc = slot.passes[p];
        CullStats& st = pc.stats;
        const auto t0 = std::chrono::steady_clock::now();
        st.tested = st.total;
        if (!gpu || slot.cull_check || (p == 0 && camera_cpu))
            cull_pass_cpu(slot, p, settings.cull_method, false);
        else if (p == 0)
            cull_pass_cpu(slot, p, settings.cull_method, true);
        if (slot.cull_check && pc.cpu_tested) {
            std::vector<std::uint8_t> exact(pc.visible.size());
            cull_boxes(pc.frustum, culling_->boxes, CullMethod::Exact, SimdLevel::Avx512, exact);
            std::int64_t fp = 0;
            for (std::size_t i = 0; i < exact.size(); ++i)
                if (p == 0 || !culling_->blended[i]) fp += pc.visible[i] && !exact[i];
            st.false_positives = fp;
        }
        // Compacted ids of the CPU-culled groups (every group on the CPU path, the
        // blended ones on the GPU path).
        std::uint32_t* region = ids + VkDeviceSize{p} * n;
        if (!pc.group_visible.empty())
            for (std::size_t g = 0; g < groups.size(); ++g) {
                if (gpu && culling_->group_batch[g] != ~0u) continue;
                std::uint32_t* out = region + groups[g].first_instance;
                for (std::uint32_t k = 0; k < groups[g].instance_count; ++k)
                    if (pc.visible[groups[g].first_instance + k])
                        *out++ = groups[g].first_instance + k;
            }
        if (gpu) {
            GpuCuller& culler = *culling_->gpu[p];
            st.gpu = true;
            if (slot.cull_timestamps)
                vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                     slot.cull_timestamps.get(), 2 * p);
            culler.record(cmd, pc.frustum, settings.cull_method, block, false);
            if (slot.cull_timestamps)
                vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                     slot.cull_timestamps.get(), 2 * p + 1);
            pc.readback = (draw_bytes + flag_bytes) * p;
            const VkBuffer rb = resources_->get(slot.cull_readback).buffer.get();
            const VkBufferCopy draws{0, pc.readback, draw_bytes};
            if (draw_bytes) vkCmdCopyBuffer(cmd, culler.draws(), rb, 1, &draws);
            const VkBufferCopy flags{0, pc.readback + draw_bytes, flag_bytes};
            if (flag_bytes) vkCmdCopyBuffer(cmd, culler.visible_flags(), rb, 1, &flags);
        }
        st.cpu_ms = ms_since(t0);
    }
    if (gpu)
        memory_barrier(cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

bool Renderer::draw_culled(VkCommandBuffer cmd, FrameSlot& slot, VkPipelineLayout layout,
                           std::size_t group, std::uint32_t pass, GPUPushConstants& pc,
                           CullStats& tally) {
    const DrawGroup& g = scene_->groups()[group];
    const GpuMesh& mesh = scene_->meshes()[g.mesh];
    if (slot.cull == CullPath::Gpu && culling_->group_batch[group] != ~0u) {
        const std::uint32_t batch = culling_->group_batch[group];
        const GpuCuller& culler = *culling_->gpu[pass];
        pc.instance_ids = culler.instance_ids();
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                           0, sizeof(pc), &pc);
        vkCmdDrawIndexedIndirectCount(
            cmd, culler.draws(), batch * sizeof(VkDrawIndexedIndirectCommand), culler.draw_counts(),
            batch * sizeof(std::uint32_t), 1, sizeof(VkDrawIndexedIndirectCommand));
        ++tally.draw_calls; // triangles: from the indirect commands read back
        return true;
    }
    const std::uint32_t n = slot.passes[pass].group_visible[group];
    if (n == 0) return false;
    pc.instance_ids = resources_->get(slot.cull_ids).address +
                      VkDeviceSize{pass} * culling_->boxes.size() * sizeof(std::uint32_t);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(pc), &pc);
    vkCmdDrawIndexed(cmd, mesh.index_count, n, mesh.first_index, 0, g.first_instance);
    tally.triangles += std::uint64_t{n} * mesh.index_count / 3;
    ++tally.draw_calls;
    return true;
}

} // namespace sherpa::gpu
