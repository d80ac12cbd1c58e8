#include "skeleton_lines.h"

#include <algorithm>
#include <cmath>

#include <sherpa/render/frame_request.h>

namespace sherpa::render {

namespace {
bool finite(const glm::vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}
} // namespace

void append_skeleton(std::vector<GPULineVertex>& out, std::span<const scene::Skin> skins,
                     std::span<const scene::Node> nodes, std::span<const glm::mat4> world,
                     std::optional<std::uint32_t> selected_joint, float joint_size) {
    auto position = [&](std::uint32_t node) { return glm::vec3(world[node][3]); };
    auto line = [&](glm::vec3 a, glm::vec3 b, glm::vec4 color) {
        out.push_back({glm::vec4(a, 1.0f), color});
        out.push_back({glm::vec4(b, 1.0f), color});
    };
    for (const scene::Skin& skin : skins)
        for (const std::uint32_t joint : skin.joints) {
            if (joint >= world.size() || joint >= nodes.size()) continue;
            const glm::vec3 p = position(joint);
            if (!finite(p)) continue;
            const bool selected = selected_joint && *selected_joint == joint;
            // The bone: up to the nearest ancestor that is a joint of this skin (a
            // skeleton may skip nodes that are not joints). Bounded against cycles.
            std::int32_t parent = nodes[joint].parent;
            for (std::size_t depth = 0; parent >= 0 && depth < nodes.size(); ++depth) {
                const auto pj = static_cast<std::uint32_t>(parent);
                if (std::find(skin.joints.begin(), skin.joints.end(), pj) != skin.joints.end())
                    break;
                parent = pj < nodes.size() ? nodes[pj].parent : -1;
            }
            if (parent >= 0 && static_cast<std::size_t>(parent) < world.size()) {
                const glm::vec3 q = position(static_cast<std::uint32_t>(parent));
                if (finite(q)) line(q, p, selected ? kHighlightDetailColor : kBoneColor);
            }
            const float r = selected ? 2.0f * joint_size : joint_size;
            const glm::vec4 color = selected ? kHighlightDetailColor : kJointColor;
            for (int axis = 0; axis < 3; ++axis) {
                glm::vec3 d(0.0f);
                d[axis] = r;
                line(p - d, p + d, color);
            }
        }
}

} // namespace sherpa::render
