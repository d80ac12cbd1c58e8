// Node visibility in the frames (SceneSetup::hidden_nodes): the scene state maps a
// changed mask to GPU instances once (scene_state.cpp); here the culling takes it
// (after the frames in flight that index the GPU cullers being replaced), the cached
// shadow cascades are redrawn, and the TLAS follows before the next ray-traced frame.
// An unchanged mask costs one comparison.
#include "frame_recorder.h"

namespace sherpa::gpu {

void FrameRecorder::apply_visibility(bool rt) {
    if (!scene) return;
    if (auto hidden = state.take_visibility_change()) {
        // Frames in flight index the GPU cullers being replaced: wait for them and
        // keep their statistics in the history now.
        for (auto& s : slots_) {
            wait_slot(*s);
            if (s->has_results && !s->history_pushed) {
                FrameStats unused;
                culling.read_stats(*s, scene.get(), unused);
            }
            s->culling.count = 0;
        }
        culling.set_hidden(std::move(*hidden), *scene);
        shadows_.invalidate(); // the casters changed
    }
    if (rt && acceleration && !state.tlas_visibility) {
        for (auto& s : slots_) wait_slot(*s);
        acceleration->set_hidden_nodes(state.hidden_nodes());
        // The rebuilt TLAS holds the loaded transforms: the frame's pose goes in again.
        state.rt_pose_generation = 0;
        state.tlas_visibility = true;
    }
}

} // namespace sherpa::gpu
