#include "motion_playback.h"

#include <algorithm>
#include <cmath>

namespace sherpa::editor {

void PlaybackClock::reset(double first, double last) {
    start = first;
    end = std::max(first, last);
    time = start;
    playing = false;
}

bool PlaybackClock::advance(double seconds) {
    if (!playing || !(seconds > 0.0) || !std::isfinite(seconds)) return false;
    const double before = time;
    const double range = duration();
    time += seconds * speed;
    if (time > end || time < start) {
        if (loop && range > 0.0) {
            time = start + std::fmod(time - start, range);
            if (time < start) time += range; // negative speed
        } else {
            time = std::clamp(time, start, end);
            playing = false;
        }
    }
    return time != before;
}

double PlaybackClock::fraction() const {
    return duration() > 0.0 ? (time - start) / duration() : 0.0;
}

void PlaybackClock::scrub(double seconds) {
    if (std::isfinite(seconds)) time = std::clamp(seconds, start, end);
}

void PlaybackClock::play(bool play) {
    if (play && !playing && !loop && time >= end) time = start;
    playing = play;
}

void Playback::setScene(std::shared_ptr<const scene::Scene> scene) {
    scene_ = std::move(scene);
    animation_ = -1;
    clock_.reset(0.0, 0.0);
    pose_inputs_.reset();
}

void Playback::selectAnimation(int animation) {
    animation_ = scene_ && animation >= 0 && animation < static_cast<int>(scene_->animations.size())
                     ? animation
                     : -1;
    if (animation_ >= 0) {
        const scene::Animation& anim = scene_->animations[static_cast<std::size_t>(animation_)];
        clock_.reset(anim.start, anim.end);
    } else {
        clock_.reset(0.0, 0.0);
    }
}

std::vector<double> Playback::keyFractions() const {
    std::vector<double> out;
    if (animation_ < 0) return out;
    const scene::Animation& anim = scene_->animations[static_cast<std::size_t>(animation_)];
    for (const double t : key_times(anim))
        out.push_back(anim.end > anim.start ? (t - anim.start) / (anim.end - anim.start) : 0.0);
    return out;
}

bool Playback::updatePose(const MorphOverrides& overrides) {
    PoseInputs inputs{animation_, clock_.time, overrides};
    if (inputs == pose_inputs_) return false;
    pose_ = scene_ ? make_pose(*scene_, inputs.animation, inputs.time, inputs.overrides) : nullptr;
    pose_inputs_ = std::move(inputs);
    return true;
}

std::vector<double> key_times(const scene::Animation& animation) {
    std::vector<double> out;
    for (const scene::AnimationSampler& s : animation.samplers)
        out.insert(out.end(), s.times.begin(), s.times.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::shared_ptr<const scene::Pose> make_pose(const scene::Scene& scene, std::int32_t animation,
                                             double time, const MorphOverrides& overrides) {
    if (animation >= static_cast<std::int32_t>(scene.animations.size())) animation = -1;
    if (animation < 0 && overrides.empty()) return nullptr;
    auto pose = std::make_shared<scene::Pose>(scene::evaluate_pose(scene, animation, time));
    for (std::size_t n = 0; n < scene.nodes.size() && n < pose->weights.size(); ++n) {
        const scene::Node& node = scene.nodes[n];
        if (node.mesh < 0) continue;
        const auto it = overrides.find(static_cast<std::uint32_t>(node.mesh));
        if (it == overrides.end()) continue;
        std::vector<float>& w = pose->weights[n];
        for (std::size_t k = 0; k < w.size() && k < it->second.size(); ++k) w[k] = it->second[k];
    }
    return pose;
}

bool is_joint(const scene::Scene& scene, std::uint32_t node) {
    return std::any_of(scene.skins.begin(), scene.skins.end(), [&](const scene::Skin& s) {
        return std::find(s.joints.begin(), s.joints.end(), node) != s.joints.end();
    });
}

} // namespace sherpa::editor
