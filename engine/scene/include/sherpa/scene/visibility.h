#pragma once
// Node visibility: one rule for every consumer (renderer, ray tracer, editor picking).
// A node hidden hides its whole subtree.
#include <span>
#include <vector>

#include <sherpa/scene/scene.h>

namespace sherpa::scene {

// Per node of `nodes`: true when the node or one of its ancestors is set in `hidden`
// (indexed by node; shorter than `nodes` or empty: the rest shown). A parent index out
// of range or a parent cycle ends the walk (hostile files never hang it).
std::vector<bool> hidden_subtrees(std::span<const Node> nodes, const std::vector<bool>& hidden);

} // namespace sherpa::scene
