// Which box automatic framing fits (framing.h): what is drawn, posed when asked.
#include <sherpa/scene/animation.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene.h>

#include <algorithm>

namespace sherpa {
namespace {

Aabb bounds_of(const Scene& scene, const Pose* pose, bool skip_backdrop) {
    const auto backdrop = [&](std::uint32_t node) {
        return skip_backdrop && std::find(scene.backdrop_nodes.begin(), scene.backdrop_nodes.end(),
                                          node) != scene.backdrop_nodes.end();
    };
    Aabb box;
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

} // namespace

Aabb framing_bounds(const Scene& scene, const Pose* pose) {
    const Aabb subject = bounds_of(scene, pose, true);
    return subject.valid() ? subject : bounds_of(scene, pose, false);
}

} // namespace sherpa
