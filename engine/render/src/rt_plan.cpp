#include "rt_plan.h"

#include <sherpa/render/gpu_structs.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <tuple>

namespace sherpa::render {

bool culls_back_faces(const scene::MaterialInstance& material) {
    const bool volume = material.volume.has_value() && (material.transmission.has_value() ||
                                                        material.diffuse_transmission.has_value());
    return !material.double_sided && !volume;
}

std::vector<BlasPlan> plan_blas(const scene::Scene& scene, std::span<const GpuMesh> meshes) {
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
        plan.cull_back_faces = true;
        for (std::uint32_t m : by_group[group]) {
            const GpuMesh& g = meshes[m];
            if ((g.flags & kMeshTopologyBits) != 0 || g.index_count < 3) continue;
            const scene::Mesh& mesh = scene.meshes[m];
            BlasGeometryPlan geometry;
            geometry.mesh = m;
            geometry.triangles = g.index_count / 3;
            // Opaque for now when the material is; sidedness decides below, once the
            // whole mesh is known.
            const bool has_material = mesh.material_id < scene.materials.size();
            geometry.opaque = has_material && scene.materials[mesh.material_id].alpha_mode ==
                                                  scene::AlphaMode::Opaque;
            if (!has_material || !culls_back_faces(scene.materials[mesh.material_id]))
                plan.cull_back_faces = false;
            plan.triangles += geometry.triangles;
            plan.geometries.push_back(geometry);
            if (plan.name.empty()) plan.name = mesh.name.substr(0, mesh.name.rfind('#'));
        }
        if (plan.geometries.empty()) continue;
        // Without culling, a single-sided geometry's back faces are any-hit's to reject.
        for (BlasGeometryPlan& g : plan.geometries)
            g.opaque = g.opaque && (plan.cull_back_faces ||
                                    scene.materials[scene.meshes[g.mesh].material_id].double_sided);
        out.push_back(std::move(plan));
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

std::vector<TlasCandidate> tlas_candidates(const scene::Scene& scene,
                                           std::span<const std::int32_t> blas_of_group) {
    std::vector<TlasCandidate> out;
    std::set<std::tuple<std::uint32_t, std::int32_t, std::uint32_t>> seen; // (node, row, group)
    for (const scene::MeshInstance& inst : scene.instances) {
        if (inst.mesh_id >= scene.meshes.size()) continue;
        const std::uint32_t group = scene.meshes[inst.mesh_id].group_id;
        if (group >= blas_of_group.size() || blas_of_group[group] < 0) continue;
        if (!seen.insert({inst.node_id, inst.row, group}).second) continue; // another primitive
        TlasCandidate c;
        c.node = inst.node_id;
        c.group = group;
        c.blas = blas_of_group[group];
        c.world = inst.world;
        c.row = scene::instance_transform(scene, inst);
        c.node_name = inst.node_id < scene.nodes.size() ? scene.nodes[inst.node_id].name : "";
        out.push_back(std::move(c));
    }
    return out;
}

TlasPlan plan_tlas(std::span<const TlasCandidate> candidates, const std::vector<bool>& hidden_nodes,
                   std::span<const glm::mat4> node_world) {
    TlasPlan plan;
    std::set<std::array<std::uint32_t, 17>> placed; // (blas, world bits)
    std::uint64_t quiet_warnings = 0;
    for (const TlasCandidate& c : candidates) {
        if (c.blas < 0) continue;
        ++plan.counts.node_mesh_pairs;
        if (c.node < hidden_nodes.size() && hidden_nodes[c.node]) {
            ++plan.counts.hidden;
            continue;
        }
        const glm::mat4 world = c.world_space                ? glm::mat4(1.0f)
                                : c.node < node_world.size() ? node_world[c.node] * c.row
                                                             : c.world;
        if (!finite(world)) {
            ++plan.counts.non_finite;
            if (plan.warnings.size() < 8) {
                plan.warnings.push_back("node " + std::to_string(c.node) + " '" + c.node_name +
                                        "': world transform is not finite; its instance of mesh " +
                                        std::to_string(c.group) +
                                        " is left out of the acceleration structure");
            } else {
                ++quiet_warnings;
            }
            continue;
        }
        std::array<std::uint32_t, 17> key{};
        key[0] = std::uint32_t(c.blas);
        std::memcpy(&key[1], &world, sizeof(glm::mat4));
        if (!placed.insert(key).second) {
            ++plan.counts.deduplicated;
            continue;
        }
        TlasInstancePlan p;
        p.blas = key[0];
        p.node = c.node;
        p.world = world;
        p.mirrored = glm::determinant(glm::mat3(world)) < 0.0f;
        plan.counts.mirrored += p.mirrored ? 1 : 0;
        plan.instances.push_back(p);
    }
    if (quiet_warnings)
        plan.warnings.push_back(std::to_string(quiet_warnings) +
                                " more instances with non-finite transforms left out");
    plan.counts.instances = plan.instances.size();
    return plan;
}

std::vector<PosedBlasPlan> plan_posed_blas(const scene::Scene& scene,
                                           std::span<const GpuMesh> meshes,
                                           std::span<const std::uint32_t> scene_instances,
                                           std::span<const BlasPlan> plans) {
    std::vector<PosedBlasPlan> out;
    std::vector<std::int32_t> plan_of_group;
    bool any = false;
    for (std::uint32_t p = 0; p < plans.size(); ++p) {
        if (plans[p].group >= plan_of_group.size()) plan_of_group.resize(plans[p].group + 1, -1);
        plan_of_group[plans[p].group] = static_cast<std::int32_t>(p);
        for (const BlasGeometryPlan& g : plans[p].geometries)
            any = any || (g.mesh < meshes.size() && meshes[g.mesh].motion != 0);
    }
    if (!any) return out;
    // Which engine meshes skin (their primitive's motion has joints).
    std::vector<char> skins(meshes.size(), 0);
    for (const scene::PrimitiveInfo& prim : scene.primitives)
        if (prim.engine_mesh >= 0 && prim.motion >= 0 &&
            std::size_t(prim.engine_mesh) < skins.size() &&
            scene.motions[std::size_t(prim.motion)].skinned())
            skins[std::size_t(prim.engine_mesh)] = 1;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> gpu_instance; // (node, mesh)
    for (std::uint32_t i = 0; i < scene_instances.size(); ++i) {
        const scene::MeshInstance& inst = scene.instances[scene_instances[i]];
        gpu_instance.emplace(std::pair{inst.node_id, inst.mesh_id}, i);
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> pairs; // (node, group)
    for (const scene::MeshInstance& inst : scene.instances) {
        if (inst.mesh_id >= meshes.size() || meshes[inst.mesh_id].motion == 0) continue;
        const std::uint32_t group = scene.meshes[inst.mesh_id].group_id;
        if (group >= plan_of_group.size() || plan_of_group[group] < 0) continue;
        if (!pairs.insert({inst.node_id, group}).second) continue;
        PosedBlasPlan posed;
        posed.node = inst.node_id;
        posed.group = group;
        posed.plan = static_cast<std::uint32_t>(plan_of_group[group]);
        const bool has_skin =
            inst.node_id < scene.nodes.size() && scene.nodes[inst.node_id].skin >= 0;
        bool complete = true;
        for (const BlasGeometryPlan& g : plans[posed.plan].geometries) {
            const auto it = gpu_instance.find({inst.node_id, g.mesh});
            if (it == gpu_instance.end()) {
                complete = false;
                break;
            }
            PosedGeometryPlan pg;
            pg.mesh = g.mesh;
            pg.gpu_instance = it->second;
            pg.moves = meshes[g.mesh].motion != 0;
            posed.world_space = posed.world_space || (pg.moves && has_skin && skins[g.mesh]);
            posed.geometries.push_back(pg);
        }
        if (!complete) continue;
        for (PosedGeometryPlan& pg : posed.geometries) pg.posed = pg.moves || posed.world_space;
        out.push_back(std::move(posed));
    }
    return out;
}

} // namespace sherpa::render
