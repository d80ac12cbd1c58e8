// The path-traced lit view (RendererKind::RayTraced, DebugView::Lit): its constants,
// when its accumulation continues and when it starts over, and its read back sums.
#include "frame_recorder.h"

#include <sherpa/gpu/gpu_error.h>

#include <cmath>
#include <cstring>

namespace sherpa::render {
namespace {

// FNV-1a over the bytes of each value: what the accumulation is of.
struct KeyHash {
    std::uint64_t h = 1469598103934665603ull;
    template <typename T> void add(const T& value) {
        const auto* b = reinterpret_cast<const unsigned char*>(&value);
        for (std::size_t i = 0; i < sizeof(T); ++i) h = (h ^ b[i]) * 1099511628211ull;
    }
};

// A sample's luminance is capped here: far above any real scene's radiance, low enough
// that sums of millions of samples stay finite in 32-bit floats.
constexpr float kMaxSampleRadiance = 1e20f;

} // namespace

PathTracer::PathTracer(SceneState& scene_state, FrameSlots& slots)
    : SceneStateRefs(scene_state), slots_(slots) {}

PathTraceFrame PathTracer::record(VkCommandBuffer cmd, FrameSlot& slot,
                                  const FrameRequest& settings, bool readback) {
    if (!path_) path_ = std::make_unique<PathTracePass>(context, *resources, bindless->layout());
    if (path_environment_ != state.environment_generation) {
        path_->set_distribution(state.environment_sampling ? *state.environment_sampling
                                                           : EnvironmentDistribution{});
        path_environment_ = state.environment_generation;
    }
    if (path_lights_ != state.generation) {
        path_->set_lights(state.emissive);
        path_lights_ = state.generation;
    }
    const CameraView camera = resolve_camera(settings.camera, state.lights.cameras,
                                             float(settings.width) / float(settings.height));
    GPUFrameData constants = lighting_constants(state.lights, environment.get(), settings);
    constants.view = camera.view;
    constants.proj = camera.proj;
    constants.view_proj = camera.proj * camera.view;
    constants.camera_position = glm::vec4(camera.position, 1.0f);
    std::memcpy(resources->get(slot.frame_data).mapped, &constants, sizeof(constants));

    PathTracedFrame f;
    f.bindless = bindless->set();
    f.tlas = acceleration->tlas();
    f.materials = scene->materials().buffer();
    f.material_extras = scene->materials().extras_buffer();
    f.material_extensions = scene->materials().extensions_buffer();
    f.frame_data = resources->get(slot.frame_data).buffer.get();
    if (environment) f.environment = environment->specular_descriptor();
    f.width = settings.width;
    f.height = settings.height;
    GPUPathPushConstants& p = f.push;
    p.inv_view_proj = glm::inverse(camera.proj * camera.view);
    p.geometries = acceleration->geometry_records();
    p.texture_lod = settings.texture_lod;
    p.clear_color = settings.clear_color;
    p.max_bounces = settings.path.max_bounces;
    p.seed = settings.path.seed;
    p.sun_cos_radius = std::cos(std::clamp(settings.sun_angular_radius, 0.0f, 1.5f));
    p.max_radiance = kMaxSampleRadiance;

    KeyHash key;
    key.add(constants);
    key.add(p);
    key.add(f.width);
    key.add(f.height);
    key.add(state.generation);
    key.add(state.environment_generation);
    key.add(state.rt_pose_key);
    key.add(state.visibility_version);
    key.add(settings.path.light_sampling);
    key.add(settings.path.one_light_ray);
    key.add(state.material_generation);
    PathTraceFrame out;
    out.restarted = settings.path.restart || key.h != path_key_ || path_samples_ == 0 ||
                    path_->width() != f.width || path_->height() != f.height;
    if (out.restarted) path_samples_ = 0;
    std::uint32_t add = settings.path.samples;
    if (settings.path.max_samples > 0)
        add = path_samples_ >= settings.path.max_samples
                  ? 0
                  : std::min(add, settings.path.max_samples - path_samples_);
    if (path_samples_ == 0) add = std::max(add, 1u); // an image needs a sample
    f.light_sampling = settings.path.light_sampling;
    f.one_light_ray = settings.path.one_light_ray;
    f.first_sample = path_samples_;
    f.samples = add;
    path_->record(cmd, f, readback);
    path_samples_ += add;
    path_key_ = key.h;
    out.samples = path_samples_;
    out.added = add;
    return out;
}

PathTraceImage PathTracer::image() {
    PathTraceImage image;
    if (!path_ || path_samples_ == 0) return image;
    slots_.wait_all();
    FrameSlot& slot = slots_[slots_.next()];
    VkCommandBuffer cmd = slot.recorder.begin();
    path_->record_sums_readback(cmd);
    slot.submission = slot.recorder.submit(*resources);
    slot.has_results = false;
    slots_.wait(slot);
    path_->read_sums(image);
    image.samples = path_samples_;
    return image;
}

PathTraceImage read_path_trace(Renderer& renderer) {
    return renderer.frames().rays().path().image();
}

PathTraceError path_trace_error(Renderer& renderer) {
    return estimate_error(read_path_trace(renderer));
}

} // namespace sherpa::render
