// The scene's acceleration structures: construction and what the BLAS and TLAS
// builds share (scratch, timing). The builds: blas_builder.cpp, tlas_builder.cpp.
#include "as_build.h"
#include "posed_geometry.h"
#include "rt_plan.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/vk_helpers.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_structs.h>

#include <chrono>

namespace sherpa::render {

ScratchBuffer::ScratchBuffer(gpu::ResourceManager& resources, std::uint64_t bytes)
    : resources_(resources), bytes_(bytes) {
    const std::uint64_t alignment = resources.context().info().as_scratch_alignment;
    buffer_ = resources.create_buffer(
        {bytes + alignment,
         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
         gpu::MemoryUsage::DeviceLocal, "acceleration-structure scratch"});
    address_ = align_up(resources.get(buffer_).address, alignment);
}

BuildTimer::BuildTimer(const gpu::Context& context, std::uint32_t count)
    : context_(context), count_(count) {
    if (!context.info().timestamps || count == 0) return;
    pool_ = gpu::create_query_pool(context.device(), VK_QUERY_TYPE_TIMESTAMP, 2 * count);
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
    gpu::vk_check(vkGetQueryPoolResults(context_.device(), pool_.get(), 0, 2 * count_,
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
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
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
    return blas_compacted_bytes() + tlas.bytes + tlas.instance_buffer_bytes +
           geometry_record_bytes + posed.stream_bytes + posed.blas_bytes + posed.scratch_bytes;
}

SceneAccelerationStructures::SceneAccelerationStructures(gpu::ResourceManager& resources,
                                                         const scene::Scene& scene,
                                                         const GpuScene& gpu,
                                                         const AccelerationSettings& settings)
    : resources_(resources), fn_(gpu::RayTracingFunctions::load(resources.context())) {
    const auto start = std::chrono::steady_clock::now();
    try {
        build_blas(scene, gpu, settings);
        update_instances(scene, settings.hidden_nodes);
    } catch (...) {
        posed_.reset();
        resources_.destroy(records_);
        resources_.destroy(instances_);
        throw;
    }
    stats_.build_wall_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

SceneAccelerationStructures::~SceneAccelerationStructures() {
    posed_.reset();
    resources_.destroy(records_);
    resources_.destroy(instances_);
}

void SceneAccelerationStructures::update_pose(const PoseFrame& frame) {
    if (posed_) {
        BuildTimer timer(resources_.context(), 2);
        gpu::CommandRecorder rec(resources_.context());
        VkCommandBuffer cmd = rec.begin();
        posed_->record(cmd, frame, timer);
        resources_.timeline().wait_for(rec.submit(resources_));
        posed_->finish(timer);
        stats_.posed = posed_->stats();
    }
    build_tlas(frame.node_world);
}

VkDeviceAddress SceneAccelerationStructures::geometry_records() const {
    return records_.valid() ? resources_.get(records_).address : 0;
}

} // namespace sherpa::render
