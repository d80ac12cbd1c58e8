// CPU posing (exact skinned + morphed positions) and the conservative per-joint bounds
// culling uses while things move.
#include "motion_internal.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/culling.h>

#include <algorithm>
#include <cmath>

namespace sherpa::scene {
namespace {

const std::vector<glm::mat4>* joints_of(const Scene& scene, const Pose& pose, std::uint32_t node,
                                        const PrimitiveMotion* m) {
    const std::int32_t skin = scene.nodes[node].skin;
    if (!m || !m->skinned() || skin < 0) return nullptr;
    return &pose.joint_matrices[static_cast<std::size_t>(skin)];
}

// Transformed boxes are computed in float like the positions they bound; this slack
// (relative to the box's magnitude) covers the rounding of both.
core::Aabb padded(const core::Aabb& b) {
    if (!b.valid()) return b;
    const glm::vec3 mag = glm::max(glm::abs(b.min), glm::abs(b.max));
    const float pad = 1e-5f * std::max({mag.x, mag.y, mag.z, 1e-30f});
    return core::Aabb::from_min_max(b.min - glm::vec3(pad), b.max + glm::vec3(pad));
}

// A box the pose pushed past the float range (inf, or NaN from inf - inf).
bool overflows(const core::Aabb& b) {
    return b.valid() && box_is_invalid(b.min, b.max);
}

} // namespace

std::vector<glm::vec3> posed_positions(const Scene& scene, const Pose& pose, std::uint32_t node,
                                       const PrimitiveInfo& prim, const glm::mat4& instance) {
    std::vector<glm::vec3> out;
    if (prim.engine_mesh < 0) return out;
    const glm::mat4 world = pose.world[node] * instance;
    if (prim.motion < 0) {
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(prim.engine_mesh)];
        out.reserve(mesh.vertices.size());
        for (const Vertex& v : mesh.vertices)
            out.push_back(glm::vec3(world * glm::vec4(v.position, 1.0f)));
        return out;
    }
    const PrimitiveMotion& m = scene.motions[static_cast<std::size_t>(prim.motion)];
    out = m.base_positions;
    const auto& weights = pose.weights[node];
    for (std::size_t k = 0; k < m.targets.size() && k < weights.size(); ++k) {
        const auto& d = m.targets[k].position;
        if (d.empty() || weights[k] == 0.0f) continue;
        for (std::size_t i = 0; i < out.size(); ++i) out[i] += weights[k] * d[i];
    }
    if (const auto* joints = joints_of(scene, pose, node, &m)) {
        const std::uint32_t n = m.influences;
        for (std::size_t i = 0; i < out.size(); ++i) {
            glm::mat4 skin(0.0f);
            for (std::uint32_t k = 0; k < n; ++k)
                if (const float w = m.weights[i * n + k]; w != 0.0f)
                    skin += w * (*joints)[m.joints[i * n + k]];
            out[i] = glm::vec3(skin * glm::vec4(out[i], 1.0f));
        }
    } else {
        for (auto& p : out) p = glm::vec3(world * glm::vec4(p, 1.0f));
    }
    return out;
}

core::Aabb culling_bounds(const Scene& scene, const Pose& pose, std::uint32_t node,
                          const PrimitiveInfo& prim, const glm::mat4& instance) {
    if (prim.engine_mesh < 0) return core::Aabb::empty();
    const glm::mat4 world = pose.world[node] * instance;
    if (prim.motion < 0)
        return padded(
            scene.meshes[static_cast<std::size_t>(prim.engine_mesh)].local_bounds.transformed(
                world));
    const PrimitiveMotion& m = scene.motions[static_cast<std::size_t>(prim.motion)];
    const auto* joints = joints_of(scene, pose, node, &m);
    const auto& weights = pose.weights[node];
    core::Aabb out;
    for (const InfluenceBox& b : m.boxes) {
        glm::vec3 lo = b.base.min, hi = b.base.max;
        for (std::size_t k = 0; k < b.deltas.size() && k < weights.size(); ++k) {
            if (!b.deltas[k].valid()) continue;
            const float w = weights[k];
            lo += glm::min(w * b.deltas[k].min, w * b.deltas[k].max);
            hi += glm::max(w * b.deltas[k].min, w * b.deltas[k].max);
        }
        const glm::mat4& to_world =
            joints && b.joint >= 0 ? (*joints)[static_cast<std::size_t>(b.joint)] : world;
        out.expand(core::Aabb::from_min_max(lo, hi).transformed(to_world));
    }
    return padded(out);
}

std::vector<core::Aabb> instance_culling_bounds(const Scene& scene, const Pose& pose) {
    std::vector<const PrimitiveInfo*> of_mesh(scene.meshes.size(), nullptr);
    for (const PrimitiveInfo& p : scene.primitives)
        if (p.engine_mesh >= 0) of_mesh[static_cast<std::size_t>(p.engine_mesh)] = &p;
    std::vector<core::Aabb> out;
    out.reserve(scene.instances.size());
    for (const MeshInstance& inst : scene.instances) {
        const PrimitiveInfo* p = inst.mesh_id < of_mesh.size() ? of_mesh[inst.mesh_id] : nullptr;
        out.push_back(
            p ? culling_bounds(scene, pose, inst.node_id, *p, instance_transform(scene, inst))
              : inst.world_bounds);
    }
    return out;
}

void apply_pose_bounds(Scene& scene, const Pose& pose) {
    const std::vector<core::Aabb> bounds = instance_culling_bounds(scene, pose);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        MeshInstance& inst = scene.instances[i];
        inst.world = pose.world[inst.node_id] * instance_transform(scene, inst);
        inst.world_bounds = bounds[i];
    }
}

PosedBounds posed_scene_bounds(const Scene& scene, const Pose& pose) {
    PosedBounds out;
    for (std::uint32_t n : scene.displayed_nodes) {
        const Node& node = scene.nodes[n];
        if (node.mesh < 0) continue;
        bool overflow = false;
        const std::size_t rows = node.instancing ? node.instancing->rows.size() : 1;
        for (std::size_t r = 0; r < rows; ++r) {
            const glm::mat4 row =
                node.instancing ? node.instancing->rows[r].matrix() : glm::mat4(1);
            for (const PrimitiveInfo& p : scene.primitives) {
                if (p.mesh != static_cast<std::uint32_t>(node.mesh) || p.engine_mesh < 0) continue;
                const std::vector<glm::vec3> posed = posed_positions(scene, pose, n, p, row);
                const core::Aabb culling = culling_bounds(scene, pose, n, p, row);
                // Both boxes leave out what either cannot bound, so the conservative one
                // still holds the exact one.
                if (overflows(culling) || !std::all_of(posed.begin(), posed.end(), [](glm::vec3 v) {
                        return core::is_finite(v);
                    })) {
                    overflow = true;
                    continue;
                }
                for (const glm::vec3& v : posed) out.exact.expand(v);
                out.culling.expand(culling);
            }
        }
        if (overflow) out.overflow.push_back(n);
    }
    return out;
}

std::vector<std::uint32_t> posed_overflow_nodes(const Scene& scene, const Pose& pose) {
    const std::vector<core::Aabb> boxes = instance_culling_bounds(scene, pose);
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const std::uint32_t node = scene.instances[i].node_id;
        if (overflows(boxes[i]) && std::find(out.begin(), out.end(), node) == out.end())
            out.push_back(node);
    }
    return out;
}

std::string posed_overflow_warning(const Scene& scene, std::uint32_t node) {
    const std::string& name = node < scene.nodes.size() ? scene.nodes[node].name : std::string();
    return "nodes[" + std::to_string(node) + "]" + (name.empty() ? "" : " \"" + name + "\"") +
           ": posed bounds of its mesh overflow the float range (joint matrices, node transforms "
           "or morph weights x positions); left out of the posed bounds";
}

namespace detail {

void compute_influence_boxes(PrimitiveMotion& m) {
    const std::size_t count = m.base_positions.size();
    const std::uint32_t n = m.influences;
    std::vector<InfluenceBox> boxes(m.skinned() ? m.max_joint + 1 : 1);
    for (std::size_t j = 0; j < boxes.size(); ++j) {
        boxes[j].joint = m.skinned() ? static_cast<std::int32_t>(j) : -1;
        boxes[j].deltas.resize(m.targets.size());
    }
    auto add = [&](InfluenceBox& b, std::size_t i) {
        b.base.expand(m.base_positions[i]);
        for (std::size_t k = 0; k < m.targets.size(); ++k)
            if (!m.targets[k].position.empty()) b.deltas[k].expand(m.targets[k].position[i]);
    };
    for (std::size_t i = 0; i < count; ++i) {
        if (!m.skinned()) {
            add(boxes[0], i);
            continue;
        }
        for (std::uint32_t k = 0; k < n; ++k) // max_joint bounds every weighted joint index
            if (m.weights[i * n + k] > 0.0f) add(boxes[m.joints[i * n + k]], i);
    }
    for (auto& b : boxes)
        if (b.base.valid()) m.boxes.push_back(std::move(b));
}

} // namespace detail
} // namespace sherpa::scene
