// freeze_pose(): a scene posed on the CPU, as a static scene (the GPU skinning test's
// independent path, the skinning benchmark's static twin).
#include <sherpa/scene/animation.h>

namespace sherpa::scene {

Scene freeze_pose(const Scene& s, const Pose& pose) {
    Scene out = s;
    out.meshes.clear();
    out.instances.clear();
    out.bounds = core::Aabb{};
    for (const MeshInstance& inst : s.instances) {
        const PrimitiveInfo* prim = nullptr;
        for (const PrimitiveInfo& p : s.primitives)
            if (p.engine_mesh == static_cast<std::int32_t>(inst.mesh_id)) prim = &p;
        if (!prim) continue;
        Mesh mesh = s.meshes[inst.mesh_id];
        const glm::mat4 row = instance_transform(s, inst);
        const std::vector<glm::vec3> posed = posed_positions(s, pose, inst.node_id, *prim, row);
        const glm::mat4 world = pose.world[inst.node_id] * row;
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(world)));
        const PrimitiveMotion* m =
            prim->motion >= 0 ? &s.motions[static_cast<std::size_t>(prim->motion)] : nullptr;
        const std::int32_t skin = s.nodes[inst.node_id].skin;
        mesh.local_bounds = core::Aabb{};
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            const std::size_t src = mesh.source_vertex.empty() ? v : mesh.source_vertex[v];
            Vertex& vx = mesh.vertices[v];
            vx.position = posed[m ? src : v];
            // Normals as the vertex stage leaves them (not renormalised): morphed, then
            // the blended joint matrix or the node's normal matrix.
            glm::vec3 n = vx.normal, t = glm::vec3(vx.tangent);
            if (m) {
                const auto& w = pose.weights[inst.node_id];
                for (std::size_t k = 0; k < m->targets.size() && k < w.size(); ++k) {
                    if (!m->targets[k].normal.empty()) n += w[k] * m->targets[k].normal[src];
                    if (!m->targets[k].tangent.empty()) t += w[k] * m->targets[k].tangent[src];
                }
            }
            if (m && m->skinned() && skin >= 0) {
                glm::mat4 j(0.0f);
                for (std::uint32_t k = 0; k < m->influences; ++k) {
                    const float w = m->weights[src * m->influences + k];
                    if (w != 0.0f)
                        j += w * pose.joint_matrices[static_cast<std::size_t>(skin)]
                                                    [m->joints[src * m->influences + k]];
                }
                n = glm::mat3(j) * n;
                t = glm::mat3(j) * t;
            } else {
                n = normal_matrix * n;
                t = glm::mat3(world) * t; // tangents follow the surface (handedness kept)
            }
            vx.normal = n;
            vx.tangent = glm::vec4(t, vx.tangent.w);
            mesh.local_bounds.expand(vx.position);
        }
        MeshInstance copy = inst;
        copy.mesh_id = static_cast<std::uint32_t>(out.meshes.size());
        copy.world = copy.prev_world = glm::mat4(1.0f);
        copy.world_bounds = mesh.local_bounds;
        out.bounds.expand(mesh.local_bounds);
        out.meshes.push_back(std::move(mesh));
        out.instances.push_back(copy);
    }
    out.motions.clear();
    out.animations.clear();
    out.skins.clear();
    for (Node& n : out.nodes) n.skin = -1;
    for (PrimitiveInfo& p : out.primitives) p.motion = -1;
    return out;
}

} // namespace sherpa::scene
