#pragma once
// `info` output for skins, animations and morph targets, and `info --time`'s pose.
#include <nlohmann/json.hpp>

#include <sherpa/scene/animation.h>
#include <sherpa/scene/scene.h>

namespace sherpa::cli {

nlohmann::json skins_json(const scene::Scene& scene);
nlohmann::json animations_json(const scene::Scene& scene);
// `morph_targets` of one primitive: count, attributes, the mesh's default weights.
nlohmann::json morph_targets_json(const scene::Scene& scene, const scene::PrimitiveInfo& p);

struct PosedReport {
    std::int32_t animation = -1; // -1: no animation, the default weights
    double time = 0.0;
    scene::PosedBounds bounds;
    std::vector<scene::AnimatedProperty> properties; // KHR_animation_pointer values at `time`
};
PosedReport pose_report(const scene::Scene& scene, std::int32_t animation, double time);
// {"pose": {animation, animation_name, time, culling_contains_posed, warnings},
// "posed_bounds", "culling_bounds", "posed_bounds_overflow" (node ids left out of both
// bounds because their posed positions leave the float range)}: merged into the top
// level of `info --json`.
nlohmann::json posed_json(const scene::Scene& scene, const PosedReport& r);

void print_motion_text(const scene::Scene& scene);
void print_posed_text(const scene::Scene& scene, const PosedReport& r);

} // namespace sherpa::cli
