// Which box automatic framing fits (framing.h): what is drawn, posed when asked.
#include <sherpa/scene/animation.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace sherpa::scene {
namespace {

core::Aabb bounds_of(const Scene& scene, const Pose* pose, bool skip_backdrop) {
    const auto backdrop = [&](std::uint32_t node) {
        return skip_backdrop && std::find(scene.backdrop_nodes.begin(), scene.backdrop_nodes.end(),
                                          node) != scene.backdrop_nodes.end();
    };
    core::Aabb box;
    if (!pose) {
        for (const MeshInstance& inst : scene.instances)
            if (!backdrop(inst.node_id) && inst.world_bounds.valid()) box.expand(inst.world_bounds);
        return box;
    }
    for (std::uint32_t n : scene.displayed_nodes) {
        const Node& node = scene.nodes[n];
        if (node.mesh < 0 || backdrop(n)) continue;
        for (const PrimitiveInfo& p : scene.primitives)
            if (p.mesh == static_cast<std::uint32_t>(node.mesh) && p.engine_mesh >= 0)
                for (const glm::vec3& v : posed_positions(scene, *pose, n, p)) box.expand(v);
    }
    return box;
}

// Coordinates beyond this are left out of the fit, as posed bounds leave out what
// overflows (PosedBounds::overflow): the fit squares extents and sums them, and a
// 3e38 vertex would turn the camera into inf/NaN (an empty image).
constexpr float kMaxFramedCoordinate = 1e18f;

bool frameable(const glm::vec3& v) {
    return core::is_finite(v) && std::abs(v.x) <= kMaxFramedCoordinate &&
           std::abs(v.y) <= kMaxFramedCoordinate && std::abs(v.z) <= kMaxFramedCoordinate;
}

// Every drawn vertex in world space, posed when asked; the backdrop left out when
// `skip_backdrop`.
std::vector<glm::vec3> points_of(const Scene& scene, const Pose* pose, bool skip_backdrop) {
    std::unordered_map<std::uint32_t, const PrimitiveInfo*> prim_of_mesh;
    for (const PrimitiveInfo& p : scene.primitives)
        if (p.engine_mesh >= 0) prim_of_mesh.emplace(static_cast<std::uint32_t>(p.engine_mesh), &p);
    std::vector<glm::vec3> out;
    for (const MeshInstance& inst : scene.instances) {
        if (inst.mesh_id >= scene.meshes.size()) continue;
        if (skip_backdrop && std::find(scene.backdrop_nodes.begin(), scene.backdrop_nodes.end(),
                                       inst.node_id) != scene.backdrop_nodes.end())
            continue;
        const auto prim = prim_of_mesh.find(inst.mesh_id);
        if (pose && prim != prim_of_mesh.end() && inst.node_id < pose->world.size()) {
            for (const glm::vec3& v : posed_positions(scene, *pose, inst.node_id, *prim->second,
                                                      instance_transform(scene, inst)))
                if (frameable(v)) out.push_back(v);
            continue;
        }
        for (const Vertex& v : scene.meshes[inst.mesh_id].vertices) {
            const glm::vec3 w = glm::vec3(inst.world * glm::vec4(v.position, 1.0f));
            if (frameable(w)) out.push_back(w);
        }
    }
    return out;
}

} // namespace

std::vector<glm::vec3> framing_points(const Scene& scene, const Pose* pose) {
    std::vector<glm::vec3> subject = points_of(scene, pose, true);
    return subject.empty() ? points_of(scene, pose, false) : subject;
}

glm::vec3 framing_front_hint(const Scene& scene, const core::Aabb& drawn) {
    if (scene.placed_cameras.empty()) return glm::vec3(0.0f);
    const glm::mat4& world = scene.placed_cameras.front().world;
    const glm::vec3 eye = glm::vec3(world[3]);
    if (drawn.valid() && core::is_finite(eye)) {
        const glm::vec3 to_eye = eye - drawn.center();
        if (to_eye.x * to_eye.x + to_eye.z * to_eye.z > 1e-12f) return {to_eye.x, 0.0f, to_eye.z};
    }
    const glm::vec3 back = glm::vec3(world[2]); // the camera looks down its -Z
    return core::is_finite(back) ? glm::vec3(back.x, 0.0f, back.z) : glm::vec3(0.0f);
}

CameraSpec frame_scene(const Scene& scene, const Pose* pose, const FramingOptions& options) {
    const std::vector<glm::vec3> points = framing_points(scene, pose);
    core::Aabb drawn;
    for (const glm::vec3& p : points) drawn.expand(p);
    if (!drawn.valid()) return frame_box(scene.bounds, options);
    return frame_points_along(points, auto_view_direction(drawn, framing_front_hint(scene, drawn)),
                              options);
}

core::Aabb framing_bounds(const Scene& scene, const Pose* pose) {
    const core::Aabb subject = bounds_of(scene, pose, true);
    return subject.valid() ? subject : bounds_of(scene, pose, false);
}

} // namespace sherpa::scene
