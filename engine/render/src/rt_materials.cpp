// The ray tracer after a material switch (KHR_materials_variants): the geometry
// records' material words follow the meshes' materials, and where a geometry's opaque
// flag (fixed when its BLAS was built) no longer holds, its instances force any-hit.
#include "posed_geometry.h"

#include <sherpa/gpu/upload.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_structs.h>

namespace sherpa::render {

SceneAccelerationStructures::MaterialFollow
SceneAccelerationStructures::follow_materials(const GpuScene& gpu) {
    MaterialFollow out;
    if (!records_.valid()) return out;
    const std::size_t blas_count = blas_.size() + (posed_ ? posed_->size() : 0);
    std::vector<bool> force(blas_count, false);
    // The BLAS (static, then posed) whose records are [first, first + count).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
    for (std::uint32_t b = 0; b < blas_count; ++b) {
        const std::uint32_t plan = b < blas_.size() ? b : posed_->plan(b - blas_.size()).plan;
        ranges.emplace_back(first_geometry(b), stats_.blas[plan].geometries);
    }
    // Each mesh's alpha mode and sidedness now, from its draw groups (which a switch
    // updated); a mesh without one is in no TLAS instance.
    std::vector<std::pair<scene::AlphaMode, bool>> mode(gpu.meshes().size(),
                                                        {scene::AlphaMode::Opaque, true});
    for (const DrawGroup& g : gpu.groups()) mode[g.mesh] = {g.alpha, g.double_sided};
    gpu::UploadBatch batch(resources_);
    constexpr VkDeviceSize kWord = offsetof(GPUGeometryInfo, material);
    for (std::uint32_t r = 0; r < record_mesh_.size(); ++r) {
        const std::uint32_t material = gpu.meshes()[record_mesh_[r]].material;
        if (material != record_material_[r]) {
            record_material_[r] = material;
            batch.upload_buffer(records_, VkDeviceSize(r) * sizeof(GPUGeometryInfo) + kWord,
                                &record_material_[r], sizeof(std::uint32_t));
            out.gpu_bytes += sizeof(std::uint32_t);
            ++out.records;
        }
    }
    for (std::uint32_t b = 0; b < blas_count; ++b) {
        const auto [first, count] = ranges[b];
        for (std::uint32_t r = first; r < first + count && r < record_mesh_.size(); ++r) {
            // Built opaque, any-hit never runs: right only for opaque double-sided
            // materials (rt_plan.cpp's rule).
            const auto [alpha, double_sided] = mode[record_mesh_[r]];
            if (record_opaque_[r] && (alpha != scene::AlphaMode::Opaque || !double_sided))
                force[b] = true;
        }
        out.forced_blas += force[b] ? 1 : 0;
    }
    if (out.records) batch.submit_and_wait();
    if (force != force_no_opaque_ && !(force_no_opaque_.empty() && out.forced_blas == 0)) {
        force_no_opaque_ = std::move(force);
        tlas_blas_.clear(); // instance flags changed: a rebuild, not a refit
        build_tlas({});
        out.tlas_rebuilt = true;
    }
    return out;
}

} // namespace sherpa::render
