// Keyframe sampling and node/joint/weight evaluation (glTF 2.0 spec, Appendix C).
#include <sherpa/scene/animation.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sherpa::scene {
namespace {

glm::quat normalised(glm::quat q) {
    const float len = glm::length(q);
    return len > 0.0f && std::isfinite(len) ? q / len : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
}

// Shortest-arc slerp; nearly parallel keys fall back to normalised lerp (sin ~ 0).
glm::quat slerp(glm::quat a, glm::quat b, float u) {
    float d = glm::dot(a, b);
    if (d < 0.0f) {
        b = -b;
        d = -d;
    }
    if (d > 0.9995f) return normalised(a * (1.0f - u) + b * u);
    const float theta = std::acos(std::min(d, 1.0f));
    const float s = std::sin(theta);
    return normalised(a * (std::sin((1.0f - u) * theta) / s) + b * (std::sin(u * theta) / s));
}

// glTF stores quaternions as x, y, z, w; glm's constructor takes w first.
glm::quat quat_at(const float* v) {
    return glm::quat(v[3], v[0], v[1], v[2]);
}

// T * R * S composed directly (the rotation's columns scaled), not as three matrix
// products: this is the inner loop of evaluation.
glm::mat4 trs(const glm::vec3& t, const glm::quat& r, const glm::vec3& s) {
    const glm::mat3 m = glm::mat3_cast(r);
    return glm::mat4(glm::vec4(m[0] * s.x, 0.0f), glm::vec4(m[1] * s.y, 0.0f),
                     glm::vec4(m[2] * s.z, 0.0f), glm::vec4(t, 1.0f));
}

} // namespace

void sample_animation(const AnimationSampler& s, AnimationPath path, double time, float* out) {
    const std::uint32_t w = s.width;
    const bool cubic = s.interpolation == Interpolation::CubicSpline;
    const std::size_t n = s.times.size();
    // Value of key k (the middle element of a cubic key's in-tangent/value/out-tangent).
    auto value = [&](std::size_t k) { return &s.values[(cubic ? 3 * k + 1 : k) * w]; };
    auto finish = [&] {
        if (path != AnimationPath::Rotation) return;
        const glm::quat q = normalised(quat_at(out));
        out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
    };
    const double t = std::isnan(time) ? s.times.front() : time;
    if (n == 1 || t <= s.times.front() || t >= s.times.back()) {
        const float* v = value(n == 1 || t <= s.times.front() ? 0 : n - 1);
        std::copy(v, v + w, out);
        return finish();
    }
    // Key k with times[k] <= t < times[k + 1]. The search is in float: a double time just
    // below the last key can round onto it (upper_bound then returns end), so k stops at
    // the last interval (u comes out ~1 there).
    const auto it = std::upper_bound(s.times.begin(), s.times.end(), static_cast<float>(t));
    const std::size_t k = std::min(static_cast<std::size_t>(it - s.times.begin()), n - 1) - 1;
    const double t0 = s.times[k], t1 = s.times[k + 1], dt = t1 - t0;
    const float u = static_cast<float>(std::clamp((t - t0) / dt, 0.0, 1.0));
    const float *a = value(k), *b = value(k + 1);
    switch (s.interpolation) {
    case Interpolation::Step:
        std::copy(a, a + w, out);
        break;
    case Interpolation::Linear:
        if (path == AnimationPath::Rotation) {
            const glm::quat q = slerp(normalised(quat_at(a)), normalised(quat_at(b)), u);
            out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
        } else {
            for (std::uint32_t c = 0; c < w; ++c) out[c] = a[c] + (b[c] - a[c]) * u;
        }
        break;
    case Interpolation::CubicSpline: {
        const float* out_tangent = &s.values[(3 * k + 2) * w];
        const float* in_tangent = &s.values[(3 * (k + 1)) * w];
        const float u2 = u * u, u3 = u2 * u, d = static_cast<float>(dt);
        const float h00 = 2 * u3 - 3 * u2 + 1, h10 = (u3 - 2 * u2 + u) * d;
        const float h01 = -2 * u3 + 3 * u2, h11 = (u3 - u2) * d;
        for (std::uint32_t c = 0; c < w; ++c)
            out[c] = h00 * a[c] + h10 * out_tangent[c] + h01 * b[c] + h11 * in_tangent[c];
        break;
    }
    }
    finish();
}

Pose evaluate_pose(const Scene& scene, std::int32_t animation, double time) {
    const std::size_t n = scene.nodes.size();
    Pose pose;
    pose.translation.resize(n);
    pose.rotation.resize(n);
    pose.scale.resize(n);
    pose.weights.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Node& node = scene.nodes[i];
        pose.translation[i] = node.translation;
        pose.rotation[i] = node.rotation;
        pose.scale[i] = node.scale;
        pose.weights[i] = node.weights;
    }
    if (animation >= 0) {
        const Animation& anim = scene.animations[static_cast<std::size_t>(animation)];
        float v[4];
        for (const AnimationChannel& ch : anim.channels) {
            const AnimationSampler& s = anim.samplers[ch.sampler];
            switch (ch.path) {
            case AnimationPath::Translation:
                sample_animation(s, ch.path, time, v);
                pose.translation[ch.node] = {v[0], v[1], v[2]};
                break;
            case AnimationPath::Rotation:
                sample_animation(s, ch.path, time, v);
                pose.rotation[ch.node] = quat_at(v);
                break;
            case AnimationPath::Scale:
                sample_animation(s, ch.path, time, v);
                pose.scale[ch.node] = {v[0], v[1], v[2]};
                break;
            case AnimationPath::Weights:
                pose.weights[ch.node].resize(s.width);
                sample_animation(s, ch.path, time, pose.weights[ch.node].data());
                break;
            }
        }
    }
    pose.local.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        pose.local[i] = scene.nodes[i].has_matrix
                            ? scene.nodes[i].matrix
                            : trs(pose.translation[i], pose.rotation[i], pose.scale[i]);
    // Parents before children: walk each root's tree (the importer refused cycles).
    pose.world.assign(n, glm::mat4(1.0f));
    std::vector<std::uint32_t> stack;
    for (std::size_t i = 0; i < n; ++i) {
        if (scene.nodes[i].parent >= 0) continue;
        pose.world[i] = pose.local[i];
        stack.push_back(static_cast<std::uint32_t>(i));
        while (!stack.empty()) {
            const std::uint32_t p = stack.back();
            stack.pop_back();
            for (std::uint32_t c : scene.nodes[p].children) {
                pose.world[c] = pose.world[p] * pose.local[c];
                stack.push_back(c);
            }
        }
    }
    pose.joint_matrices.resize(scene.skins.size());
    for (std::size_t s = 0; s < scene.skins.size(); ++s) {
        const Skin& skin = scene.skins[s];
        auto& out = pose.joint_matrices[s];
        out.resize(skin.joints.size());
        for (std::size_t j = 0; j < skin.joints.size(); ++j)
            out[j] = pose.world[skin.joints[j]] * skin.inverse_bind[j];
    }
    pose.properties = evaluate_pointer_channels(scene, animation, time);
    return pose;
}

} // namespace sherpa::scene

namespace sherpa::scene {

std::string_view to_string(Interpolation i) {
    switch (i) {
    case Interpolation::Step:
        return "STEP";
    case Interpolation::Linear:
        return "LINEAR";
    case Interpolation::CubicSpline:
        return "CUBICSPLINE";
    }
    return "?";
}

std::string_view to_string(AnimationPath p) {
    switch (p) {
    case AnimationPath::Translation:
        return "translation";
    case AnimationPath::Rotation:
        return "rotation";
    case AnimationPath::Scale:
        return "scale";
    case AnimationPath::Weights:
        return "weights";
    }
    return "?";
}

} // namespace sherpa::scene
