// KHR_animation_pointer inside the renderer: the frame's pose carries the animated
// property values (Pose::properties). When they differ from the last applied ones,
// copies of the loaded materials, lights and cameras take them
// (apply_animated_properties()); the lights and cameras go to the scene state's
// SceneLights (the frame constants), node visibility joins SceneSetup::hidden_nodes, and
// the materials reach the GPU through the one narrow path GpuMaterials::update(), which
// uploads only the records that changed (after the frames in flight, which read the same
// buffers: SceneChanges::apply_scene_changes()). A frame without animated values costs
// one comparison.
#include "scene_state.h"

#include <algorithm>
#include <cstring>

namespace sherpa::render {
namespace {

bool same(const std::vector<scene::AnimatedProperty>& a,
          const std::vector<scene::AnimatedProperty>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::memcmp(a[i].value, b[i].value, sizeof a[i].value) != 0 ||
            a[i].target.property != b[i].target.property ||
            a[i].target.object != b[i].target.object || a[i].target.slot != b[i].target.slot)
            return false;
    return true;
}

} // namespace

void SceneState::load_animated(const scene::Scene& source) {
    // Copies only for a file that animates properties: the others keep nothing.
    const bool animates =
        std::any_of(source.animations.begin(), source.animations.end(),
                    [](const scene::Animation& a) { return !a.pointers.empty(); });
    base_materials_ = animates ? source.materials : std::vector<scene::MaterialInstance>{};
    base_lights_ = animates ? source.lights : std::vector<scene::Light>{};
    base_cameras_ = animates ? source.cameras : std::vector<scene::Camera>{};
    materials_animated_ = false;
    base_visible_.clear();
    bool hidden = false;
    for (const scene::Node& n : source.nodes) {
        base_visible_.push_back(n.visible);
        hidden |= !n.visible;
    }
    animated_.clear();
    animated_hidden_.clear();
    if (hidden) // KHR_node_visibility's own values, before any animation
        for (bool v : base_visible_) animated_hidden_.push_back(!v);
}

std::optional<std::vector<scene::MaterialInstance>>
SceneState::animate(const std::vector<scene::AnimatedProperty>& values) {
    if (!gpu) return std::nullopt;
    if (same(values, animated_) ||
        (base_materials_.empty() && base_lights_.empty() && base_cameras_.empty()))
        return std::nullopt; // the file animates no property
    std::vector<scene::MaterialInstance> materials = base_materials_;
    lights.lights = base_lights_;
    lights.cameras.cameras = base_cameras_;
    std::vector<bool> visible = base_visible_;
    const std::vector<std::uint32_t> touched = scene::apply_animated_properties(
        values, materials, lights.lights, lights.cameras.cameras, &visible);
    std::vector<bool> hidden(visible.size());
    bool any_hidden = false;
    for (std::size_t i = 0; i < visible.size(); ++i) any_hidden |= hidden[i] = !visible[i];
    animated_hidden_ = any_hidden ? std::move(hidden) : std::vector<bool>{};
    // Materials changed now or before (back to the loaded values): rebuild and upload
    // what differs from what the buffers hold.
    const bool materials_animated = !touched.empty() || materials_animated_;
    materials_animated_ = !touched.empty();
    animated_ = values;
    if (!materials_animated) return std::nullopt;
    return materials;
}

} // namespace sherpa::render
