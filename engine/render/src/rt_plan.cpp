#include "rt_plan.h"

#include <sherpa/render/gpu_structs.h>

#include <array>
#include <cmath>
#include <cstring>
#include <set>

namespace sherpa::gpu {

std::vector<BlasPlan> plan_blas(const Scene& scene, std::span<const GpuMesh> meshes) {
    // Engine meshes by glTF mesh, in primitive order.
    std::vector<std::vector<std::uint32_t>> by_group;
    for (std::uint32_t m = 0; m < scene.meshes.size() && m < meshes.size(); ++m) {
        const std::uint32_t group = scene.meshes[m].group_id;
        if (group >= by_group.size()) by_group.resize(group + 1);
        by_group[group].push_back(m);
    }
    std::vector<BlasPlan> out;
    for (std::uint32_t group = 0; group < by_group.size(); ++group) {
        BlasPlan plan;
        plan.group = group;
        for (std::uint32_t m : by_group[group]) {
            const GpuMesh& g = meshes[m];
            if ((g.flags & kMeshTopologyBits) != 0 || g.index_count < 3) continue;
            const Mesh& mesh = scene.meshes[m];
            BlasGeometryPlan geometry;
            geometry.mesh = m;
            geometry.triangles = g.index_count / 3;
            geometry.opaque = mesh.material_id < scene.materials.size() &&
                              scene.materials[mesh.material_id].alpha_mode == AlphaMode::Opaque &&
                              scene.materials[mesh.material_id].double_sided;
            plan.triangles += geometry.triangles;
            plan.geometries.push_back(geometry);
            if (plan.name.empty()) plan.name = mesh.name.substr(0, mesh.name.rfind('#'));
        }
        if (!plan.geometries.empty()) out.push_back(std::move(plan));
    }
    return out;
}

std::vector<std::vector<std::uint32_t>> batch_by_scratch(std::span<const std::uint64_t> scratch,
                                                         std::uint64_t budget,
                                                         std::uint64_t alignment) {
    const std::uint64_t a = alignment ? alignment : 1;
    std::vector<std::vector<std::uint32_t>> batches;
    std::uint64_t used = 0;
    for (std::uint32_t i = 0; i < scratch.size(); ++i) {
        const std::uint64_t need = (scratch[i] + a - 1) / a * a;
        if (batches.empty() || used + need > budget) {
            batches.emplace_back();
            used = 0;
        }
        batches.back().push_back(i);
        used += need;
    }
    return batches;
}

namespace {

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

} // namespace

TlasPlan plan_tlas(const Scene& scene, std::span<const std::int32_t> blas_of_group,
                   const std::vector<bool>& hidden_nodes) {
    TlasPlan plan;
    std::set<std::pair<std::uint32_t, std::uint32_t>> pairs; // (node, group)
    std::set<std::array<std::uint32_t, 17>> placed;          // (blas, world bits)
    std::uint64_t quiet_warnings = 0;
    for (const MeshInstance& inst : scene.instances) {
        if (inst.mesh_id >= scene.meshes.size()) continue;
        const std::uint32_t group = scene.meshes[inst.mesh_id].group_id;
        if (group >= blas_of_group.size() || blas_of_group[group] < 0) continue;
        if (!pairs.insert({inst.node_id, group}).second) continue; // another primitive of it
        ++plan.counts.node_mesh_pairs;
        if (inst.node_id < hidden_nodes.size() && hidden_nodes[inst.node_id]) {
            ++plan.counts.hidden;
            continue;
        }
        if (!finite(inst.world)) {
            ++plan.counts.non_finite;
            if (plan.warnings.size() < 8) {
                const std::string name =
                    inst.node_id < scene.nodes.size() ? scene.nodes[inst.node_id].name : "";
                plan.warnings.push_back("node " + std::to_string(inst.node_id) + " '" + name +
                                        "': world transform is not finite; its instance of mesh " +
                                        std::to_string(group) +
                                        " is left out of the acceleration structure");
            } else {
                ++quiet_warnings;
            }
            continue;
        }
        std::array<std::uint32_t, 17> key{};
        key[0] = std::uint32_t(blas_of_group[group]);
        std::memcpy(&key[1], &inst.world, sizeof(glm::mat4));
        if (!placed.insert(key).second) {
            ++plan.counts.deduplicated;
            continue;
        }
        TlasInstancePlan p;
        p.blas = key[0];
        p.node = inst.node_id;
        p.world = inst.world;
        p.mirrored = glm::determinant(glm::mat3(inst.world)) < 0.0f;
        plan.counts.mirrored += p.mirrored ? 1 : 0;
        plan.instances.push_back(p);
    }
    if (quiet_warnings)
        plan.warnings.push_back(std::to_string(quiet_warnings) +
                                " more instances with non-finite transforms left out");
    plan.counts.instances = plan.instances.size();
    return plan;
}

} // namespace sherpa::gpu
