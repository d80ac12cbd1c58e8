// One BLAS per glTF mesh: the geometry records, the builds batched under the
// scratch budget (one submission per batch, each build timed), then compaction.
#include "as_build.h"
#include "posed_geometry.h"
#include "rt_plan.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/gpu/vk_helpers.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_structs.h>

#include <algorithm>

namespace sherpa::render {

BlasInput describe_blas(const BlasPlan& plan, const GpuScene& gpu,
                        VkBuildAccelerationStructureFlagsKHR flags,
                        std::span<const VkDeviceAddress> positions) {
    BlasInput in;
    for (std::size_t k = 0; k < plan.geometries.size(); ++k) {
        const BlasGeometryPlan& g = plan.geometries[k];
        const GpuMesh& mesh = gpu.meshes()[g.mesh];
        auto geometry = gpu::vk_init<VkAccelerationStructureGeometryKHR>(
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR);
        geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
        // Opaque materials skip any-hit; masked and blended ones reach it (alpha test)
        // exactly once per triangle.
        geometry.flags = g.opaque ? VK_GEOMETRY_OPAQUE_BIT_KHR
                                  : VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR;
        auto& t = geometry.geometry.triangles;
        t = gpu::vk_init<VkAccelerationStructureGeometryTrianglesDataKHR>(
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR);
        t.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
        t.vertexData.deviceAddress =
            k < positions.size() ? positions[k]
                                 : mesh.stream[std::size_t(scene::VertexAttribute::Position)];
        t.vertexStride = stream_stride(scene::VertexAttribute::Position);
        t.maxVertex = mesh.vertex_count - 1;
        t.indexType = VK_INDEX_TYPE_UINT32;
        t.indexData.deviceAddress =
            gpu.index_address() + VkDeviceAddress(mesh.first_index) * sizeof(std::uint32_t);
        in.geometries.push_back(geometry);
        in.ranges.push_back({g.triangles, 0, 0, 0});
        in.max_primitives.push_back(g.triangles);
    }
    in.info = gpu::vk_init<VkAccelerationStructureBuildGeometryInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR);
    in.info.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
    in.info.flags = flags;
    in.info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    in.info.geometryCount = static_cast<std::uint32_t>(in.geometries.size());
    in.info.pGeometries = in.geometries.data();
    in.sizes = gpu::vk_init<VkAccelerationStructureBuildSizesInfoKHR>(
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR);
    return in;
}

void SceneAccelerationStructures::build_blas(const scene::Scene& scene, const GpuScene& gpu,
                                             const AccelerationSettings& settings) {
    const std::vector<BlasPlan> plans = plan_blas(scene, gpu.meshes());
    for (const scene::MaterialInstance& m : scene.materials)
        material_culls_.push_back(culls_back_faces(m));
    const gpu::Context& context = resources_.context();
    const VkDevice device = context.device();

    // The geometry records, one array for the scene, and the statistics per BLAS.
    std::vector<GPUGeometryInfo> records;
    for (const BlasPlan& plan : plans) {
        if (plan.group >= blas_of_mesh_.size()) blas_of_mesh_.resize(plan.group + 1, -1);
        blas_of_mesh_[plan.group] = static_cast<std::int32_t>(stats_.blas.size());
        BlasStats s;
        s.mesh = plan.group;
        s.name = plan.name;
        s.geometries = static_cast<std::uint32_t>(plan.geometries.size());
        s.triangles = plan.triangles;
        s.first_geometry = static_cast<std::uint32_t>(records.size());
        s.culls_back_faces = plan.cull_back_faces;
        for (const BlasGeometryPlan& g : plan.geometries) {
            const GpuMesh& mesh = gpu.meshes()[g.mesh];
            GPUGeometryInfo r{};
            for (std::size_t a = 0; a < scene::kVertexAttributeCount; ++a)
                r.stream[a] = mesh.stream[a];
            r.indices =
                gpu.index_address() + VkDeviceAddress(mesh.first_index) * sizeof(std::uint32_t);
            r.material = mesh.material;
            r.flags = mesh.flags;
            records.push_back(r);
            record_mesh_.push_back(g.mesh);
            record_material_.push_back(mesh.material);
            record_opaque_.push_back(g.opaque);
            s.opaque_geometries += g.opaque ? 1 : 0;
        }
        stats_.blas.push_back(std::move(s));
    }
    if (records.empty()) return;
    // Instances that skin or morph: posed copies, their BLAS and records (after the
    // static ones).
    std::vector<PosedBlasPlan> posed =
        plan_posed_blas(scene, gpu.meshes(), gpu.scene_instances(), plans);
    // A glTF mesh whose every instance is posed needs no static BLAS (its records stay:
    // the posed ones are copies of them).
    std::vector<std::int64_t> static_pairs(plans.size(), 0);
    for (const TlasCandidate& c : tlas_candidates(scene, blas_of_mesh_)) ++static_pairs[c.blas];
    for (const PosedBlasPlan& p : posed) --static_pairs[p.plan];
    if (!posed.empty()) {
        posed_ = std::make_unique<PosedGeometry>(resources_, fn_, gpu, plans, std::move(posed),
                                                 settings.refit_posed);
        std::vector<std::uint32_t> first_static;
        for (const BlasStats& s : stats_.blas) first_static.push_back(s.first_geometry);
        posed_->append_records(records, first_static);
        // The posed copies keep their static record's mesh, material and opacity.
        for (std::uint32_t j = 0; j < posed_->size(); ++j) {
            const std::uint32_t from = first_static[posed_->plan(j).plan];
            const std::uint32_t count = stats_.blas[posed_->plan(j).plan].geometries;
            for (std::uint32_t k = 0; k < count; ++k) {
                record_mesh_.push_back(record_mesh_[from + k]);
                record_material_.push_back(record_material_[from + k]);
                record_opaque_.push_back(record_opaque_[from + k]);
            }
        }
        if (record_mesh_.size() != records.size())
            throw gpu::GpuError("ray tracing: posed geometry records do not copy their BLAS's");
        stats_.posed = posed_->stats();
    }
    const VkDeviceSize record_bytes = records.size() * sizeof(GPUGeometryInfo);
    records_ = resources_.create_buffer({record_bytes,
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                             VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                             VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                         gpu::MemoryUsage::DeviceLocal, "geometry records"});
    {
        gpu::UploadBatch batch(resources_);
        batch.upload_buffer(records_, 0, records.data(), record_bytes);
        batch.submit_and_wait();
    }
    stats_.geometry_records = records.size();
    stats_.geometry_record_bytes = record_bytes;

    // Sizes, then batches whose scratch fits the budget.
    std::vector<BlasInput> inputs;
    std::vector<std::uint64_t> scratch;
    for (const BlasPlan& plan : plans) {
        inputs.push_back(describe_blas(
            plan, gpu,
            VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                (settings.compact ? VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR : 0)));
        BlasInput& in = inputs.back();
        fn_.get_build_sizes(device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &in.info,
                            in.max_primitives.data(), &in.sizes);
        scratch.push_back(in.sizes.buildScratchSize);
    }
    std::vector<std::uint32_t> order; // the plans built
    std::vector<std::uint64_t> built_scratch;
    for (std::uint32_t i = 0; i < plans.size(); ++i) {
        stats_.blas[i].built = static_pairs[i] > 0;
        if (!stats_.blas[i].built) continue;
        order.push_back(i);
        built_scratch.push_back(scratch[i]);
    }
    const std::uint64_t alignment = context.info().as_scratch_alignment;
    auto batches = batch_by_scratch(built_scratch, settings.scratch_budget, alignment);
    for (auto& batch : batches)
        for (std::uint32_t& k : batch) k = order[k];
    stats_.batches = static_cast<std::uint32_t>(batches.size());
    stats_.scratch_budget = settings.scratch_budget;
    for (const auto& batch : batches) {
        std::uint64_t sum = 0;
        for (std::uint32_t i : batch) sum += align_up(scratch[i], alignment);
        stats_.scratch_buffer_bytes = std::max(stats_.scratch_buffer_bytes, sum);
    }
    blas_.resize(plans.size());  // empty where not built
    if (batches.empty()) return; // every mesh is instanced posed only (posed_geometry.cpp)
    ScratchBuffer scratch_buffer(resources_, stats_.scratch_buffer_bytes);

    gpu::CommandRecorder rec(resources_.context());
    for (std::uint32_t b = 0; b < batches.size(); ++b) {
        const auto& batch = batches[b];
        const auto n = static_cast<std::uint32_t>(batch.size());
        BuildTimer timer(context, n);
        gpu::UniqueQueryPool compacted;
        if (settings.compact) {
            compacted = gpu::create_query_pool(
                device, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, n);
            vkResetQueryPool(device, compacted.get(), 0, n);
        }
        VkCommandBuffer cmd = rec.begin();
        // The vertex and index uploads are earlier transfers.
        gpu::memory_barrier(
            cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, VK_ACCESS_2_SHADER_READ_BIT);
        std::vector<VkAccelerationStructureKHR> built;
        VkDeviceAddress offset = 0;
        for (std::uint32_t k = 0; k < n; ++k) {
            const std::uint32_t i = batch[k];
            BlasInput& in = inputs[i];
            blas_[i] = gpu::AccelerationStructure(
                resources_, fn_, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                in.sizes.accelerationStructureSize, "BLAS " + stats_.blas[i].name);
            in.info.dstAccelerationStructure = blas_[i].get();
            in.info.scratchData.deviceAddress = scratch_buffer.address() + offset;
            offset += align_up(scratch[i], alignment);
            const VkAccelerationStructureBuildRangeInfoKHR* ranges = in.ranges.data();
            timer.begin(cmd, k);
            fn_.cmd_build(cmd, 1, &in.info, &ranges);
            build_barrier(cmd); // serialises the builds: each is timed alone
            timer.end(cmd, k);
            built.push_back(blas_[i].get());
        }
        if (settings.compact)
            fn_.cmd_write_properties(cmd, n, built.data(),
                                     VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR,
                                     compacted.get(), 0);
        resources_.timeline().wait_for(rec.submit(resources_));

        const std::vector<double> ms = timer.read();
        std::vector<VkDeviceSize> compact_sizes(n, 0);
        if (settings.compact)
            gpu::vk_check(vkGetQueryPoolResults(device, compacted.get(), 0, n,
                                                n * sizeof(VkDeviceSize), compact_sizes.data(),
                                                sizeof(VkDeviceSize),
                                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                          "vkGetQueryPoolResults(compacted sizes)");
        for (std::uint32_t k = 0; k < n; ++k) {
            BlasStats& s = stats_.blas[batch[k]];
            s.batch = b;
            s.build_ms = ms[k];
            s.build_bytes = inputs[batch[k]].sizes.accelerationStructureSize;
            s.scratch_bytes = scratch[batch[k]];
            s.compacted_bytes = s.build_bytes;
        }
        if (!settings.compact) continue;

        // Compaction: a smaller structure per BLAS and a copy; the originals go
        // once the copies completed.
        std::vector<gpu::AccelerationStructure> originals;
        cmd = rec.begin();
        for (std::uint32_t k = 0; k < n; ++k) {
            const std::uint32_t i = batch[k];
            if (compact_sizes[k] == 0 || compact_sizes[k] >= stats_.blas[i].build_bytes) continue;
            gpu::AccelerationStructure small(resources_, fn_,
                                             VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                                             compact_sizes[k], "BLAS " + stats_.blas[i].name);
            auto copy = gpu::vk_init<VkCopyAccelerationStructureInfoKHR>(
                VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR);
            copy.src = blas_[i].get();
            copy.dst = small.get();
            copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
            fn_.cmd_copy(cmd, &copy);
            originals.push_back(std::exchange(blas_[i], std::move(small)));
            stats_.blas[i].compacted_bytes = compact_sizes[k];
        }
        build_barrier(cmd);
        resources_.timeline().wait_for(rec.submit(resources_));
    }
}

} // namespace sherpa::render
