#pragma once
// The skeleton overlay's geometry: every skin's joints as small crosses and its bones
// (joint to the nearest ancestor that is a joint of the same skin) as lines, in world
// space from one pose's world matrices. Pure: no Vulkan, testable on the CPU.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/render/gpu_structs.h>
#include <sherpa/scene/scene.h>

namespace sherpa::render {

inline const glm::vec4 kBoneColor{0.92f, 0.92f, 0.92f, 1.0f}; // light grey
inline const glm::vec4 kJointColor{0.1f, 0.85f, 1.0f, 1.0f};  // cyan
// The selected joint, its cross twice as large and its bone, use kHighlightDetailColor.

// Appends the line list. `world` holds one matrix per node (Pose::world or
// Scene::node_world); joints outside it, and non-finite positions, are skipped.
// `joint_size`: half the length of a joint cross's arms (world units).
void append_skeleton(std::vector<GPULineVertex>& out, std::span<const scene::Skin> skins,
                     std::span<const scene::Node> nodes, std::span<const glm::mat4> world,
                     std::optional<std::uint32_t> selected_joint, float joint_size);

} // namespace sherpa::render
