#pragma once
// Internal: the importer stages for skins, morph targets and animations.
#include <cstdint>
#include <string>
#include <vector>

#include <sherpa/scene/scene.h>

namespace tinygltf {
struct Primitive;
}

namespace sherpa::scene::detail {

struct ImportContext;

// JOINTS_n/WEIGHTS_n and morph targets of one triangle primitive whose POSITION is
// `positions`; appends a Scene::motions entry and returns its index, or -1 when the
// primitive neither skins nor morphs (nothing is stored then).
std::int32_t import_primitive_motion(ImportContext& ctx, const tinygltf::Primitive& prim,
                                     const std::string& where, const std::vector<float>& positions,
                                     PrimitiveInfo& info);
// Skins (after the nodes): joints, inverse bind matrices, skeleton; checks that every
// skinned node's primitives index only its skin's joints.
void import_skins(ImportContext& ctx);
// Mesh and node default morph weights (after the nodes).
void import_default_weights(ImportContext& ctx);
// Animations (after skins and weights): samplers and channels, validated.
void import_animations(ImportContext& ctx);
// The per-joint (or whole-primitive) boxes culling uses while the primitive moves.
void compute_influence_boxes(PrimitiveMotion& m);

} // namespace sherpa::scene::detail
