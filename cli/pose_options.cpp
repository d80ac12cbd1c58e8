#include "pose_options.h"

#include <charconv>
#include <cmath>

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
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out.animation);
        if (ec != std::errc{} || end != v.data() + v.size() || out.animation < 0) {
            error = "--animation needs a non-negative integer";
            return OptionMatch::Bad;
        }
    } else {
        // std::from_chars for double accepts "nan" and "inf": a time must be finite.
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out.time);
        if (ec != std::errc{} || end != v.data() + v.size() || !std::isfinite(out.time)) {
            error = "--time needs a finite number of seconds";
            return OptionMatch::Bad;
        }
        out.timed = true;
    }
    return OptionMatch::Taken;
}

std::shared_ptr<const Pose> resolve_pose(const Scene& scene, const PoseOptions& options,
                                         std::string& error) {
    error.clear();
    if (options.bind && (options.timed || options.animation >= 0)) {
        error = "--pose bind takes no --animation or --time";
        return nullptr;
    }
    if (options.bind) return std::make_shared<const Pose>(evaluate_pose(scene, -1, 0.0));
    if (options.animation >= 0 && !options.timed) {
        error = "--animation needs --time T";
        return nullptr;
    }
    if (!options.timed) return nullptr;
    if (options.animation >= static_cast<std::int32_t>(scene.animations.size())) {
        error = scene.source + ": --animation " + std::to_string(options.animation) +
                " out of range (the file has " + std::to_string(scene.animations.size()) + ")";
        return nullptr;
    }
    std::int32_t animation = options.animation;
    if (animation < 0 && !scene.animations.empty()) animation = 0;
    return std::make_shared<const Pose>(evaluate_pose(scene, animation, options.time));
}

} // namespace sherpa::cli
