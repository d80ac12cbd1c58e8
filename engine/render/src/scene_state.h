#pragma once
// What a load fixes and the frames only read (private to the render layer): the scene on
// the GPU (GpuScene: streams, instances, materials and textures in the bindless table),
// its acceleration structures and the pose they hold, the node visibility, the lights
// and cameras frames are resolved against, and the environment. Frame slots, targets
// and passes are the FrameRecorder's (frame_recorder.h), which reads this state.
#include "environment_map.h"

#include <sherpa/gpu/bindless.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/camera.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/path_trace.h>
#include <sherpa/render/renderer.h>

#include <optional>

namespace sherpa::gpu {

// What lighting and camera resolution read of the loaded scene (no whole Scene kept).
struct SceneLights {
    SceneCameras cameras; // bounds (the GPU scene's when valid) and the file's cameras
    std::vector<Light> lights;
    std::vector<PlacedLight> placed_lights;
};

class SceneState {
public:
    SceneState(Context& context, ResourceManager& resources, const RendererOptions& options);
    ~SceneState();
    SceneState(const SceneState&) = delete;
    SceneState& operator=(const SceneState&) = delete;

    // `gpu_scene` (made from `source`) becomes the loaded scene, set up as `setup` says;
    // with RendererOptions::ray_tracing its acceleration structures are built here.
    void load(const Scene& source, std::unique_ptr<GpuScene> gpu_scene, const SceneSetup& setup);
    // The scene leaves (frames using it must be complete).
    void unload();
    // The environment (frames using the old one must be complete); null: none.
    void set_environment(const EnvironmentImage* image);
    // When SceneSetup::hidden_nodes differs from the mask applied last: that mask applied
    // (subtree rule) as a flag per GPU instance; nullopt when unchanged or no scene.
    std::optional<std::vector<std::uint8_t>> take_visibility_change();
    // The applied mask, subtree-expanded, per node (what the TLAS leaves out).
    const std::vector<bool>& hidden_nodes() const { return hidden_nodes_; }

    Context& context;
    ResourceManager& resources;
    const RendererOptions options;
    SceneSetup setup; // of the scene loaded (hidden nodes as set_hidden_nodes() left them)
    BindlessTable bindless;
    std::unique_ptr<GpuScene> gpu; // null: nothing loaded
    // With RendererOptions::ray_tracing: the scene's BLAS/TLAS.
    std::unique_ptr<SceneAccelerationStructures> acceleration;
    // The pose the acceleration structures hold (FrameSlot::pose_key, of this load), and
    // whether their TLAS holds the applied visibility.
    std::uint64_t rt_pose_key = 0, rt_pose_generation = 0;
    bool tlas_visibility = true;
    SceneLights lights;
    std::uint64_t generation = 0; // counts loads and unloads
    std::uint64_t visibility_version = 0;
    std::unique_ptr<EnvironmentMap> environment; // null: none (set_environment)
    // The path tracer's sampling of the environment (ray tracing only).
    std::unique_ptr<EnvironmentDistribution> environment_sampling;
    std::uint64_t environment_generation = 0; // counts set_environment()

private:
    // Visibility: the loaded scene's nodes (the subtree rule), the node of each GPU
    // instance, the mask last applied (as given) and its subtree-expanded form.
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> instance_node_;
    std::vector<bool> hidden_given_, hidden_nodes_;
};

} // namespace sherpa::gpu
