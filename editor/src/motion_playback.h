#pragma once
// The timeline's state without widgets: a clock over one animation's range (play,
// speed, loop), the animation's key times, and the Pose the viewport draws (the
// engine's evaluate_pose() with the editor's morph weight overrides applied).
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
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
    // Puts the time at `seconds`, clamped to the range; a non-finite time is ignored.
    void scrub(double seconds);
    // Plays or pauses; playing again after a non-looping run stopped on the last key
    // starts from the first.
    void play(bool play);
};

// Every key time of every sampler of `animation`, sorted, without repeats.
std::vector<double> key_times(const scene::Animation& animation);

// Per glTF mesh, the morph weights that replace what the animation or the file says,
// for every node that shows the mesh.
using MorphOverrides = std::map<std::uint32_t, std::vector<float>>;

// The pose to draw: `animation` (-1: none, the file's default pose) at `time`, morph
// weights overridden. Null when there is nothing to pose (no animation, no override),
// so the renderer draws the scene as loaded.
std::shared_ptr<const scene::Pose> make_pose(const scene::Scene& scene, std::int32_t animation,
                                             double time, const MorphOverrides& overrides);

// One animation of a scene on a clock and the Pose it makes with the morph weight
// overrides: the timeline's state, its widgets aside. The pose is made again only
// when what it is made from changed (a new one has the viewport rewrite and redraw it).
class Playback {
public:
    // Another scene (null: none): no animation, no pose made yet. Held while played.
    void setScene(std::shared_ptr<const scene::Scene> scene);
    // -1: none. Puts the clock on the animation's key range, at its start, paused.
    void selectAnimation(int animation);
    int animation() const { return animation_; }
    // An animation with a non-empty key range: what play and the slider act on.
    bool playable() const { return animation_ >= 0 && clock_.duration() > 0.0; }
    PlaybackClock& clock() { return clock_; }
    const PlaybackClock& clock() const { return clock_; }
    // The animation's key times as fractions of its range (the slider's ticks).
    std::vector<double> keyFractions() const;
    // Makes the pose of the animation at the clock's time with `overrides`, unless it
    // was made from these already. Returns whether it made one.
    bool updatePose(const MorphOverrides& overrides);
    // The pose to draw now; null: the scene as loaded (no animation, no override).
    std::shared_ptr<const scene::Pose> pose() const { return pose_; }

private:
    // What pose_ was made from.
    struct PoseInputs {
        int animation = -1;
        double time = 0.0;
        MorphOverrides overrides;
        bool operator==(const PoseInputs&) const = default;
    };

    std::shared_ptr<const scene::Scene> scene_;
    int animation_ = -1;
    PlaybackClock clock_;
    std::shared_ptr<const scene::Pose> pose_;
    std::optional<PoseInputs> pose_inputs_; // none: make it
};

// Whether `node` is a joint of any skin of `scene`.
bool is_joint(const scene::Scene& scene, std::uint32_t node);

} // namespace sherpa::editor
