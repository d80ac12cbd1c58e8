// The Renderer's environment: made on set_environment(), bound into each frame set
// the next time that slot records (bind_frame_set), freed when replaced or removed.
#include "renderer_impl.h"

namespace sherpa::gpu {

void Renderer::Impl::set_environment(const EnvironmentImage* image,
                                     const EnvironmentOptions& env_options) {
    // Frames in flight may read the old maps: wait for them before they go.
    for (auto& slot : slots_) wait_slot(*slot);
    environment.reset();
    if (image)
        environment = std::make_unique<EnvironmentMap>(context, *resources, *image, env_options);
    // The path tracer's sampling distribution, made while the image is at hand.
    environment_distribution_.reset();
    if (image && options.ray_tracing)
        environment_distribution_ =
            std::make_unique<EnvironmentDistribution>(environment_distribution(*image));
    ++environment_generation_;
    resources->collect_garbage();
}

void Renderer::set_environment(const EnvironmentImage* image, const EnvironmentOptions& options) {
    impl_->set_environment(image, options);
}

} // namespace sherpa::gpu
