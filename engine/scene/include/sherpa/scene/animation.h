#pragma once
// Animation evaluation and CPU posing: pure functions of (scene, animation, time).
// Nothing here changes the Scene except apply_pose_bounds(); the renderer poses on the GPU
// (FrameRequest::pose).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <sherpa/core/aabb.h>
#include <sherpa/scene/scene.h>

namespace sherpa::scene {

// Every node's transform and morph weights at one time.
struct Pose {
    std::vector<glm::vec3> translation, scale; // per node (TRS nodes; matrix nodes keep theirs)
    std::vector<glm::quat> rotation;           // unit
    std::vector<glm::mat4> local, world;     // per node, every node (not only the displayed scene)
    std::vector<std::vector<float>> weights; // per node: morph weights (empty without targets)
    std::vector<std::vector<glm::mat4>> joint_matrices; // per skin: world(joint) x inverseBind
    // KHR_animation_pointer values at this time (material, light, camera properties,
    // node visibility): apply_animated_properties() writes them where they belong.
    std::vector<AnimatedProperty> properties;
};

// Samples `s` at `time` into `out` (s.width floats). Times outside the keys clamp to
// the first/last key; STEP holds the key at or before `time`; LINEAR slerps rotations
// (shortest arc) and lerps the rest; CUBICSPLINE evaluates glTF's Hermite spline with
// tangents scaled by the key interval. Rotations come out normalised. A NaN time
// evaluates as the first key.
void sample_animation(const AnimationSampler& s, AnimationPath path, double time, float* out);

// The pose of `scene` with animation `animation` (-1: none, the file's default pose) at
// `time` seconds. Precondition: animation < scene.animations.size().
Pose evaluate_pose(const Scene& scene, std::int32_t animation, double time);

// World-space positions of primitive `prim`'s vertices (the file's vertex order) on node
// `node`, morphed by the node's weights and skinned by its skin when both apply; static
// primitives are transformed by the node's world matrix (times `instance`, an
// EXT_mesh_gpu_instancing row's transform). Empty for primitives without an engine mesh.
std::vector<glm::vec3> posed_positions(const Scene& scene, const Pose& pose, std::uint32_t node,
                                       const PrimitiveInfo& prim,
                                       const glm::mat4& instance = glm::mat4(1.0f));

// Conservative world bounds of the same vertices, from the per-joint boxes computed at
// load (PrimitiveMotion::boxes) with the morph delta boxes scaled by the current
// weights: always contains posed_positions, costs O(joints + targets), not O(vertices).
// Not finite where the pose leaves the float range (posed_overflow_nodes()): culling
// then keeps the instance (an invalid box is never culled).
core::Aabb culling_bounds(const Scene& scene, const Pose& pose, std::uint32_t node,
                          const PrimitiveInfo& prim, const glm::mat4& instance = glm::mat4(1.0f));

// Conservative world bounds of every instance (Scene::instances order) in `pose`: its
// primitive's culling_bounds() on its node (and row). What culling uses while things move.
std::vector<core::Aabb> instance_culling_bounds(const Scene& scene, const Pose& pose);

// Moves `scene`'s instances to `pose` for culling: world matrices from the pose and
// world_bounds from instance_culling_bounds() (vertices are not changed).
void apply_pose_bounds(Scene& scene, const Pose& pose);

// `scene` posed on the CPU as a static scene: one mesh per instance in world space,
// positions from posed_positions(), normals morphed and then transformed as the GPU's
// vertex stage does (the blended joint matrix, or the node's normal matrix; not
// renormalised); no skins, morph targets or animations are left. Costs O(vertices).
Scene freeze_pose(const Scene& scene, const Pose& pose);

// Exact and conservative bounds of the displayed scene's instances in `pose`. A finite
// pose can still put positions past the float range (a joint matrix, scale or morph
// weight near 3e38 gives inf, and inf - inf NaN): such an instance is left out of both
// boxes, which stay finite, and its node is listed in `overflow` (once, in displayed
// order). The static path refuses the same at load (world bounds overflow).
struct PosedBounds {
    core::Aabb exact, culling;
    std::vector<std::uint32_t> overflow; // nodes whose posed bounds leave the float range
};
PosedBounds posed_scene_bounds(const Scene& scene, const Pose& pose);

// Nodes of the displayed scene's instances whose conservative posed bounds
// (instance_culling_bounds()) leave the float range, once each in instance order.
// O(joints + targets): cheap enough to run on every pose the editor shows.
std::vector<std::uint32_t> posed_overflow_nodes(const Scene& scene, const Pose& pose);

// The warning for an overflowing node: names it and the cause, says what it costs.
std::string posed_overflow_warning(const Scene& scene, std::uint32_t node);

} // namespace sherpa::scene
