// The ray tracer after a material switch (KHR_materials_variants): the geometry
// records' material words follow the meshes' materials; where a BLAS built to cull back
// faces now holds a material that must not, its instances stop culling, and where a
// geometry's opaque flag (fixed when its BLAS was built) no longer holds, they force
// any-hit.
#include "posed_geometry.h"

#include <algorithm>

#include <sherpa/gpu/upload.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/gpu_structs.h>

namespace sherpa::render {

SceneAccelerationStructures::MaterialFollow
SceneAccelerationStructures::follow_materials(const GpuScene& gpu) {
    MaterialFollow out;
    if (!records_.valid()) return out;
    const std::size_t blas_count = blas_.size() + (posed_ ? posed_->size() : 0);
    std::vector<bool> force(blas_count, false), no_cull(blas_count, false);
    // The BLAS (static, then posed) whose records are [first, first + count).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
    for (std::uint32_t b = 0; b < blas_count; ++b)
        ranges.emplace_back(first_geometry(b), stats_.blas[plan_of(b)].geometries);
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
        const std::uint32_t end = std::min<std::uint32_t>(first + count, record_mesh_.size());
        bool cull = stats_.blas[plan_of(b)].culls_back_faces;
        for (std::uint32_t r = first; r < end; ++r)
            if (record_material_[r] >= material_culls_.size() ||
                !material_culls_[record_material_[r]])
                cull = false;
        no_cull[b] = stats_.blas[plan_of(b)].culls_back_faces && !cull;
        for (std::uint32_t r = first; r < end; ++r) {
            // Built opaque, any-hit never runs: right only for opaque materials whose
            // back faces are drawn (double-sided) or culled by the traversal
            // (rt_plan.cpp's rule).
            const auto [alpha, double_sided] = mode[record_mesh_[r]];
            if (record_opaque_[r] && (alpha != scene::AlphaMode::Opaque || !(double_sided || cull)))
                force[b] = true;
        }
        out.forced_blas += force[b] ? 1 : 0;
        out.unculled_blas += no_cull[b] ? 1 : 0;
    }
    if (out.records) batch.submit_and_wait();
    const bool was_default = force_no_opaque_.empty() && cull_disabled_.empty();
    const bool is_default = out.forced_blas == 0 && out.unculled_blas == 0;
    if ((force != force_no_opaque_ || no_cull != cull_disabled_) && !(was_default && is_default)) {
        force_no_opaque_ = std::move(force);
        cull_disabled_ = std::move(no_cull);
        tlas_blas_.clear(); // instance flags changed: a rebuild, not a refit
        build_tlas({});
        out.tlas_rebuilt = true;
    }
    return out;
}

} // namespace sherpa::render
