// The loaded scene's state between frames: load and unload, the environment, and node
// visibility (the setup's mask joined by KHR_node_visibility's). A changed mask is
// expanded to subtrees once (hidden_subtrees(), the editor's rule too) and mapped to GPU
// instances for the culling pass (whose GPU cullers, shown-id lists and statistics leave
// hidden instances out); the recorder redraws the cached shadow cascades and brings the
// TLAS up to date before the next ray-traced frame. An unchanged mask costs one
// comparison. Animated properties: renderer_animated.cpp.
#include "scene_state.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/scene/visibility.h>
#include <sherpa/texture/texture_pipeline.h>

#include <chrono>

namespace sherpa::render {

SceneState::SceneState(gpu::Context& ctx, gpu::ResourceManager& res, const RendererOptions& opts)
    : context(ctx), resources(res), options(opts), bindless(res) {}

SceneState::~SceneState() {
    environment.reset();
    anisotropic_lut.reset();
    brdf_lut.reset();
    acceleration.reset();
    gpu.reset();
}

void SceneState::load(const scene::Scene& source, std::unique_ptr<GpuScene> gpu_scene,
                      const SceneSetup& scene_setup) {
    setup = scene_setup;
    gpu = std::move(gpu_scene);
    if (options.ray_tracing) {
        if (!context.info().ray_tracing_enabled)
            throw gpu::GpuError("ray tracing was asked for but the device does not ray trace "
                                "(or it was turned off: --rt off)");
        acceleration = std::make_unique<SceneAccelerationStructures>(resources, source, *gpu,
                                                                     options.acceleration);
        // The emissive images' luminance from the texture pipeline (decoded once, or cached).
        const auto start = std::chrono::steady_clock::now();
        emissive =
            emissive_lights(source, kMaxEmissiveTriangles, &gpu->materials().textures().prepared());
        emissive_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
    }
    lights.cameras.bounds = gpu->bounds().valid() ? gpu->bounds() : source.bounds;
    lights.cameras.cameras = source.cameras;
    lights.cameras.placed_cameras = source.placed_cameras;
    lights.lights = source.lights;
    lights.placed_lights = source.placed_lights;
    ++generation;
    nodes_ = source.nodes;
    instance_node_.clear();
    for (const std::uint32_t si : gpu->scene_instances())
        instance_node_.push_back(si < source.instances.size() ? source.instances[si].node_id : ~0u);
    hidden_given_.clear();
    hidden_nodes_.clear();
    // The TLAS was built with RendererOptions::acceleration's mask; ours replaces it.
    tlas_visibility = options.acceleration.hidden_nodes.empty();
    variants = source.variants;
    variant = source.variants.active;
    load_animated(source);
    update_anisotropic_lut();
}

void SceneState::unload() {
    acceleration.reset();
    gpu.reset();
    ++generation; // frame sets must stop naming the freed material buffers
    lights = SceneLights{};
    emissive = EmissiveLights{};
    emissive_ms = 0.0;
    nodes_.clear();
    instance_node_.clear();
    hidden_given_.clear();
    hidden_nodes_.clear();
    update_anisotropic_lut();
}

void SceneState::update_anisotropic_lut() {
    const bool wanted =
        environment && gpu && gpu->materials().extensions().anisotropic_materials > 0;
    if (wanted == (anisotropic_lut != nullptr)) return;
    anisotropic_lut = wanted ? std::make_unique<BrdfLut>(context, resources, true) : nullptr;
    ++environment_generation;
}

void SceneState::set_environment(const EnvironmentImage* image,
                                 const EnvironmentOptions& env_options) {
    environment.reset();
    // The lookup table is the BRDF's: made with the first environment, kept while one
    // follows another, freed with the last (no environment, no GPU bytes).
    if (!image) brdf_lut.reset();
    if (image) {
        const bool lut_built = !brdf_lut;
        if (lut_built) brdf_lut = std::make_unique<BrdfLut>(context, resources);
        environment = std::make_unique<EnvironmentMap>(context, resources, *image, env_options,
                                                       *brdf_lut, lut_built);
    }
    update_anisotropic_lut();
    // The path tracer's sampling distribution, made while the image is at hand.
    environment_sampling.reset();
    if (image && options.ray_tracing)
        environment_sampling =
            std::make_unique<EnvironmentDistribution>(environment_distribution(*image));
    ++environment_generation;
}

std::optional<std::vector<std::uint8_t>> SceneState::take_visibility_change() {
    if (!gpu) return std::nullopt;
    static const std::vector<bool> kNone;
    const std::vector<bool>& asked = setup.hidden_nodes ? *setup.hidden_nodes : kNone;
    // Nodes KHR_node_visibility hides (as loaded, or animated through
    // KHR_animation_pointer) join the ones the setup hides.
    std::vector<bool> merged;
    if (!animated_hidden_.empty()) {
        merged = animated_hidden_;
        for (std::size_t i = 0; i < asked.size() && i < merged.size(); ++i)
            merged[i] = merged[i] || asked[i];
    }
    const std::vector<bool>& given = animated_hidden_.empty() ? asked : merged;
    if (given == hidden_given_) return std::nullopt;
    hidden_given_ = given;
    hidden_nodes_ = scene::hidden_subtrees(nodes_, given);
    tlas_visibility = false;
    ++visibility_version; // the path tracer's accumulation starts over
    return hidden_instances();
}

std::vector<std::uint8_t> SceneState::hidden_instances() const {
    std::vector<std::uint8_t> hidden(instance_node_.size(), 0);
    for (std::size_t i = 0; i < hidden.size(); ++i)
        hidden[i] = instance_node_[i] < hidden_nodes_.size() && hidden_nodes_[instance_node_[i]];
    return hidden;
}

} // namespace sherpa::render
