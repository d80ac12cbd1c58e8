// The scene's acceleration structures: construction, the TLAS build and what the
// BLAS and TLAS builds share (scratch, timing). The BLAS builds: blas_builder.cpp.
#include "as_build.h"
#include "rt_plan.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_structs.h>

#include <chrono>
#include <cstring>

namespace sherpa::gpu {

ScratchBuffer::ScratchBuffer(ResourceManager& resources, std::uint64_t bytes)
    : resources_(resources), bytes_(bytes) {
    const std::uint64_t alignment = resources.context().info().as_scratch_alignment;
    buffer_ = resources.create_buffer(
        {bytes + alignment,
         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
         MemoryUsage::DeviceLocal, "acceleration-structure scratch"});
    address_ = align_up(resources.get(buffer_).address, alignment);
}

BuildTimer::BuildTimer(const Context& context, std::uint32_t count)
    : context_(context), count_(count) {
    if (!context.info().timestamps || count == 0) return;
    pool_ = create_query_pool(context.device(), VK_QUERY_TYPE_TIMESTAMP, 2 * count);
    vkResetQueryPool(context.device(), pool_.get(), 0, 2 * count);
}

void BuildTimer::write(VkCommandBuffer cmd, std::uint32_t query) const {
    if (pool_)
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                             pool_.get(), query);
}

std::vector<double> BuildTimer::read() const {
    std::vector<double> ms(count_, -1.0);
    if (!pool_) return ms;
    std::vector<std::uint64_t> ticks(2 * count_);
    vk_check(vkGetQueryPoolResults(context_.device(), pool_.get(), 0, 2 * count_,
                                   ticks.size() * sizeof(std::uint64_t), ticks.data(),
                                   sizeof(std::uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
             "vkGetQueryPoolResults(acceleration-structure builds)");
    const double ns = context_.info().timestamp_period_ns;
    for (std::uint32_t i = 0; i < count_; ++i)
        ms[i] = double(ticks[2 * i + 1] - ticks[2 * i]) * ns * 1e-6;
    return ms;
}

void build_barrier(VkCommandBuffer cmd) {
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                   VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                   VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
                       VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_COPY_BIT_KHR,
                   VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                       VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR);
}

std::uint64_t AccelerationStats::blas_triangles() const {
    std::uint64_t n = 0;
    for (const BlasStats& b : blas) n += b.triangles;
    return n;
}

std::uint64_t AccelerationStats::blas_build_bytes() const {
    std::uint64_t n = 0;
    for (const BlasStats& b : blas) n += b.build_bytes;
    return n;
}

std::uint64_t AccelerationStats::blas_compacted_bytes() const {
    std::uint64_t n = 0;
    for (const BlasStats& b : blas) n += b.compacted_bytes;
    return n;
}

std::uint64_t AccelerationStats::total_bytes() const {
    return blas_compacted_bytes() + tlas.bytes + tlas.instance_buffer_bytes + geometry_record_bytes;
}

SceneAccelerationStructures::SceneAccelerationStructures(ResourceManager& resources,
                                                         const Scene& scene, const GpuScene& gpu,
                                                         const AccelerationSettings& settings)
    : resources_(resources), fn_(RayTracingFunctions::load(resources.context())) {
    const auto start = std::chrono::steady_clock::now();
    try {
        build_blas(scene, gpu, settings);
        build_tlas(scene, settings);
    } catch (...) {
        resources_.destroy(records_);
        resources_.destroy(instances_);
        throw;
    }
    stats_.build_wall_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

SceneAccelerationStructures::~SceneAccelerationStructures() {
    resources_.destroy(records_);
    resources_.destroy(instances_);
}

VkDeviceAddress SceneAccelerationStructures::geometry_records() const {
    return records_.valid() ? resources_.get(records_).address : 0;
}

namespace {

// glm is column-major; VkTransformMatrixKHR is 3 rows of 4.
VkTransformMatrixKHR to_vk(const glm::mat4& m) {
    VkTransformMatrixKHR t{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) t.matrix[r][c] = m[c][r];
    return t;
}

} // namespace

void SceneAccelerationStructures::build_tlas(const Scene& scene,
                                             const AccelerationSettings& settings) {
    TlasPlan plan = plan_tlas(scene, blas_of_mesh_, settings.hidden_nodes);
    stats_.tlas = plan.counts;
    for (std::string& w : plan.warnings) stats_.warnings.push_back(std::move(w));
    if (plan.instances.empty()) return;

    const std::uint32_t count = static_cast<std::uint32_t>(plan.instances.size());
    const VkDeviceSize bytes = VkDeviceSize(count) * sizeof(VkAccelerationStructureInstanceKHR);
    instances_ = resources_.create_buffer(
        {bytes,
         VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
             VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
         MemoryUsage::Upload, "TLAS instances"});
    auto* out = static_cast<VkAccelerationStructureInstanceKHR*>(resources_.get(instances_).mapped);
    for (std::uint32_t i = 0; i < count; ++i) {
        const TlasInstancePlan& p = plan.instances[i];
        VkAccelerationStructureInstanceKHR inst{};
        inst.transform = to_vk(p.world);
        // 24 bits: more geometry records than that cannot be addressed.
        const std::uint32_t first = stats_.blas[p.blas].first_geometry;
        if (first >= (1u << 24))
            throw GpuError("ray tracing: geometry record " + std::to_string(first) +
                           " is past the 24-bit instance custom index");
        inst.instanceCustomIndex = first;
        inst.mask = 0xff;
        inst.instanceShaderBindingTableRecordOffset = 0;
        // Facing is decided in the hit shaders from world-space geometry (as the
        // rasterizer's winding is per material), so the hardware culls nothing.
        inst.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
        inst.accelerationStructureReference = blas_[p.blas].address();
        std::memcpy(out + i, &inst, sizeof(inst));
    }
    stats_.tlas.instance_buffer_bytes = bytes;

    auto geometry = vk_init<VkAccelerationStructureGeometryKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
    geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    geometry.geometry.instances = vk_init<VkAccelerationStructureGeometryInstancesDataKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR);
    geometry.geometry.instances.data.deviceAddress = resources_.get(instances_).address;
    auto info = vk_init<VkAccelerationStructureBuildGeometryInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
    info.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
    info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    info.geometryCount = 1;
    info.pGeometries = &geometry;
    auto sizes = vk_init<VkAccelerationStructureBuildSizesInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
    const VkDevice device = resources_.context().device();
    fn_.get_build_sizes(device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, &count,
                        &sizes);
    tlas_ = AccelerationStructure(resources_, fn_, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                  sizes.accelerationStructureSize, "TLAS");
    ScratchBuffer scratch(resources_, sizes.buildScratchSize);
    info.dstAccelerationStructure = tlas_.get();
    info.scratchData.deviceAddress = scratch.address();
    VkAccelerationStructureBuildRangeInfoKHR range{count, 0, 0, 0};
    const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;

    BuildTimer timer(resources_.context(), 1);
    CommandRecorder rec(resources_.context());
    VkCommandBuffer cmd = rec.begin();
    // The BLAS builds completed in earlier submissions; their results are read here.
    build_barrier(cmd);
    timer.begin(cmd, 0);
    fn_.cmd_build(cmd, 1, &info, &ranges);
    build_barrier(cmd);
    timer.end(cmd, 0);
    resources_.timeline().wait_for(rec.submit(resources_));
    stats_.tlas.build_ms = timer.read()[0];
    stats_.tlas.bytes = sizes.accelerationStructureSize;
    stats_.tlas.scratch_bytes = sizes.buildScratchSize;
}

} // namespace sherpa::gpu
