#pragma once
// What a load fixes and the frames only read (private to the render layer): the scene on
// the GPU (GpuScene: streams, instances, materials and textures in the bindless table),
// its acceleration structures and the pose they hold, the node visibility, the lights
// and cameras frames are resolved against, the emissive triangles the path tracer
// samples, the material variants and the animated properties' loaded values, and the
// environment. Frame slots, targets and passes are the FrameRecorder's
// (frame_recorder.h), which reads this state.
#include "environment_map.h"

#include <sherpa/gpu/bindless.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/emissive_lights.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/path_trace.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/animation_pointer.h>
#include <sherpa/scene/material_variants.h>

#include <optional>

namespace sherpa::render {

// What lighting and camera resolution read of the loaded scene (no whole Scene kept).
struct SceneLights {
    SceneCameras cameras; // bounds (the GPU scene's when valid) and the file's cameras
    std::vector<scene::Light> lights;
    std::vector<scene::PlacedLight> placed_lights;
};

class SceneState {
public:
    SceneState(gpu::Context& context, gpu::ResourceManager& resources,
               const RendererOptions& options);
    ~SceneState();
    SceneState(const SceneState&) = delete;
    SceneState& operator=(const SceneState&) = delete;

    // `gpu_scene` (made from `source`) becomes the loaded scene, set up as `setup` says;
    // with RendererOptions::ray_tracing its acceleration structures are built here.
    void load(const scene::Scene& source, std::unique_ptr<GpuScene> gpu_scene,
              const SceneSetup& setup);
    // The scene leaves (frames using it must be complete).
    void unload();
    // The environment (frames using the old one must be complete); null: none.
    void set_environment(const EnvironmentImage* image, const EnvironmentOptions& env_options);
    // When SceneSetup::hidden_nodes, joined by the nodes KHR_node_visibility hides (as
    // loaded or animated), differs from the mask applied last: that mask applied
    // (subtree rule) as a flag per GPU instance; nullopt when unchanged or no scene.
    std::optional<std::vector<std::uint8_t>> take_visibility_change();
    // The applied mask, subtree-expanded, per node (what the TLAS leaves out), and per
    // GPU instance (for the culling pass).
    const std::vector<bool>& hidden_nodes() const { return hidden_nodes_; }
    std::vector<std::uint8_t> hidden_instances() const;
    // KHR_animation_pointer (renderer_animated.cpp): a frame's animated property values
    // into the lights, cameras and node visibility; when they differ from the values
    // applied last and change materials now or did before, the materials to upload
    // (GpuMaterials::update() through update_scene_materials()); nullopt otherwise. A
    // file that animates no property keeps no copies and costs one comparison.
    std::optional<std::vector<scene::MaterialInstance>>
    animate(const std::vector<scene::AnimatedProperty>& values);

    gpu::Context& context;
    gpu::ResourceManager& resources;
    const RendererOptions options;
    SceneSetup setup; // of the scene loaded (hidden nodes as set_hidden_nodes() left them)
    gpu::BindlessTable bindless;
    std::unique_ptr<GpuScene> gpu; // null: nothing loaded
    // With RendererOptions::ray_tracing: the scene's BLAS/TLAS.
    std::unique_ptr<SceneAccelerationStructures> acceleration;
    // The pose the acceleration structures hold (FrameSlot::pose_key, of this load), and
    // whether their TLAS holds the applied visibility.
    std::uint64_t rt_pose_key = 0, rt_pose_generation = 0;
    bool tlas_visibility = true;
    SceneLights lights;
    // The emissive triangles the path tracer samples as lights (ray tracing only).
    EmissiveLights emissive;
    double emissive_ms = 0.0;     // CPU time the list took at load
    std::uint64_t generation = 0; // counts loads and unloads
    std::uint64_t visibility_version = 0;
    // Counts material uploads after the load (animated materials): the path tracer's
    // accumulation starts over.
    std::uint64_t material_generation = 0;
    // KHR_materials_variants: the loaded scene's mappings and the variant both renderers
    // draw now (SceneChanges::set_variant()).
    scene::MaterialVariants variants;
    std::int32_t variant = -1;
    // The split-sum table every environment reads (made with the first, freed with the
    // last); before `environment`, which reads it.
    std::unique_ptr<BrdfLut> brdf_lut;
    std::unique_ptr<EnvironmentMap> environment; // null: none (set_environment)
    // KHR_materials_anisotropy's table: only while an environment and a scene with an
    // anisotropic material are both loaded (update_anisotropic_lut).
    std::unique_ptr<BrdfLut> anisotropic_lut;
    // The path tracer's sampling of the environment (ray tracing only).
    std::unique_ptr<EnvironmentDistribution> environment_sampling;
    std::uint64_t environment_generation = 0; // counts set_environment()

private:
    void load_animated(const scene::Scene& source);
    // Makes or frees anisotropic_lut as the scene and the environment ask; a change
    // counts as a new environment (the frame sets bind it again).
    void update_anisotropic_lut();

    // KHR_animation_pointer: the loaded values (copies only for a file that animates
    // properties), the values applied last, the nodes they hide (KHR_node_visibility's
    // loaded values before any animation), whether the last values changed materials.
    std::vector<scene::MaterialInstance> base_materials_;
    std::vector<scene::Light> base_lights_;
    std::vector<scene::Camera> base_cameras_;
    std::vector<bool> base_visible_; // per node
    std::vector<scene::AnimatedProperty> animated_;
    std::vector<bool> animated_hidden_;
    bool materials_animated_ = false;
    // Visibility: the loaded scene's nodes (the subtree rule), the node of each GPU
    // instance, the mask last applied (as given) and its subtree-expanded form.
    std::vector<scene::Node> nodes_;
    std::vector<std::uint32_t> instance_node_;
    std::vector<bool> hidden_given_, hidden_nodes_;
};

// How the classes that record frames (FrameRecorder and its FrameSlots, SceneChanges,
// RayTracedFrames, PathTracer) read the SceneState: the state, its device, resources and bindless
// table, and the loaded scene's parts as the state holds them (null: none loaded).
struct SceneStateRefs {
    explicit SceneStateRefs(SceneState& s)
        : state(s), context(s.context), resources(&s.resources), bindless(&s.bindless),
          scene(s.gpu), acceleration(s.acceleration), environment(s.environment) {}
    SceneState& state;
    gpu::Context& context;
    gpu::ResourceManager* const resources;
    gpu::BindlessTable* const bindless;
    const std::unique_ptr<GpuScene>& scene;
    const std::unique_ptr<SceneAccelerationStructures>& acceleration;
    const std::unique_ptr<EnvironmentMap>& environment;
};

} // namespace sherpa::render
