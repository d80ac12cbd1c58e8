#include "pose_options.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace sherpa::cli {

OptionMatch parse_pose_option(Args args, std::size_t& i, PoseOptions& out, std::string& error) {
    const std::string_view a = args[i];
    if (a != "--animation" && a != "--time" && a != "--pose") return OptionMatch::NotMine;
    if (i + 1 >= args.size()) {
        error = std::string(a) + " needs a value";
        return OptionMatch::Bad;
    }
    const std::string_view v = args[++i];
    if (a == "--pose") {
        if (v != "bind") {
            error = "--pose takes only 'bind' (the file's default pose)";
            return OptionMatch::Bad;
        }
        out.bind = true;
    } else if (a == "--animation") {
        if (!parse_index(v, out.animation)) {
            error = "--animation needs a non-negative integer";
            return OptionMatch::Bad;
        }
    } else {
        // std::from_chars for double accepts "nan" and "inf": a time must be finite.
        if (!parse_number(v, out.time) || !std::isfinite(out.time)) {
            error = "--time needs a finite number of seconds";
            return OptionMatch::Bad;
        }
        out.timed = true;
    }
    return OptionMatch::Taken;
}

bool pose_animation(const scene::Scene& scene, const PoseOptions& options, std::int32_t& animation,
                    std::string& error) {
    error.clear();
    if (options.bind && (options.timed || options.animation >= 0)) {
        error = "--pose bind takes no --animation or --time";
        return false;
    }
    if (options.animation >= 0 && !options.timed) {
        error = "--animation needs --time T";
        return false;
    }
    if (options.animation >= static_cast<std::int32_t>(scene.animations.size())) {
        error = scene.source + ": --animation " + std::to_string(options.animation) +
                " out of range (the file has " + std::to_string(scene.animations.size()) + ")";
        return false;
    }
    animation = options.animation;
    if (options.timed && animation < 0 && !scene.animations.empty()) animation = 0;
    return true;
}

std::shared_ptr<const scene::Pose> resolve_pose(const scene::Scene& scene,
                                                const PoseOptions& options, std::string& error) {
    std::int32_t animation = -1;
    if (!pose_animation(scene, options, animation, error) || !(options.bind || options.timed))
        return nullptr;
    auto pose =
        std::make_shared<const scene::Pose>(scene::evaluate_pose(scene, animation, options.time));
    // Drawn and culled anyway (an unbounded instance is never culled), but said.
    for (std::uint32_t node : scene::posed_overflow_nodes(scene, *pose))
        std::fprintf(stderr, "warning: %s: %s\n", scene.source.c_str(),
                     scene::posed_overflow_warning(scene, node).c_str());
    return pose;
}

std::string default_pose_warning(const scene::Scene& scene, const PoseOptions& options) {
    if (options.timed || options.bind || scene.animations.empty()) return {};
    std::string names;
    for (std::size_t i = 0; i < scene.animations.size() && i < 5; ++i)
        names += (i ? ", " : "") + (scene.animations[i].name.empty()
                                        ? "animations[" + std::to_string(i) + "]"
                                        : "\"" + scene.animations[i].name + "\"");
    if (scene.animations.size() > 5) names += ", ...";
    return std::to_string(scene.animations.size()) + " animation(s) (" + names +
           "): `render` and `cull` draw the default pose unless given `--animation N --time T`";
}

} // namespace sherpa::cli
