#include <sherpa/scene/scene.h>

#include "validate_internal.h" // add_import_message

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace sherpa::scene {

namespace {

// An instance select_scene leaves out: a SHERPA_INSTANCE_SKIPPED warning at the node's
// pointer and the text in Scene::warnings, once however often the scene is selected.
void left_out(Scene& scene, const std::string& text) {
    if (std::find(scene.warnings.begin(), scene.warnings.end(), text) != scene.warnings.end())
        return;
    scene.warnings.push_back(text);
    detail::add_import_message(scene.validation, "SHERPA_INSTANCE_SKIPPED", Severity::Warning,
                               text);
}

} // namespace

glm::mat4 Node::local_transform() const {
    if (has_matrix) return matrix;
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

glm::mat4 InstanceRow::matrix() const {
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

glm::mat4 instance_transform(const Scene& scene, const MeshInstance& instance) {
    if (instance.row < 0 || instance.node_id >= scene.nodes.size()) return glm::mat4(1.0f);
    const auto& instancing = scene.nodes[instance.node_id].instancing;
    if (!instancing || std::size_t(instance.row) >= instancing->rows.size()) return glm::mat4(1.0f);
    return instancing->rows[std::size_t(instance.row)].matrix();
}

SamplerDesc Scene::sampler_of(const TextureRecord& t) const {
    if (t.sampler >= 0 && static_cast<std::size_t>(t.sampler) < samplers.size())
        return samplers[static_cast<std::size_t>(t.sampler)];
    return SamplerDesc{}; // glTF: repeat wrapping, auto filtering
}

std::vector<std::pair<std::string, Provenance>>
Scene::attribute_provenance(const PrimitiveInfo& p) const {
    std::vector<std::pair<std::string, Provenance>> out;
    const Mesh* mesh =
        p.engine_mesh >= 0 ? &meshes[static_cast<std::size_t>(p.engine_mesh)] : nullptr;
    if (mesh)
        for (VertexAttribute a : kAllVertexAttributes)
            out.emplace_back(gltf_name(a), mesh->provenance_of(a));
    for (const std::string& name : p.file_attributes) {
        const bool canonical =
            std::any_of(out.begin(), out.end(), [&](const auto& e) { return e.first == name; });
        if (!canonical) out.emplace_back(name, Provenance::Authored);
    }
    return out;
}

std::uint64_t Scene::node_primitive_pairs() const {
    std::uint64_t pairs = 0;
    for (std::uint32_t n : displayed_nodes)
        if (nodes[n].mesh >= 0 && static_cast<std::size_t>(nodes[n].mesh) < mesh_primitives.size())
            pairs += mesh_primitives[static_cast<std::size_t>(nodes[n].mesh)].size() *
                     (nodes[n].instancing ? nodes[n].instancing->file_rows : 1u);
    return pairs;
}

bool select_scene(Scene& scene, std::int32_t scene_index, std::string& error) {
    if (scene.scenes.empty()) {
        // Nothing to display (e.g. a file with no nodes): an empty flattening.
        scene.displayed_scene = -1;
        scene.instances.clear();
        scene.placed_lights.clear();
        scene.placed_cameras.clear();
        scene.node_world.assign(scene.nodes.size(), glm::mat4(1.0f));
        scene.displayed_nodes.clear();
        scene.bounds = core::Aabb::empty();
        return true;
    }
    if (scene_index < 0 || static_cast<std::size_t>(scene_index) >= scene.scenes.size()) {
        error = "scene index " + std::to_string(scene_index) + " out of range (" +
                std::to_string(scene.scenes.size()) + " scenes)";
        return false;
    }
    std::vector<MeshInstance> instances;
    std::vector<PlacedLight> lights;
    std::vector<PlacedCamera> cameras;
    std::vector<glm::mat4> world(scene.nodes.size(), glm::mat4(1.0f));
    std::vector<std::uint32_t> displayed;
    core::Aabb bounds;

    // Iterative DFS: hierarchies can be deep (VC) and the importer has already
    // rejected cycles and multiple parents, so every node is visited once.
    std::vector<std::uint32_t> stack(
        scene.scenes[static_cast<std::size_t>(scene_index)].roots.rbegin(),
        scene.scenes[static_cast<std::size_t>(scene_index)].roots.rend());
    for (std::uint32_t r : stack) world[r] = scene.nodes[r].local_transform();
    while (!stack.empty()) {
        const std::uint32_t id = stack.back();
        stack.pop_back();
        const Node& node = scene.nodes[id];
        const glm::mat4& m = world[id];
        displayed.push_back(id);
        if (!core::is_finite(m)) {
            error = "nodes[" + std::to_string(id) + "]: world transform is not finite";
            return false;
        }
        if (node.mesh >= 0 && static_cast<std::size_t>(node.mesh) < scene.mesh_primitives.size()) {
            // EXT_mesh_gpu_instancing: one instance per row, instead of the node's own.
            const NodeInstancing* rows = node.instancing ? &*node.instancing : nullptr;
            const std::size_t row_count = rows ? rows->rows.size() : 1;
            for (std::size_t r = 0; r < row_count; ++r) {
                const glm::mat4 w = rows ? m * rows->rows[r].matrix() : m;
                for (std::int32_t mesh_id :
                     scene.mesh_primitives[static_cast<std::size_t>(node.mesh)]) {
                    if (mesh_id < 0) continue;
                    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(mesh_id)];
                    MeshInstance inst;
                    inst.mesh_id = static_cast<std::uint32_t>(mesh_id);
                    inst.material_id = mesh.material_id;
                    inst.node_id = id;
                    inst.row = rows ? static_cast<std::int32_t>(r) : -1;
                    inst.world = inst.prev_world = w;
                    inst.world_bounds = mesh.local_bounds.transformed(w);
                    // Finite matrix x finite positions can still exceed the float range:
                    // infinite bounds would print as null and frame nothing, and the
                    // vertices would reach the rasterizer as infinities. The instance is
                    // left out, by name; the rest of the scene is shown.
                    if (!core::is_finite(inst.world_bounds.min) ||
                        !core::is_finite(inst.world_bounds.max)) {
                        left_out(scene,
                                 "nodes[" + std::to_string(id) + "]" +
                                     (node.name.empty() ? "" : " \"" + node.name + "\"") +
                                     (rows ? " EXT_mesh_gpu_instancing row " +
                                                 std::to_string(rows->rows[r].file_row)
                                           : std::string()) +
                                     ": world bounds of its mesh overflow the float range (" +
                                     (rows ? "node transform x instance row" : "node transform") +
                                     " x positions); the instance is not drawn");
                        continue;
                    }
                    bounds.expand(inst.world_bounds);
                    instances.push_back(inst);
                }
            }
        }
        if (node.light >= 0) {
            PlacedLight pl;
            pl.light = static_cast<std::uint32_t>(node.light);
            pl.node = id;
            pl.position = glm::vec3(m[3]);
            const glm::vec3 d = glm::vec3(m * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
            const float len = glm::length(d);
            pl.direction = len > 0.0f ? d / len : glm::vec3(0.0f, 0.0f, -1.0f);
            lights.push_back(pl);
        }
        if (node.camera >= 0) cameras.push_back({static_cast<std::uint32_t>(node.camera), id, m});
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
            world[*it] = m * scene.nodes[*it].local_transform();
            stack.push_back(*it);
        }
    }
    scene.displayed_scene = scene_index;
    scene.instances = std::move(instances);
    scene.placed_lights = std::move(lights);
    scene.placed_cameras = std::move(cameras);
    scene.node_world = std::move(world);
    scene.displayed_nodes = std::move(displayed);
    scene.bounds = bounds;
    return true;
}

} // namespace sherpa::scene
