// Posed bounds target: the shared motion assets (skins, morph targets, animations),
// imported once, then per case random animations (channels on any node, every path
// and interpolation, 1-6 keys, times from 1e-30 apart to 1e30), inverse bind
// matrices, node transforms and morph weights, with values from everyday magnitudes
// to 3.4e38 (finite: the importer refuses non-finite keys), posed at a random time
// (before, inside or after the keys, or NaN). What runs: evaluate_pose,
// posed_scene_bounds, instance_culling_bounds, posed_overflow_nodes, and now and
// then freeze_pose. Findings besides a crash or UB: posed or culling bounds that
// are not finite, an overflowing node that is not reported, and (for everyday
// values) culling bounds that do not hold the exact posed bounds.
#include "pose_target.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <sherpa/scene/animation.h>
#include <sherpa/scene/culling.h>
#include <sherpa/scene/scene_loader.h>

namespace sherpa::fuzz {

namespace fs = std::filesystem;

namespace {

constexpr const char* kModels[] = {"RiggedSimple", "SimpleMorph", "AnimatedMorphSphere",
                                   "BoxAnimated", "VC"};

// A finite float: everyday magnitudes unless `tame` is cleared by drawing an extreme.
float value(Rng& rng, bool& tame) {
    switch (rng.below(12)) {
    case 0:
        tame = false;
        return (rng.chance(2) ? 1.0f : -1.0f) * std::numeric_limits<float>::max();
    case 1:
        tame = false;
        return (rng.chance(2) ? 3e38f : -3e38f);
    case 2: { // a power of two from 2^-128 to 2^127 (the operands drawn in a fixed order)
        tame = false;
        const float p = float(std::ldexp(1.0, int(rng.below(256)) - 128));
        return rng.chance(2) ? p : -p;
    }
    case 3:
        tame = false;
        return std::numeric_limits<float>::denorm_min() * float(1 + rng.below(1000));
    case 4:
        return 0.0f;
    case 5:
        return -0.0f;
    case 6:
        return 1.0f;
    default: // everyday: -10..10
        return float(std::int64_t(rng.below(20001)) - 10000) / 1000.0f;
    }
}

bool overflows(const core::Aabb& b) {
    return b.valid() && scene::box_is_invalid(b.min, b.max);
}

std::string f2s(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// Strictly increasing finite key times.
std::vector<float> key_times(Rng& rng, std::size_t count, bool& tame) {
    std::vector<float> t;
    float at = rng.chance(4) ? -float(rng.below(100)) : 0.0f;
    for (std::size_t k = 0; k < count; ++k) {
        t.push_back(at);
        float step = 0.05f + float(rng.below(200)) / 100.0f;
        if (rng.chance(16)) step = 1e-30f, tame = false; // below the float spacing: skipped
        if (rng.chance(32)) step = 1e30f, tame = false;
        const float next = at + step;
        at = next > at && std::isfinite(next) ? next : std::nextafter(at, 3e38f);
    }
    while (t.size() > 1 && !(t.back() > t[t.size() - 2] && std::isfinite(t.back()))) t.pop_back();
    return t;
}

} // namespace

bool PoseTarget::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    for (const char* model : kModels) {
        const fs::path file =
            config.assets_dir / "gltf" / model / "glTF" / (std::string(model) + ".gltf");
        scene::LoadResult r = scene::import_gltf(file.string(), scene::LoadOptions{});
        if (!r) {
            error = file.string() + ": " + r.error;
            return false;
        }
        Seed seed{model, *r.scene, *r.scene};
        seeds_.push_back(std::move(seed));
    }
    fs::create_directories(config.work_dir);
    case_path_ = config.work_dir / "__case.txt";
    return true;
}

void PoseTarget::mutate(Rng& rng, scene::Scene& s, std::string& log) {
    const std::size_t nodes = s.nodes.size();
    switch (rng.below(6)) {
    case 0: { // a new animation of random channels
        scene::Animation a;
        a.name = "fuzz";
        const std::size_t channels = 1 + rng.below(6);
        for (std::size_t c = 0; c < channels; ++c) {
            const std::uint32_t node = std::uint32_t(rng.below(nodes));
            const scene::Node& n = s.nodes[node];
            scene::AnimationChannel ch;
            ch.node = node;
            ch.path = scene::AnimationPath(rng.below(4));
            std::uint32_t width = ch.path == scene::AnimationPath::Rotation ? 4 : 3;
            if (ch.path == scene::AnimationPath::Weights) {
                if (n.weights.empty())
                    ch.path = scene::AnimationPath::Translation;
                else
                    width = std::uint32_t(n.weights.size());
            }
            if (n.has_matrix && ch.path != scene::AnimationPath::Weights)
                continue; // refused at import
            scene::AnimationSampler sm;
            sm.interpolation = scene::Interpolation(rng.below(3));
            sm.width = width;
            sm.times = key_times(rng, 1 + rng.below(6), tame_);
            const std::size_t per_key =
                sm.interpolation == scene::Interpolation::CubicSpline ? 3 : 1;
            sm.values.resize(sm.times.size() * per_key * width);
            for (float& v : sm.values) v = value(rng, tame_);
            ch.sampler = std::uint32_t(a.samplers.size());
            a.start = a.samplers.empty() ? sm.times.front() : std::min(a.start, sm.times.front());
            a.end = a.samplers.empty() ? sm.times.back() : std::max(a.end, sm.times.back());
            a.samplers.push_back(std::move(sm));
            a.channels.push_back(ch);
            log += "channel node " + std::to_string(node) + " path " +
                   std::string(to_string(ch.path)) + " " +
                   std::string(to_string(a.samplers.back().interpolation)) + " keys " +
                   std::to_string(a.samplers.back().times.size()) + "\n";
        }
        if (a.samplers.empty()) return;
        s.animations.push_back(std::move(a));
        animation_ = std::int32_t(s.animations.size() - 1);
        return;
    }
    case 1: { // values of an existing sampler
        if (s.animations.empty()) return;
        scene::Animation& a = s.animations[rng.below(s.animations.size())];
        if (a.samplers.empty()) return;
        scene::AnimationSampler& sm = a.samplers[rng.below(a.samplers.size())];
        if (sm.values.empty()) return;
        for (std::size_t k = 0, n = 1 + rng.below(8); k < n; ++k) {
            const std::size_t at = rng.below(sm.values.size());
            sm.values[at] = value(rng, tame_);
            log += "sampler value " + std::to_string(at) + " = " + f2s(sm.values[at]) + "\n";
        }
        return;
    }
    case 2: { // an inverse bind matrix
        if (s.skins.empty()) return;
        scene::Skin& skin = s.skins[rng.below(s.skins.size())];
        if (skin.inverse_bind.empty()) return;
        const std::size_t j = rng.below(skin.inverse_bind.size());
        for (std::size_t k = 0, n = 1 + rng.below(4); k < n; ++k) {
            const std::size_t e = rng.below(16);
            skin.inverse_bind[j][int(e / 4)][int(e % 4)] = value(rng, tame_);
        }
        log += "inverse bind matrix " + std::to_string(j) + "\n";
        return;
    }
    case 3: { // a node's transform
        scene::Node& n = s.nodes[rng.below(nodes)];
        if (n.has_matrix) {
            const std::size_t e = rng.below(16);
            n.matrix[int(e / 4)][int(e % 4)] = value(rng, tame_);
        } else {
            glm::vec3& v = rng.chance(2) ? n.translation : n.scale;
            v[int(rng.below(3))] = value(rng, tame_);
            if (rng.chance(4)) { // any quaternion, unit or not; drawn in a fixed order
                float q[4];
                for (float& c : q) c = value(rng, tame_);
                n.rotation = glm::quat(q[3], q[0], q[1], q[2]);
            }
        }
        log += "node transform\n";
        return;
    }
    default: { // morph weights of a node
        std::vector<std::uint32_t> morphed;
        for (std::uint32_t i = 0; i < nodes; ++i)
            if (!s.nodes[i].weights.empty()) morphed.push_back(i);
        if (morphed.empty()) return;
        scene::Node& n = s.nodes[morphed[rng.below(morphed.size())]];
        for (float& w : n.weights)
            if (rng.chance(2)) w = value(rng, tame_);
        log += "morph weights\n";
        return;
    }
    }
}

fs::path PoseTarget::make_case(Rng& rng) {
    current_ = &seeds_[rng.below(seeds_.size())];
    scene::Scene& s = current_->scene;
    const scene::Scene& o = current_->original;
    s.nodes = o.nodes;
    s.skins = o.skins;
    s.animations = o.animations;
    tame_ = true;
    animation_ =
        s.animations.empty() || rng.chance(8) ? -1 : std::int32_t(rng.below(s.animations.size()));
    std::string log = current_->model + "\n";
    for (std::size_t k = 0, n = 1 + rng.below(4); k < n; ++k) mutate(rng, s, log);
    if (animation_ >= 0) {
        const scene::Animation& a = s.animations[std::size_t(animation_)];
        switch (rng.below(8)) {
        case 0:
            time_ = std::numeric_limits<double>::quiet_NaN();
            break;
        case 1:
            time_ = a.start - 1.0 - double(rng.below(100));
            break;
        case 2:
            time_ = a.end + double(rng.below(100));
            break;
        case 3:
            time_ = rng.chance(2) ? 1e30 : -1e30;
            break;
        default:
            time_ = a.start + (double(a.end) - a.start) * double(rng.below(10001)) / 10000.0;
        }
    } else {
        time_ = 0.0;
    }
    freeze_ = rng.chance(16);
    log += "animation " + std::to_string(animation_) + " time " + f2s(time_) +
           (tame_ ? " tame" : " extreme") + (freeze_ ? " freeze" : "") + "\n";
    write_case_file(case_path_,
                    std::span(reinterpret_cast<const std::uint8_t*>(log.data()), log.size()));
    return config_.work_dir;
}

std::optional<std::string> PoseTarget::run() {
    const scene::Scene& s = current_->scene;
    const scene::Pose pose = scene::evaluate_pose(s, animation_, time_);
    const scene::PosedBounds b = scene::posed_scene_bounds(s, pose);
    if (overflows(b.exact) || overflows(b.culling))
        return "posed_scene_bounds returned bounds that are not finite";
    const std::vector<std::uint32_t> overflow = scene::posed_overflow_nodes(s, pose);
    const std::vector<core::Aabb> boxes = scene::instance_culling_bounds(s, pose);
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (overflows(boxes[i]) &&
            std::find(overflow.begin(), overflow.end(), s.instances[i].node_id) == overflow.end())
            return "instance " + std::to_string(i) + ": culling bounds overflow, node not reported";
    if (tame_ && b.exact.valid()) {
        // The conservative box holds the exact one, up to float rounding of both.
        const glm::vec3 mag = glm::max(glm::max(glm::abs(b.exact.min), glm::abs(b.exact.max)),
                                       glm::max(glm::abs(b.culling.min), glm::abs(b.culling.max)));
        const float tol = 1e-4f * std::max({mag.x, mag.y, mag.z, 1.0f});
        if (!b.culling.valid() ||
            glm::any(glm::greaterThan(b.culling.min - glm::vec3(tol), b.exact.min)) ||
            glm::any(glm::lessThan(b.culling.max + glm::vec3(tol), b.exact.max)))
            return "culling bounds do not hold the exact posed bounds";
    }
    if (freeze_) {
        const scene::Scene frozen = scene::freeze_pose(s, pose);
        for (std::size_t m = 0; m < frozen.meshes.size(); ++m)
            for (const std::uint32_t index : frozen.meshes[m].indices)
                if (index >= frozen.meshes[m].vertices.size())
                    return "freeze_pose: mesh " + std::to_string(m) + " index out of range";
    }
    return std::nullopt;
}

} // namespace sherpa::fuzz
