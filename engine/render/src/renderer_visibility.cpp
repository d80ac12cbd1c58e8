// What changes in the loaded scene between frames, applied before a frame: the frame's
// animated properties (KHR_animation_pointer, renderer_animated.cpp) and the node
// visibility (SceneSetup::hidden_nodes and the nodes KHR_node_visibility hides). The
// scene state maps a changed mask to GPU instances once (scene_state.cpp); here the
// animated materials are uploaded (after the frames in flight, which read the same
// buffers), the culling takes the mask (after the frames in flight that index the GPU
// cullers being replaced), the cached shadow cascades are redrawn, and the TLAS follows
// before the next ray-traced frame. An unchanged frame costs two comparisons.
#include "scene_changes.h"

namespace sherpa::render {

SceneChanges::SceneChanges(SceneState& scene_state, FrameSlots& slots, CullingPass& culling_pass,
                           ShadowPass& shadows)
    : SceneStateRefs(scene_state), slots_(slots), culling(culling_pass), shadows_(shadows) {}

void SceneChanges::apply_scene_changes(const FrameRequest& settings, bool rt) {
    if (!scene) return;
    static const std::vector<scene::AnimatedProperty> kNone;
    if (auto materials = state.animate(settings.pose ? settings.pose->properties : kNone)) {
        slots_.wait_all();
        if (update_scene_materials(*state.gpu, *materials)) {
            ++state.material_generation;
            shadows_.invalidate(); // masked casters read alpha and cutoff
        }
    }
    if (auto hidden = state.take_visibility_change()) {
        retire_culling();
        culling.set_hidden(std::move(*hidden), *scene);
        shadows_.invalidate(); // the casters changed
    }
    if (rt && acceleration && !state.tlas_visibility) {
        slots_.wait_all();
        acceleration->set_hidden_nodes(state.hidden_nodes());
        // The rebuilt TLAS holds the loaded transforms: the frame's pose goes in again.
        state.rt_pose_generation = 0;
        state.tlas_visibility = true;
    }
}

void SceneChanges::retire_culling() {
    for (auto& s : slots_) {
        slots_.wait(*s);
        if (s->has_results && !s->history_pushed) {
            FrameStats unused;
            culling.read_stats(*s, scene.get(), unused);
        }
        s->culling.count = 0;
    }
}

} // namespace sherpa::render
