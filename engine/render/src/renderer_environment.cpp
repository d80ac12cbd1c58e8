// The Renderer's environment: made on set_environment() into the scene state, bound
// into each frame set the next time that slot records (bind_frame_set), freed when
// replaced or removed.
#include "frame_recorder.h"

namespace sherpa::render {

void Renderer::set_environment(const EnvironmentImage* image, const EnvironmentOptions& options) {
    // Frames in flight may read the old maps (and the background drawn from them):
    // wait for them before they go.
    frames_->wait_all(true);
    scene_->set_environment(image, options);
    resources_->collect_garbage();
}

} // namespace sherpa::render
