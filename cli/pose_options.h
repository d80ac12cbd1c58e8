#pragma once
// The pose options `render` and `cull` share: --animation N --time T, --pose bind.
#include "cli_common.h"
#include "texture_cli.h" // OptionMatch

#include <cstdint>
#include <memory>
#include <string>

#include <sherpa/scene/animation.h>

namespace sherpa::cli {

struct PoseOptions {
    std::int32_t animation = -1; // -1: the first animation (when --time is given)
    double time = 0.0;
    bool timed = false; // --time given
    bool bind = false;  // --pose bind
};

// If args[i] is a pose option, consumes it and its value (advancing i) into `out`;
// Bad sets `error`.
OptionMatch parse_pose_option(Args args, std::size_t& i, PoseOptions& out, std::string& error);

// Checks the options against each other and the scene, and gives the animation to
// evaluate: -1 for --pose bind and for --time on a file without animations (its
// default weights), else --animation N (default: the first). False with `error` when
// they do not fit.
bool pose_animation(const scene::Scene& scene, const PoseOptions& options, std::int32_t& animation,
                    std::string& error);

// The pose the options ask for: null without any (the scene as loaded); the file's
// default pose for --pose bind; else animation N (default: the first; none: the
// default weights) at time T, clamped to its keys. Empty `error` unless the options
// do not fit the scene (then null). Nodes whose posed bounds overflow the float range
// are warned about on stderr.
std::shared_ptr<const scene::Pose> resolve_pose(const scene::Scene& scene,
                                                const PoseOptions& options, std::string& error);

// The warning `render` and `cull` print when the file has animations and no pose was
// asked for (they then draw the default pose); empty when a pose was asked for or the
// file has none. The editor has a timeline and says nothing of the kind.
std::string default_pose_warning(const scene::Scene& scene, const PoseOptions& options);

} // namespace sherpa::cli
