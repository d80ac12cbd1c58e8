#pragma once
// Skins, morph targets and animations as the importer keeps them. Per-vertex motion
// data exists only for primitives that have JOINTS_n/WEIGHTS_n or morph targets:
// static scenes carry nothing extra. Indices are the file's (nodes, meshes, skins).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/core/aabb.h>
#include <sherpa/scene/animation_pointer.h>

namespace sherpa::scene {

struct Skin {
    std::string name;
    std::vector<std::uint32_t> joints;   // node indices
    std::vector<glm::mat4> inverse_bind; // one per joint (identity when the file gives none)
    std::int32_t skeleton = -1;          // node index, -1 when the file names none
};

// One morph target's deltas in the file's vertex order; a stream is empty when the
// target does not give that attribute.
struct MorphTarget {
    std::vector<glm::vec3> position, normal, tangent;
};

// Conservative bounds precomputed at load for culling while moving: the box of the
// base positions of the vertices one joint influences (or of all vertices when the
// primitive is not skinned) and, per morph target, the box of those vertices' deltas.
// Posed, a vertex lies in base + sum_k w_k * delta_k, then in the convex hull of its
// joints' transforms of that box.
struct InfluenceBox {
    std::int32_t joint = -1; // index into the skin's joints; -1: not skinned
    core::Aabb base;
    std::vector<core::Aabb> deltas; // per morph target (empty boxes where it moves nothing)
};

// The motion data of one triangle primitive, in the file's vertex order ("source
// vertices": the engine mesh may have split them for flat normals or tangents).
struct PrimitiveMotion {
    std::uint32_t mesh = 0, primitive = 0;      // glTF indices
    std::vector<glm::vec3> base_positions;      // POSITION as authored
    std::uint32_t influences = 0;               // joints per vertex: 4 per JOINTS_n set
    std::vector<std::uint16_t> joints;          // vertex-major, `influences` per vertex
    std::vector<float> weights;                 // normalised (sum 1), same layout
    std::uint32_t max_joint = 0;                // largest joint index used (skin check)
    std::vector<MorphTarget> targets;           //
    std::vector<std::string> target_attributes; // union over targets: POSITION, NORMAL, TANGENT
    std::vector<InfluenceBox> boxes;
    bool skinned() const { return influences > 0; }
};

enum class Interpolation : std::uint8_t { Step, Linear, CubicSpline };
enum class AnimationPath : std::uint8_t { Translation, Rotation, Scale, Weights };
std::string_view to_string(Interpolation i);
std::string_view to_string(AnimationPath p);

// Key times (strictly increasing, finite) and values. `width` floats make one value
// (3 for T/S, 4 for R as x,y,z,w, the morph target count for weights). CUBICSPLINE
// stores (in-tangent, value, out-tangent) per key, as glTF does.
struct AnimationSampler {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
    std::vector<float> values;
    std::uint32_t width = 0;
};

struct AnimationChannel {
    std::uint32_t sampler = 0, node = 0;
    AnimationPath path = AnimationPath::Translation;
    // The file's indices in its animation (channels without a node are skipped, and
    // samplers are kept only where a channel uses them): what JSON pointers name.
    std::uint32_t source = 0, source_sampler = 0;
};

struct Animation {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
    // KHR_animation_pointer channels other than node TRS/weights (those become
    // `channels`): material, light, camera and visibility properties.
    std::vector<PointerChannel> pointers;
    float start = 0.0f, end = 0.0f; // first and last key time over all samplers
};

} // namespace sherpa::scene
