#pragma once
// The ray tracer's moving meshes (private to the render layer): per planned posed
// BLAS (rt_plan.h: one per (node, glTF mesh) instance that skins or morphs), posed
// copies of the vertices it moves (position, and normal and tangent where the mesh
// has them, as the hit shaders read them), written by shaders/pose_vertices.comp from
// the frame's pose with the rasterizer's own deformation (motion.glsl), and a BLAS
// over them, built on the first pose and refitted (or rebuilt) on each later one.
// Geometries that do not move and need no world-space copy keep the stored streams.
#include "as_build.h"
#include "rt_plan.h"

#include <sherpa/gpu/acceleration_structure.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_structs.h>

namespace sherpa::render {

class PosedGeometry {
public:
    PosedGeometry(gpu::ResourceManager& resources, const gpu::RayTracingFunctions& fn,
                  const GpuScene& gpu, std::span<const BlasPlan> plans,
                  std::vector<PosedBlasPlan> posed, bool refit);
    ~PosedGeometry();
    PosedGeometry(const PosedGeometry&) = delete;
    PosedGeometry& operator=(const PosedGeometry&) = delete;

    std::size_t size() const { return blas_.size(); }
    const PosedBlasPlan& plan(std::size_t i) const { return plans_[i]; }
    VkDeviceAddress blas_address(std::size_t i) const { return blas_[i].address(); }
    std::uint32_t first_geometry(std::size_t i) const { return first_record_[i]; }
    // Appends its geometry records (copies of the static ones of the same glTF mesh,
    // `records[first_static[plan] + k]`, with the posed streams put in).
    void append_records(std::vector<GPUGeometryInfo>& records,
                        std::span<const std::uint32_t> first_static);
    // Records posing and the BLAS builds (the first time) or refits into `cmd`; the
    // statistics once `timer` (2 spans) is read: see finish().
    void record(VkCommandBuffer cmd, const PoseFrame& frame, const BuildTimer& timer);
    void finish(const BuildTimer& timer);
    const PosedStats& stats() const { return stats_; }

private:
    struct Geometry {
        std::uint32_t mesh = 0, gpu_instance = 0, vertices = 0, flags = 0;
        VkDeviceAddress motion = 0; // its GPUMotionMesh, or the zero record
        VkDeviceAddress positions = 0, normals = 0, tangents = 0; // posed; 0: stored streams
    };

    gpu::ResourceManager& resources_;
    const gpu::RayTracingFunctions& fn_;
    const GpuScene& gpu_;
    std::vector<PosedBlasPlan> plans_;
    std::vector<std::vector<Geometry>> geometries_; // per posed BLAS, per geometry
    std::vector<BlasInput> inputs_;
    std::vector<gpu::AccelerationStructure> blas_;
    std::vector<std::uint32_t> first_record_;
    std::vector<VkDeviceAddress> scratch_; // per BLAS, aligned, in scratch_buffer_
    gpu::BufferHandle streams_;
    std::unique_ptr<ScratchBuffer> scratch_buffer_;
    gpu::UniquePipelineLayout layout_;
    gpu::UniquePipeline pipeline_;
    bool built_ = false, refit_ = true;
    PosedStats stats_;
};

} // namespace sherpa::render
