#pragma once
// The timeline's state without widgets: a clock over one animation's range (play,
// speed, loop), the animation's key times, and the Pose the viewport draws (the
// engine's evaluate_pose() with the editor's morph weight overrides applied).
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include <sherpa/scene/animation.h>

namespace sherpa::editor {

struct PlaybackClock {
    double start = 0.0, end = 0.0; // the animation's key range (seconds)
    double time = 0.0;
    double speed = 1.0; // animation seconds per wall-clock second
    bool loop = true;
    bool playing = false;

    double duration() const { return end - start; }
    // Puts the clock on [start, end] of an animation, at its start, paused.
    void reset(double first, double last);
    // Advances by `seconds` of wall clock while playing. Past the end a looping clock
    // wraps to the start (any number of times); otherwise it stops on the last key.
    // Returns whether the time changed.
    bool advance(double seconds);
    // Time as a fraction of the range (0 for an empty range).
    double fraction() const;
};

// Every key time of every sampler of `animation`, sorted, without repeats.
std::vector<double> key_times(const Animation& animation);

// Per glTF mesh, the morph weights that replace what the animation or the file says,
// for every node that shows the mesh.
using MorphOverrides = std::map<std::uint32_t, std::vector<float>>;

// The pose to draw: `animation` (-1: none, the file's default pose) at `time`, morph
// weights overridden. Null when there is nothing to pose (no animation, no override),
// so the renderer draws the scene as loaded.
std::shared_ptr<const Pose> make_pose(const Scene& scene, std::int32_t animation, double time,
                                      const MorphOverrides& overrides);

// Whether `node` is a joint of any skin of `scene`.
bool is_joint(const Scene& scene, std::uint32_t node);

} // namespace sherpa::editor
