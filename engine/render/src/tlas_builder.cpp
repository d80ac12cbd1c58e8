// The TLAS: one instance per (node, glTF mesh) as plan_tlas decides, built on load
// and rebuilt or refitted when transforms, the pose or visibility change.
#include "as_build.h"
#include "posed_geometry.h"
#include "rt_plan.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/acceleration_structures.h>

#include <cstring>
#include <map>

namespace sherpa::render {

namespace {

// glm is column-major; VkTransformMatrixKHR is 3 rows of 4.
VkTransformMatrixKHR to_vk(const glm::mat4& m) {
    VkTransformMatrixKHR t{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) t.matrix[r][c] = m[c][r];
    return t;
}

} // namespace

void SceneAccelerationStructures::update_instances(const scene::Scene& scene,
                                                   const std::vector<bool>& hidden_nodes) {
    candidates_ = tlas_candidates(scene, blas_of_mesh_);
    if (posed_) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> posed; // (node, group)
        for (std::uint32_t i = 0; i < posed_->size(); ++i)
            posed.emplace(std::pair{posed_->plan(i).node, posed_->plan(i).group}, i);
        for (TlasCandidate& c : candidates_) {
            const auto it = posed.find({c.node, c.group});
            if (it == posed.end()) continue;
            c.blas = static_cast<std::int32_t>(blas_.size() + it->second);
            c.world_space = posed_->plan(it->second).world_space;
        }
    }
    hidden_ = hidden_nodes;
    build_tlas({});
}

void SceneAccelerationStructures::set_hidden_nodes(const std::vector<bool>& hidden_nodes) {
    hidden_ = hidden_nodes;
    build_tlas({});
}

VkDeviceAddress SceneAccelerationStructures::blas_address(std::uint32_t blas) const {
    return blas < blas_.size() ? blas_[blas].address() : posed_->blas_address(blas - blas_.size());
}

std::uint32_t SceneAccelerationStructures::first_geometry(std::uint32_t blas) const {
    return blas < blas_.size() ? stats_.blas[blas].first_geometry
                               : posed_->first_geometry(blas - blas_.size());
}

std::uint32_t SceneAccelerationStructures::plan_of(std::uint32_t blas) const {
    return blas < blas_.size() ? blas : posed_->plan(blas - blas_.size()).plan;
}

bool SceneAccelerationStructures::instances_cull(std::uint32_t blas) const {
    return stats_.blas[plan_of(blas)].culls_back_faces &&
           !(blas < cull_disabled_.size() && cull_disabled_[blas]);
}

void SceneAccelerationStructures::build_tlas(std::span<const glm::mat4> node_world) {
    // Posed instances join once their BLAS were built (the first update_pose()).
    std::vector<TlasCandidate> unposed;
    const bool pending = posed_ && posed_->stats().updates == 0;
    if (pending) {
        unposed = candidates_;
        for (TlasCandidate& c : unposed)
            if (c.blas >= static_cast<std::int32_t>(blas_.size())) c.blas = -1;
    }
    TlasPlan plan = plan_tlas(pending ? unposed : candidates_, hidden_, node_world);
    stats_.warnings = std::move(plan.warnings); // the TLAS's are the only warnings
    std::vector<std::uint32_t> order;
    for (const TlasInstancePlan& p : plan.instances) order.push_back(p.blas);
    // A refit keeps the structure's instances and only moves them: same count, same
    // BLAS in the same order. Anything else (a node hidden or shown) is a rebuild.
    const bool refit = tlas_ && order == tlas_blas_;
    const TlasStats previous = stats_.tlas;
    stats_.tlas = plan.counts;
    stats_.tlas.builds = previous.builds;
    stats_.tlas.refits = previous.refits;
    if (plan.instances.empty()) {
        tlas_ = gpu::AccelerationStructure();
        resources_.destroy(instances_);
        tlas_blas_.clear();
        return;
    }

    const std::uint32_t count = static_cast<std::uint32_t>(plan.instances.size());
    const VkDeviceSize bytes = VkDeviceSize(count) * sizeof(VkAccelerationStructureInstanceKHR);
    if (!instances_.valid() || resources_.get(instances_).size < bytes) {
        resources_.destroy(instances_);
        instances_ = resources_.create_buffer(
            {bytes,
             VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                 VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
             gpu::MemoryUsage::Upload, "TLAS instances"});
    }
    auto* out = static_cast<VkAccelerationStructureInstanceKHR*>(resources_.get(instances_).mapped);
    for (std::uint32_t i = 0; i < count; ++i) {
        const TlasInstancePlan& p = plan.instances[i];
        VkAccelerationStructureInstanceKHR inst{};
        inst.transform = to_vk(p.world);
        // 24 bits: more geometry records than that cannot be addressed.
        const std::uint32_t first = first_geometry(p.blas);
        if (first >= (1u << 24))
            throw gpu::GpuError("ray tracing: geometry record " + std::to_string(first) +
                                " is past the 24-bit instance custom index");
        inst.instanceCustomIndex = first;
        inst.mask = 0xff;
        inst.instanceShaderBindingTableRecordOffset = 0;
        // Facing is the object-space winding (a mirroring instance does not flip it), as
        // the hit shaders decide it. Where a mesh mixes sidedness, culling is per
        // material in any-hit (rt.rahit, pt.rahit) and the traversal culls nothing;
        // where all its materials are single-sided the traversal culls back faces for
        // the rays that ask (rt.rgen, pt.rgen). Vulkan's default facing (no
        // TRIANGLE_FLIP_FACING) is the hit shaders' front (h.front in rt_hit.glsl).
        inst.flags =
            instances_cull(p.blas) ? 0 : VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
        // A material switch made a geometry built opaque need any-hit (follow_materials()).
        if (p.blas < force_no_opaque_.size() && force_no_opaque_[p.blas])
            inst.flags |= VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR;
        inst.accelerationStructureReference = blas_address(p.blas);
        std::memcpy(out + i, &inst, sizeof(inst));
    }
    stats_.tlas.instance_buffer_bytes = resources_.get(instances_).size;

    auto geometry = gpu::vk_init<VkAccelerationStructureGeometryKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    geometry.geometry.instances = gpu::vk_init<VkAccelerationStructureGeometryInstancesDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR);
    geometry.geometry.instances.data.deviceAddress = resources_.get(instances_).address;
    auto info = gpu::vk_init<VkAccelerationStructureBuildGeometryInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
    info.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
    info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                 VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR;
    info.mode = refit ? VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR
                      : VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    info.geometryCount = 1;
    info.pGeometries = &geometry;
    auto sizes = gpu::vk_init<VkAccelerationStructureBuildSizesInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
    const VkDevice device = resources_.context().device();
    fn_.get_build_sizes(device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, &count,
                        &sizes);
    if (!refit) {
        // The previous TLAS (if any) is unused: every build and update waits for itself.
        tlas_ = gpu::AccelerationStructure(resources_, fn_,
                                           VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                           sizes.accelerationStructureSize, "TLAS");
        tlas_blas_ = order;
    } else {
        info.srcAccelerationStructure = tlas_.get();
    }
    const VkDeviceSize scratch_bytes = refit ? sizes.updateScratchSize : sizes.buildScratchSize;
    ScratchBuffer scratch(resources_, scratch_bytes);
    info.dstAccelerationStructure = tlas_.get();
    info.scratchData.deviceAddress = scratch.address();
    VkAccelerationStructureBuildRangeInfoKHR range{count, 0, 0, 0};
    const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;

    BuildTimer timer(resources_.context(), 1);
    gpu::CommandRecorder rec(resources_.context());
    VkCommandBuffer cmd = rec.begin();
    // The BLAS builds (and a previous TLAS build) completed in earlier submissions.
    build_barrier(cmd);
    timer.begin(cmd, 0);
    fn_.cmd_build(cmd, 1, &info, &ranges);
    build_barrier(cmd);
    timer.end(cmd, 0);
    resources_.timeline().wait_for(rec.submit(resources_));
    stats_.tlas.build_ms = timer.read()[0];
    ++(refit ? stats_.tlas.refits : stats_.tlas.builds);
    stats_.tlas.bytes = tlas_.size();
    stats_.tlas.scratch_bytes = scratch_bytes;
}

} // namespace sherpa::render
