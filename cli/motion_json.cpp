// `info` output for skins, morph targets and animations, and the posed bounds of
// `info --time T [--animation N]`.
#include "motion_json.h"

#include "scene_json.h"

#include <cstdio>
#include <map>

namespace sherpa::cli {

using nlohmann::json;

namespace {

// Property i's pointer as the file writes it: its channel's own (evaluate_pose() gives
// one property per pointer channel, in order). pointer_of() names a camera's znear and
// zfar as the perspective ones, also on an orthographic camera.
std::string property_pointer(const scene::Scene& scene, const PosedReport& r, std::size_t i) {
    if (r.animation >= 0 && std::size_t(r.animation) < scene.animations.size()) {
        const auto& pointers = scene.animations[std::size_t(r.animation)].pointers;
        if (i < pointers.size()) return pointers[i].pointer;
    }
    return scene::pointer_of(r.properties[i].target);
}

} // namespace

json skins_json(const scene::Scene& scene) {
    json out = json::array();
    for (const scene::Skin& s : scene.skins)
        out.push_back({{"name", s.name},
                       {"joints", s.joints},
                       {"skeleton", s.skeleton >= 0 ? json(s.skeleton) : json(nullptr)}});
    return out;
}

json animations_json(const scene::Scene& scene) {
    json out = json::array();
    for (const scene::Animation& a : scene.animations) {
        std::map<std::string, int> paths, interpolations;
        std::size_t keyframes = 0;
        for (const auto& c : a.channels) ++paths[std::string(to_string(c.path))];
        for (const auto& s : a.samplers) {
            ++interpolations[std::string(to_string(s.interpolation))];
            keyframes += s.times.size();
        }
        json pointers = json::array();
        for (const scene::PointerChannel& p : a.pointers) pointers.push_back(p.pointer);
        out.push_back({{"name", a.name},
                       {"pointer_channels", pointers},
                       {"start", a.start},
                       {"duration", a.end},
                       {"channels", a.channels.size()},
                       {"channels_by_path", paths},
                       {"samplers", a.samplers.size()},
                       {"samplers_by_interpolation", interpolations},
                       {"keyframes", keyframes}});
    }
    return out;
}

json morph_targets_json(const scene::Scene& scene, const scene::PrimitiveInfo& p) {
    json attributes = json::array();
    if (p.motion >= 0)
        attributes = scene.motions[static_cast<std::size_t>(p.motion)].target_attributes;
    return {{"count", p.morph_targets},
            {"attributes", attributes},
            {"default_weights", scene.mesh_weights[p.mesh]}};
}

PosedReport pose_report(const scene::Scene& scene, std::int32_t animation, double time) {
    PosedReport r;
    r.animation = animation;
    r.time = time;
    const scene::Pose pose = scene::evaluate_pose(scene, animation, time);
    r.bounds = scene::posed_scene_bounds(scene, pose);
    r.properties = pose.properties;
    return r;
}

json posed_json(const scene::Scene& scene, const PosedReport& r) {
    const bool contains =
        !r.bounds.exact.valid() ||
        (r.bounds.culling.valid() &&
         glm::all(glm::lessThanEqual(r.bounds.culling.min, r.bounds.exact.min)) &&
         glm::all(glm::greaterThanEqual(r.bounds.culling.max, r.bounds.exact.max)));
    json pose = {
        {"animation", r.animation >= 0 ? json(r.animation) : json(nullptr)},
        {"animation_name", r.animation >= 0
                               ? json(scene.animations[static_cast<std::size_t>(r.animation)].name)
                               : json(nullptr)},
        {"time", r.time},
        {"culling_contains_posed", contains}};
    json warnings = json::array();
    for (std::uint32_t n : r.bounds.overflow)
        warnings.push_back(scene::posed_overflow_warning(scene, n));
    pose["warnings"] = warnings;
    json properties = json::array();
    for (std::size_t i = 0; i < r.properties.size(); ++i) {
        const scene::AnimatedProperty& p = r.properties[i];
        properties.push_back(
            {{"pointer", property_pointer(scene, r, i)},
             {"property", to_string(p.target.property)},
             {"value",
              std::vector<float>(p.value, p.value + scene::pointer_width(p.target.property))}});
    }
    return {{"pose", pose},
            {"animated_properties", properties},
            {"posed_bounds", aabb_json(r.bounds.exact)},
            {"culling_bounds", aabb_json(r.bounds.culling)},
            {"posed_bounds_overflow", r.bounds.overflow}};
}

void print_motion_text(const scene::Scene& scene) {
    for (std::size_t i = 0; i < scene.skins.size(); ++i) {
        const scene::Skin& s = scene.skins[i];
        std::printf("  skin %zu \"%s\": %zu joints, skeleton %d\n", i, s.name.c_str(),
                    s.joints.size(), s.skeleton);
    }
    for (std::size_t i = 0; i < scene.animations.size(); ++i) {
        const scene::Animation& a = scene.animations[i];
        std::size_t keys = 0;
        for (const auto& s : a.samplers) keys += s.times.size();
        std::printf("  animation %zu \"%s\": %.3f s, %zu channels, %zu samplers, %zu keyframes\n",
                    i, a.name.c_str(), a.end, a.channels.size(), a.samplers.size(), keys);
    }
    for (const auto& p : scene.primitives)
        if (p.morph_targets)
            std::printf("  mesh %u primitive %u: %u morph targets\n", p.mesh, p.primitive,
                        p.morph_targets);
}

void print_posed_text(const scene::Scene& scene, const PosedReport& r) {
    const core::Aabb& e = r.bounds.exact;
    const core::Aabb& c = r.bounds.culling;
    std::printf("  pose: animation %d at t = %g s\n", r.animation, r.time);
    if (e.valid())
        std::printf("  posed bounds [%g %g %g] .. [%g %g %g]\n", e.min.x, e.min.y, e.min.z, e.max.x,
                    e.max.y, e.max.z);
    if (c.valid())
        std::printf("  culling bounds [%g %g %g] .. [%g %g %g]\n", c.min.x, c.min.y, c.min.z,
                    c.max.x, c.max.y, c.max.z);
    for (std::uint32_t n : r.bounds.overflow)
        std::printf("  warning: %s\n", scene::posed_overflow_warning(scene, n).c_str());
    for (std::size_t i = 0; i < r.properties.size(); ++i) {
        const scene::AnimatedProperty& p = r.properties[i];
        std::printf("  animated %s =", property_pointer(scene, r, i).c_str());
        for (std::uint32_t k = 0; k < scene::pointer_width(p.target.property); ++k)
            std::printf(" %g", p.value[k]);
        std::printf("\n");
    }
}

} // namespace sherpa::cli
