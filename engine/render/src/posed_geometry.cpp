#include "posed_geometry.h"

#include "pose_vertices_comp.h"

#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/gpu/vk_helpers.h>

#include <array>

namespace sherpa::render {

namespace {

constexpr VkDeviceSize kZeroRecord = 64; // a GPUMotionMesh with no streams, at offset 0

// The shaders' HAS_* bit of a stream in mesh_flags.
bool has(std::uint32_t flags, scene::VertexAttribute a) {
    return (flags & (1u << static_cast<std::uint32_t>(a))) != 0;
}

} // namespace

PosedGeometry::PosedGeometry(gpu::ResourceManager& resources, const gpu::RayTracingFunctions& fn,
                             const GpuScene& gpu, std::span<const BlasPlan> plans,
                             std::vector<PosedBlasPlan> posed, bool refit)
    : resources_(resources), fn_(fn), gpu_(gpu), plans_(std::move(posed)), refit_(refit) {
    stats_.refit = refit;
    // The posed streams, each 16-byte aligned, after the zero motion record.
    VkDeviceSize bytes = kZeroRecord;
    auto take = [&](VkDeviceSize size) {
        const VkDeviceSize at = align_up(bytes, 16);
        bytes = at + size;
        return at;
    };
    for (const PosedBlasPlan& p : plans_) {
        auto& out = geometries_.emplace_back();
        stats_.world_space += p.world_space ? 1 : 0;
        for (const PosedGeometryPlan& g : p.geometries) {
            const GpuMesh& mesh = gpu.meshes()[g.mesh];
            Geometry geo;
            geo.mesh = g.mesh;
            geo.gpu_instance = g.gpu_instance;
            geo.vertices = mesh.vertex_count;
            geo.flags = mesh.flags;
            geo.motion = mesh.motion;
            if (g.posed) {
                const VkDeviceSize n = mesh.vertex_count;
                geo.positions = take(n * stream_stride(scene::VertexAttribute::Position));
                if (has(mesh.flags, scene::VertexAttribute::Normal))
                    geo.normals = take(n * stream_stride(scene::VertexAttribute::Normal));
                if (has(mesh.flags, scene::VertexAttribute::Tangent))
                    geo.tangents = take(n * stream_stride(scene::VertexAttribute::Tangent));
                stats_.vertices += n;
            }
            out.push_back(geo);
            ++stats_.geometries;
        }
    }
    streams_ = resources_.create_buffer(
        {bytes,
         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
             VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
             VK_BUFFER_USAGE_TRANSFER_DST_BIT,
         gpu::MemoryUsage::DeviceLocal, "posed vertices"});
    stats_.stream_bytes = bytes;
    const VkDeviceAddress base = resources_.get(streams_).address;
    {
        const std::array<std::uint8_t, kZeroRecord> zero{};
        gpu::UploadBatch batch(resources_);
        batch.upload_buffer(streams_, 0, zero.data(), zero.size());
        batch.submit_and_wait();
    }
    for (auto& geos : geometries_)
        for (Geometry& g : geos) {
            if (!g.motion) g.motion = base; // the zero record: no morph, no skin
            for (VkDeviceAddress* a : {&g.positions, &g.normals, &g.tangents})
                if (*a) *a += base;
        }

    // The BLAS: sizes now, builds on the first pose.
    const gpu::Context& context = resources_.context();
    const VkBuildAccelerationStructureFlagsKHR flags =
        refit ? VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                    VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR
              : VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_BUILD_BIT_KHR;
    const std::uint64_t alignment = context.info().as_scratch_alignment;
    std::uint64_t scratch = 0;
    std::vector<std::uint64_t> offsets;
    for (std::size_t i = 0; i < plans_.size(); ++i) {
        const BlasPlan& plan = plans[plans_[i].plan];
        std::vector<VkDeviceAddress> positions;
        for (std::size_t k = 0; k < plan.geometries.size(); ++k) {
            const Geometry& g = geometries_[i][k];
            positions.push_back(
                g.positions
                    ? g.positions
                    : gpu.meshes()[g.mesh].stream[std::size_t(scene::VertexAttribute::Position)]);
        }
        BlasInput& in = inputs_.emplace_back(describe_blas(plan, gpu, flags, positions));
        fn_.get_build_sizes(context.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                            &in.info, in.max_primitives.data(), &in.sizes);
        blas_.emplace_back(resources_, fn_, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                           in.sizes.accelerationStructureSize, "posed BLAS " + plan.name);
        offsets.push_back(scratch);
        scratch +=
            align_up(std::max(in.sizes.buildScratchSize, in.sizes.updateScratchSize), alignment);
        stats_.blas_bytes += in.sizes.accelerationStructureSize;
        stats_.triangles += plan.triangles;
    }
    stats_.blas = blas_.size();
    // Kept: every pose change builds or refits, and must not allocate on the frame path.
    scratch_buffer_ = std::make_unique<ScratchBuffer>(resources_, scratch);
    stats_.scratch_bytes = scratch;
    for (std::uint64_t o : offsets) scratch_.push_back(scratch_buffer_->address() + o);

    // The posing pipeline: motion.glsl with MOTION on.
    const VkDevice device = context.device();
    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(GPUPoseVerticesPush)};
    layout_ = gpu::create_pipeline_layout(device, {}, {&range, 1}, "vkCreatePipelineLayout(pose)");
    const gpu::UniqueShaderModule module = gpu::create_shader_module(
        device, spirv_pose_vertices_comp, "vkCreateShaderModule(pose vertices)");
    const VkBool32 on = VK_TRUE;
    const VkSpecializationMapEntry entry{1, 0, sizeof(VkBool32)}; // MOTION
    const VkSpecializationInfo constants{1, &entry, sizeof(on), &on};
    pipeline_ = gpu::create_compute_pipeline(device, layout_.get(), module.get(),
                                             "vkCreateComputePipelines(pose vertices)", &constants);
}

PosedGeometry::~PosedGeometry() {
    resources_.destroy(streams_);
}

void PosedGeometry::append_records(std::vector<GPUGeometryInfo>& records,
                                   std::span<const std::uint32_t> first_static) {
    for (std::size_t i = 0; i < plans_.size(); ++i) {
        first_record_.push_back(static_cast<std::uint32_t>(records.size()));
        for (std::size_t k = 0; k < geometries_[i].size(); ++k) {
            const Geometry& g = geometries_[i][k];
            GPUGeometryInfo r = records[first_static[plans_[i].plan] + k];
            if (g.positions) r.stream[std::size_t(scene::VertexAttribute::Position)] = g.positions;
            if (g.normals) r.stream[std::size_t(scene::VertexAttribute::Normal)] = g.normals;
            if (g.tangents) r.stream[std::size_t(scene::VertexAttribute::Tangent)] = g.tangents;
            records.push_back(r);
        }
    }
}

void PosedGeometry::record(VkCommandBuffer cmd, const PoseFrame& frame, const BuildTimer& timer) {
    timer.begin(cmd, 0);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    for (std::size_t i = 0; i < geometries_.size(); ++i)
        for (const Geometry& g : geometries_[i]) {
            if (!g.positions) continue;
            const GpuMesh& mesh = gpu_.meshes()[g.mesh];
            GPUPoseVerticesPush push{};
            push.instance =
                frame.instances + VkDeviceAddress(g.gpu_instance) * sizeof(GPUInstanceData);
            push.positions = mesh.stream[std::size_t(scene::VertexAttribute::Position)];
            push.normals = mesh.stream[std::size_t(scene::VertexAttribute::Normal)];
            push.tangents = mesh.stream[std::size_t(scene::VertexAttribute::Tangent)];
            push.motion = g.motion;
            push.pose = frame.pose;
            push.out_positions = g.positions;
            push.out_normals = g.normals;
            push.out_tangents = g.tangents;
            push.mesh_flags = g.flags;
            push.highlight_base = frame.highlight_base;
            push.vertex_count = g.vertices;
            push.object_space = plans_[i].world_space ? 0u : 1u;
            vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push),
                               &push);
            vkCmdDispatch(cmd, (g.vertices + 63) / 64, 1, 1);
        }
    // Posed vertices feed the builds and, later, the hit shaders.
    gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR |
                            VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR,
                        VK_ACCESS_2_SHADER_READ_BIT);
    timer.end(cmd, 0);
    timer.begin(cmd, 1);
    const bool update = built_ && refit_;
    for (std::size_t i = 0; i < blas_.size(); ++i) {
        BlasInput& in = inputs_[i];
        in.info.pGeometries = in.geometries.data();
        in.info.mode = update ? VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR
                              : VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
        in.info.srcAccelerationStructure = update ? blas_[i].get() : VK_NULL_HANDLE;
        in.info.dstAccelerationStructure = blas_[i].get();
        in.info.scratchData.deviceAddress = scratch_[i];
        const VkAccelerationStructureBuildRangeInfoKHR* ranges = in.ranges.data();
        fn_.cmd_build(cmd, 1, &in.info, &ranges);
    }
    build_barrier(cmd);
    timer.end(cmd, 1);
    (update ? stats_.refits : stats_.builds) += blas_.size();
    built_ = true;
    ++stats_.updates;
}

void PosedGeometry::finish(const BuildTimer& timer) {
    const std::vector<double> ms = timer.read();
    stats_.pose_ms = ms[0];
    stats_.blas_ms = ms[1];
}

} // namespace sherpa::render
