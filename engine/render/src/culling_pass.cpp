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
// Check mode (FrameRequest::cull_check) also runs the CPU test on the GPU path,
// reads back the GPU's visible flags and counts the differences.
#include "passes.h"
#include "scene_state.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/gpu/vk_helpers.h>

#include <chrono>
#include <cstring>
#include <numeric>
#include <span>

namespace sherpa::render {

namespace {

bool box_visible(const scene::Frustum& f, const core::Aabb& box, scene::CullMethod m) {
    switch (m) {
    case scene::CullMethod::Sphere:
        return scene::sphere_visible(f, box);
    case scene::CullMethod::PVertex:
        return scene::pvertex_visible(f, box);
    default:
        return scene::exact_visible(f, box);
    }
}

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// A device-local list of GPU instance ids (what push constants' instance_ids point at).
gpu::BufferHandle upload_instance_ids(gpu::ResourceManager& resources,
                                      std::span<const std::uint32_t> ids, const char* name) {
    const VkDeviceSize bytes = ids.size_bytes();
    const gpu::BufferHandle buffer = resources.create_buffer(
        {bytes,
         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
             VK_BUFFER_USAGE_TRANSFER_DST_BIT,
         gpu::MemoryUsage::DeviceLocal, name});
    gpu::UploadBatch upload(resources);
    upload.upload_buffer(buffer, 0, ids.data(), bytes);
    upload.submit_and_wait();
    return buffer;
}

} // namespace

CullingPass::CullingPass(gpu::Context& context, gpu::ResourceManager& resources)
    : context_(context), resources_(resources) {}

CullingPass::~CullingPass() {
    reset();
}

void CullingPass::reset() {
    cascade_stats_.clear();
    if (culling_) resources_.destroy(culling_->identity);
    if (culling_) resources_.destroy(culling_->shown);
    culling_.reset();
}

void CullingPass::build(const GpuScene& scene) {
    reset();
    culling_ = std::make_unique<SceneCulling>();
    const auto& bounds = scene.instance_bounds();
    culling_->boxes.assign(bounds);
    culling_->invalid.assign(bounds.size(), 0);
    for (std::uint32_t i : culling_->boxes.invalid) culling_->invalid[i] = 1;
    culling_->blended.assign(bounds.size(), 0);
    culling_->casters = static_cast<std::uint32_t>(bounds.size());
    for (const DrawGroup& g : scene.groups())
        if (g.alpha == scene::AlphaMode::Blend) {
            std::fill_n(culling_->blended.begin() + g.first_instance, g.instance_count, 1);
            culling_->casters -= g.instance_count;
        }
    if (bounds.empty()) return;
    std::vector<std::uint32_t> identity(bounds.size());
    std::iota(identity.begin(), identity.end(), 0u);
    culling_->identity = upload_instance_ids(resources_, identity, "instance ids (identity)");
}

void CullingPass::set_hidden(std::vector<std::uint8_t> hidden, const GpuScene& scene) {
    if (!culling_) return;
    SceneCulling& c = *culling_;
    hidden.resize(c.boxes.size(), 0);
    c.hidden = std::move(hidden);
    c.hidden_count = c.hidden_casters = 0;
    for (std::size_t i = 0; i < c.hidden.size(); ++i) {
        c.hidden_count += c.hidden[i] != 0;
        c.hidden_casters += c.hidden[i] != 0 && !c.blended[i];
    }
    // The cullers' objects leave hidden instances out: rebuilt on next use.
    c.gpu.clear();
    c.group_batch.clear();
    c.gpu_object_batch.clear();
    ++c.objects_version;
    resources_.destroy(c.shown);
    const auto& groups = scene.groups();
    c.group_shown.assign(groups.size(), 0);
    if (c.hidden_count == 0) return;
    std::vector<std::uint32_t> shown(c.hidden.size(), 0);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        std::uint32_t* out = shown.data() + groups[g].first_instance;
        for (std::uint32_t k = 0; k < groups[g].instance_count; ++k)
            if (!c.hidden[groups[g].first_instance + k]) {
                *out++ = groups[g].first_instance + k;
                ++c.group_shown[g];
            }
    }
    c.shown = upload_instance_ids(resources_, shown, "instance ids (shown)");
}

// Objects of the non-blended groups, one batch per group; the same objects for the
// camera and every cascade (blended instances cast no shadow).
void CullingPass::build_gpu(const GpuScene& scene) {
    const auto& groups = scene.groups();
    std::vector<GPUCullObject> objects;
    std::vector<VkDrawIndexedIndirectCommand> draws;
    std::vector<std::uint32_t> instances;
    culling_->group_batch.assign(groups.size(), ~0u);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (groups[g].alpha == scene::AlphaMode::Blend) continue;
        const GpuMesh& mesh = scene.meshes()[groups[g].mesh];
        culling_->group_batch[g] = static_cast<std::uint32_t>(draws.size());
        // Objects of a batch sit at their GPU instance indices, so each batch's ids
        // start at the group's first instance.
        draws.push_back({mesh.index_count, 0, mesh.first_index, 0, groups[g].first_instance});
        for (std::uint32_t k = 0; k < groups[g].instance_count; ++k) {
            const std::uint32_t inst = groups[g].first_instance + k;
            if (culling_->is_hidden(inst)) continue; // drawn by no pass
            objects.push_back(
                make_cull_object(scene.instance_bounds()[inst], culling_->group_batch[g], inst));
            instances.push_back(inst);
            culling_->gpu_object_batch.push_back(culling_->group_batch[g]);
        }
    }
    const auto pipeline = std::make_shared<const GpuCullPipeline>(context_); // one for all views
    for (std::uint32_t p = 0; p < kMaxCullPasses; ++p) {
        auto culler =
            std::make_unique<GpuCuller>(context_, resources_, Renderer::kFramesInFlight, pipeline);
        culler->build(objects, draws, instances);
        culling_->gpu.push_back(std::move(culler));
    }
}

// CPU test of `view`: visible flags, visible count per draw group, counts.
// `caster_view`: a shadow cascade (blended instances cast no shadow).
// `blended_only`: only the blended instances (GPU path).
void CullingPass::test_cpu(FrameContext& f, PassCull& view, bool caster_view, bool blended_only) {
    const scene::CullMethod method = f.settings.cull_method;
    const auto& groups = f.scene->groups();
    const scene::BoxesSoA& boxes = culling_->boxes;
    view.group_visible.assign(groups.size(), 0);
    if (blended_only) { // writes only the blended instances' flags: no O(instances) work
        view.visible.resize(boxes.size());
        for (std::size_t g = 0; g < groups.size(); ++g) {
            if (groups[g].alpha != scene::AlphaMode::Blend) continue;
            for (std::uint32_t k = 0; k < groups[g].instance_count; ++k) {
                const std::uint32_t i = groups[g].first_instance + k;
                view.visible[i] = !culling_->is_hidden(i) &&
                                  (culling_->invalid[i] ||
                                   box_visible(view.frustum, instance_bounds(f)[i], method));
                view.group_visible[g] += view.visible[i];
            }
        }
        return;
    }
    view.visible.resize(boxes.size());
    scene::cull_boxes(view.frustum, boxes, method, core::SimdLevel::Avx512, view.visible);
    view.cpu_tested = true;
    scene::CullStats& st = view.stats;
    if (culling_->hidden_count > 0)
        for (std::size_t i = 0; i < view.visible.size(); ++i)
            if (culling_->hidden[i]) view.visible[i] = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (caster_view && groups[g].alpha == scene::AlphaMode::Blend) continue; // casts no shadow
        for (std::uint32_t k = 0; k < groups[g].instance_count; ++k) {
            const std::uint32_t i = groups[g].first_instance + k;
            view.group_visible[g] += view.visible[i];
            st.invalid += culling_->invalid[i] && !culling_->is_hidden(i);
        }
        st.visible += view.group_visible[g];
    }
    st.culled = st.tested - st.visible;
}

// A moving scene's instance boxes in this frame's pose, for the CPU test; rebuilt only
// when the pose is another than the boxes hold (paused or default pose: no work).
void CullingPass::use_posed_bounds(FrameContext& f) {
    if (culling_->boxes_pose == f.slot.pose_key) return;
    culling_->boxes_pose = f.slot.pose_key;
    const auto& bounds = f.slot.posed_bounds;
    culling_->boxes.assign(bounds);
    std::fill(culling_->invalid.begin(), culling_->invalid.end(), 0);
    for (std::uint32_t i : culling_->boxes.invalid) culling_->invalid[i] = 1;
}

// The GPU cullers' objects with this frame's posed boxes, in the cullers' order,
// into the slot's host-visible buffer (rewritten only when the slot's pose or scene
// changed since); returns its address.
VkDeviceAddress CullingPass::write_posed_objects(FrameContext& f) {
    FrameSlot& slot = f.slot;
    const GpuCuller& culler = *culling_->gpu.front();
    const auto& instances = culler.object_instances();
    const VkDeviceSize bytes = std::max<VkDeviceSize>(instances.size(), 1) * sizeof(GPUCullObject);
    if (bytes > slot.cull_objects_capacity) {
        resources_.destroy(slot.cull_objects);
        slot.cull_objects_capacity = bytes;
        slot.cull_objects = resources_.create_buffer(
            {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
             gpu::MemoryUsage::Upload, "posed cull objects"});
        slot.cull_objects_generation = 0; // a new buffer: nothing written yet
    }
    const gpu::Buffer& buf = resources_.get(slot.cull_objects);
    if (slot.cull_objects_generation == slot.pose_generation &&
        slot.cull_objects_pose == slot.pose_key &&
        slot.cull_objects_version == culling_->objects_version)
        return buf.address;
    slot.cull_objects_generation = slot.pose_generation;
    slot.cull_objects_pose = slot.pose_key;
    slot.cull_objects_version = culling_->objects_version;
    auto* out = static_cast<GPUCullObject*>(buf.mapped);
    for (std::size_t k = 0; k < instances.size(); ++k)
        out[k] = make_cull_object(slot.posed_bounds[instances[k]], culling_->gpu_object_batch[k],
                                  instances[k]);
    return buf.address;
}

// Per-frame buffers sized for `instances`: compacted ids (CPU path), the readback of
// the indirect commands and flags and the dispatch timestamps (GPU path).
void CullingPass::prepare_buffers(FrameContext& f, std::uint32_t instances) {
    FrameSlot& slot = f.slot;
    const VkDeviceSize id_bytes =
        std::max<VkDeviceSize>(VkDeviceSize{instances} * 4 * kMaxCullPasses, 4);
    if (id_bytes > slot.cull_ids_capacity) {
        resources_.destroy(slot.cull_ids);
        slot.cull_ids_capacity = id_bytes;
        slot.cull_ids = resources_.create_buffer(
            {id_bytes,
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
             gpu::MemoryUsage::Upload, "culled instance ids"});
    }
    if (slot.culling.path != CullPath::Gpu) return;
    if (culling_->gpu.empty()) build_gpu(*f.scene);
    const GpuCuller& any = *culling_->gpu.front();
    const VkDeviceSize draw_bytes =
        VkDeviceSize{any.batch_count()} * sizeof(VkDrawIndexedIndirectCommand);
    const VkDeviceSize flag_bytes = slot.culling.check ? VkDeviceSize{any.object_count()} * 4 : 0;
    const VkDeviceSize bytes =
        std::max<VkDeviceSize>((draw_bytes + flag_bytes) * kMaxCullPasses, 4);
    if (bytes > slot.cull_readback_capacity) {
        resources_.destroy(slot.cull_readback);
        slot.cull_readback_capacity = bytes;
        slot.cull_readback = resources_.create_buffer(
            {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUsage::Readback, "cull readback"});
    }
    if (!slot.cull_timestamps && context_.info().timestamps)
        slot.cull_timestamps =
            gpu::create_query_pool(context_.device(), VK_QUERY_TYPE_TIMESTAMP, 2 * kMaxCullPasses);
    if (slot.cull_timestamps)
        vkResetQueryPool(context_.device(), slot.cull_timestamps.get(), 0, 2 * kMaxCullPasses);
}

void CullingPass::record(FrameContext& f) {
    FrameSlot& slot = f.slot;
    FrameCulling& fc = slot.culling;
    const FrameRequest& settings = f.settings;
    fc.path = CullPath::None;
    fc.check = false;
    fc.count = 0;
    slot.prepass = scene::CullStats{};
    slot.prepass.pass = "depth_prepass";
    slot.history_pushed = false;
    if (!f.scene || !culling_) return;
    if (slot.posed) use_posed_bounds(f);
    if (culling_->identity.valid())
        slot.push_base.instance_ids = resources_.get(culling_->identity).address;
    const std::uint32_t n = static_cast<std::uint32_t>(culling_->boxes.size());
    fc.count = 1 + f.cascades;
    if (fc.views.size() < fc.count) fc.views.resize(fc.count);
    glm::mat4 camera_vp = slot.camera.proj * slot.camera.view;
    if (settings.freeze_cull) {
        const CameraView frozen =
            resolve_camera(*settings.freeze_cull, f.lighting.cameras, f.aspect());
        camera_vp = frozen.proj * frozen.view;
    }
    for (std::uint32_t v = 0; v < fc.count; ++v) {
        PassCull& view = fc.views[v];
        const bool camera = v == 0;
        view.cpu_tested = false;
        view.gpu = nullptr;
        view.stats = scene::CullStats{};
        view.stats.pass = camera ? "camera" : "cascade" + std::to_string(v - 1);
        view.stats.method = settings.cull_method;
        view.stats.simd = std::min(core::SimdLevel::Avx512, core::best_simd_level());
        view.stats.total = camera ? n : culling_->casters;
        view.stats.hidden = camera ? culling_->hidden_count : culling_->hidden_casters;
        view.stats.view_projection = camera ? camera_vp : slot.cascades.cull_view_proj[v - 1];
        view.frustum = scene::frustum_from_view_projection(view.stats.view_projection);
        view.ids_offset = VkDeviceSize{v} * n * sizeof(std::uint32_t);
    }
    if (settings.cull == CullPath::None || n == 0) {
        for (std::uint32_t v = 0; v < fc.count; ++v)
            fc.views[v].stats.visible = fc.views[v].stats.total - fc.views[v].stats.hidden;
        return;
    }
    const bool gpu = settings.cull == CullPath::Gpu;
    fc.path = gpu ? CullPath::Gpu : CullPath::Cpu;
    fc.check = settings.cull_check;
    // The cull-boxes overlay colours the camera's CPU result.
    const bool camera_cpu = !gpu || settings.cull_check || (settings.overlays & kOverlayCullBoxes);
    prepare_buffers(f, n);
    auto* ids = static_cast<std::uint32_t*>(resources_.get(slot.cull_ids).mapped);
    const GpuCuller* any = gpu ? culling_->gpu.front().get() : nullptr;
    const VkDeviceSize draw_bytes =
        any ? VkDeviceSize{any->batch_count()} * sizeof(VkDrawIndexedIndirectCommand) : 0;
    const VkDeviceSize flag_bytes = any && fc.check ? VkDeviceSize{any->object_count()} * 4 : 0;
    const std::uint32_t block = f.slot_index % Renderer::kFramesInFlight;
    const VkDeviceAddress posed_objects = gpu && slot.posed ? write_posed_objects(f) : 0;

    const auto& groups = f.scene->groups();
    for (std::uint32_t v = 0; v < fc.count; ++v) {
        PassCull& view = fc.views[v];
        scene::CullStats& st = view.stats;
        const bool camera = v == 0;
        const auto t0 = std::chrono::steady_clock::now();
        st.tested = st.total - st.hidden;
        if (!gpu || fc.check || (camera && camera_cpu))
            test_cpu(f, view, !camera, false);
        else if (camera)
            test_cpu(f, view, false, true);
        if (fc.check && view.cpu_tested) {
            std::vector<std::uint8_t> exact(view.visible.size());
            scene::cull_boxes(view.frustum, culling_->boxes, scene::CullMethod::Exact,
                              core::SimdLevel::Avx512, exact);
            std::int64_t fp = 0;
            for (std::size_t i = 0; i < exact.size(); ++i)
                if ((camera || !culling_->blended[i]) && !culling_->is_hidden(i))
                    fp += view.visible[i] && !exact[i];
            st.false_positives = fp;
        }
        // Compacted ids of the CPU-culled groups (every group on the CPU path, the
        // blended ones on the GPU path).
        std::uint32_t* region = ids + view.ids_offset / sizeof(std::uint32_t);
        if (!view.group_visible.empty())
            for (std::size_t g = 0; g < groups.size(); ++g) {
                if (gpu && culling_->group_batch[g] != ~0u) continue;
                std::uint32_t* out = region + groups[g].first_instance;
                for (std::uint32_t k = 0; k < groups[g].instance_count; ++k)
                    if (view.visible[groups[g].first_instance + k])
                        *out++ = groups[g].first_instance + k;
            }
        if (gpu) {
            GpuCuller& culler = *culling_->gpu[v];
            view.gpu = &culler;
            st.gpu = true;
            if (slot.cull_timestamps)
                vkCmdWriteTimestamp2(f.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                     slot.cull_timestamps.get(), 2 * v);
            culler.record(f.cmd, view.frustum, settings.cull_method, block, false, posed_objects);
            if (slot.cull_timestamps)
                vkCmdWriteTimestamp2(f.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                     slot.cull_timestamps.get(), 2 * v + 1);
            view.readback = (draw_bytes + flag_bytes) * v;
            const VkBuffer rb = resources_.get(slot.cull_readback).buffer.get();
            const VkBufferCopy draws{0, view.readback, draw_bytes};
            if (draw_bytes) vkCmdCopyBuffer(f.cmd, culler.draws(), rb, 1, &draws);
            const VkBufferCopy flags{0, view.readback + draw_bytes, flag_bytes};
            if (flag_bytes) vkCmdCopyBuffer(f.cmd, culler.visible_flags(), rb, 1, &flags);
        }
        st.cpu_ms = ms_since(t0);
    }
    if (gpu)
        gpu::memory_barrier(f.cmd, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

} // namespace sherpa::render
