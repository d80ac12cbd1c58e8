// glTF animations -> sherpa::scene::Animation. Times must be finite and strictly increasing,
// values finite and as many as the times and interpolation require: anything else is an
// ImportError naming the sampler, so evaluation never meets NaN or an unsorted key list.
#include "accessor_reader.h"
#include "import_context.h"
#include "import_error.h"
#include "motion_internal.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

AnimationSampler read_sampler(ImportContext& ctx, const tinygltf::AnimationSampler& src,
                              std::uint32_t width, std::uint32_t components,
                              const std::string& where) {
    AnimationSampler s;
    s.width = width;
    if (src.interpolation == "STEP")
        s.interpolation = Interpolation::Step;
    else if (src.interpolation == "LINEAR" || src.interpolation.empty())
        s.interpolation = Interpolation::Linear;
    else if (src.interpolation == "CUBICSPLINE")
        s.interpolation = Interpolation::CubicSpline;
    else
        fail(where + ".interpolation: \"" + src.interpolation +
             "\" is not STEP, LINEAR or CUBICSPLINE");
    std::uint32_t nc = 0;
    s.times = read_accessor_floats(ctx.model, src.input, {1}, nc, where + ".input");
    if (s.times.empty()) fail(where + ".input: has no keyframes");
    for (std::size_t k = 0; k < s.times.size(); ++k) {
        if (!std::isfinite(s.times[k]))
            fail(where + ".input[" + std::to_string(k) + "] is not finite");
        if (k > 0 && !(s.times[k] > s.times[k - 1]))
            fail(where + ".input: key times are not strictly increasing (key " + std::to_string(k) +
                 " at " + number_text(s.times[k]) + " after " + number_text(s.times[k - 1]) + ")");
    }
    s.values = read_accessor_floats(ctx.model, src.output, {components}, nc, where + ".output");
    const std::size_t per_key =
        std::size_t{width} * (s.interpolation == Interpolation::CubicSpline ? 3 : 1);
    if (s.values.size() != s.times.size() * per_key)
        fail(where + ".output: has " + std::to_string(s.values.size()) + " values; " +
             std::to_string(s.times.size()) + " keys " +
             (s.interpolation == Interpolation::CubicSpline ? "(cubic spline) " : "") + "need " +
             std::to_string(s.times.size() * per_key));
    for (std::size_t i = 0; i < s.values.size(); ++i)
        if (!std::isfinite(s.values[i]))
            fail(where + ".output: value " + std::to_string(i) + " is not finite");
    return s;
}

// Rotation keys should be unit quaternions; a zero one has no rotation at all and is
// replaced by the identity (counted), others are normalised when evaluated.
void check_rotation_keys(ImportContext& ctx, AnimationSampler& s, const std::string& where) {
    const bool cubic = s.interpolation == Interpolation::CubicSpline;
    std::uint32_t zero = 0, far = 0;
    for (std::size_t k = 0; k < s.times.size(); ++k) {
        float* q = &s.values[(cubic ? 3 * k + 1 : k) * 4];
        const double len = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] +
                                     double(q[2]) * q[2] + double(q[3]) * q[3]);
        if (len < 1e-12) {
            ++zero;
            q[0] = q[1] = q[2] = 0.0f;
            q[3] = 1.0f;
        } else if (std::abs(len - 1.0) > 1e-3) {
            ++far;
        }
    }
    if (zero)
        ctx.warn(where + ": " + std::to_string(zero) +
                 " zero rotation keys replaced by the identity");
    if (far)
        ctx.warn(where + ": " + std::to_string(far) +
                 " rotation keys are not unit quaternions; normalised when evaluated");
}

// The index in `anim.samplers` of the file's sampler `sampler`, read the first time a
// channel uses it (with that channel's value width); a later channel of another width
// is refused.
std::uint32_t channel_sampler(ImportContext& ctx, const tinygltf::Animation& src, int sampler,
                              std::uint32_t width, std::uint32_t components, bool rotation,
                              const std::string& cpath, const std::string& where, Animation& anim,
                              std::vector<int>& sampler_index) {
    int& si = sampler_index[static_cast<std::size_t>(sampler)];
    const std::string spath = where + ".samplers[" + std::to_string(sampler) + "]";
    if (si < 0) {
        anim.samplers.push_back(read_sampler(ctx, src.samplers[static_cast<std::size_t>(sampler)],
                                             width, components, spath));
        if (rotation) check_rotation_keys(ctx, anim.samplers.back(), spath);
        si = static_cast<int>(anim.samplers.size() - 1);
    } else if (anim.samplers[static_cast<std::size_t>(si)].width != width) {
        fail(cpath + ": shares " + spath + " with a channel of another value size");
    }
    return static_cast<std::uint32_t>(si);
}

// The KHR_animation_pointer pointer of a channel whose target.path is "pointer".
std::string animation_pointer(const tinygltf::AnimationChannel& ch, const std::string& cpath) {
    const auto it = ch.target_extensions.find("KHR_animation_pointer");
    if (it == ch.target_extensions.end() || !it->second.Get("pointer").IsString())
        fail(cpath + ".target.extensions.KHR_animation_pointer.pointer: missing or not a string");
    return it->second.Get("pointer").Get<std::string>();
}

// "/nodes/N/translation" (rotation, scale, weights) -> node N and that path.
bool node_pointer(const std::string& pointer, int& node, std::string& path) {
    constexpr std::string_view kNodes = "/nodes/";
    if (pointer.rfind(kNodes, 0) != 0) return false;
    const std::size_t slash = pointer.find('/', kNodes.size());
    if (slash == std::string::npos || slash == kNodes.size()) return false;
    const std::string rest = pointer.substr(slash + 1);
    if (rest != "translation" && rest != "rotation" && rest != "scale" && rest != "weights")
        return false;
    std::uint32_t n = 0;
    const char* first = pointer.data() + kNodes.size();
    const auto [end, ec] = std::from_chars(first, pointer.data() + slash, n);
    if (ec != std::errc() || end != pointer.data() + slash || n > 0x7fffffffu) return false;
    node = static_cast<int>(n);
    path = rest;
    return true;
}

// A KHR_animation_pointer channel on a material, light, camera or node visibility.
void import_pointer_channel(ImportContext& ctx, const tinygltf::Animation& src, std::size_t c,
                            const std::string& cpath, const std::string& where,
                            const std::string& pointer, Animation& anim,
                            std::vector<int>& sampler_index) {
    const auto& ch = src.channels[c];
    PointerChannel out;
    out.pointer = pointer;
    if (const std::string why = resolve_animation_pointer(ctx.scene, pointer, out.target);
        !why.empty())
        fail(cpath + ".target.extensions.KHR_animation_pointer.pointer: \"" + pointer +
             "\" is not animated: " + why);
    const std::uint32_t width = pointer_width(out.target.property);
    out.sampler = channel_sampler(ctx, src, ch.sampler, width, width, false, cpath, where, anim,
                                  sampler_index);
    out.source = static_cast<std::uint32_t>(c);
    out.source_sampler = static_cast<std::uint32_t>(ch.sampler);
    anim.pointers.push_back(std::move(out));
}

// One channel of animation `src`: its sampler read (once, with the channel's width)
// and the channel appended to `anim`. Throws ImportError naming what is wrong.
void import_channel(ImportContext& ctx, const tinygltf::Animation& src, std::size_t c,
                    const std::string& cpath, const std::string& where, Animation& anim,
                    std::vector<int>& sampler_index, std::uint32_t& skipped) {
    Scene& scene = ctx.scene;
    const auto& ch = src.channels[c];
    if (ch.sampler < 0 || static_cast<std::size_t>(ch.sampler) >= src.samplers.size())
        fail(cpath + ".sampler: index " + std::to_string(ch.sampler) + " out of range");
    int target_node = ch.target_node;
    std::string target_path = ch.target_path;
    if (target_path == "pointer") {
        const std::string pointer = animation_pointer(ch, cpath);
        // The pointer form of node TRS and weights is a node channel.
        if (!node_pointer(pointer, target_node, target_path)) {
            import_pointer_channel(ctx, src, c, cpath, where, pointer, anim, sampler_index);
            return;
        }
    }
    if (target_node < 0) {
        ++skipped; // glTF allows targets defined by extensions only
        return;
    }
    if (static_cast<std::size_t>(target_node) >= scene.nodes.size())
        fail(cpath + ".target.node: " + std::to_string(target_node) + " out of range");
    const Node& node = scene.nodes[static_cast<std::size_t>(target_node)];
    AnimationChannel out;
    out.node = static_cast<std::uint32_t>(target_node);
    std::uint32_t width = 3, components = 3;
    if (target_path == "translation") {
        out.path = AnimationPath::Translation;
    } else if (target_path == "scale") {
        out.path = AnimationPath::Scale;
    } else if (target_path == "rotation") {
        out.path = AnimationPath::Rotation;
        width = components = 4;
    } else if (target_path == "weights") {
        out.path = AnimationPath::Weights;
        width = static_cast<std::uint32_t>(node.weights.size());
        components = 1;
        if (width == 0)
            fail(cpath + ": animates weights of nodes[" + std::to_string(out.node) +
                 "], which has no morph targets");
    } else {
        ++skipped; // "pointer" and other extension paths
        return;
    }
    if (node.has_matrix && out.path != AnimationPath::Weights)
        fail(cpath + ": animates nodes[" + std::to_string(out.node) +
             "], which has a matrix (glTF forbids animating it)");
    out.sampler =
        channel_sampler(ctx, src, ch.sampler, width, components,
                        out.path == AnimationPath::Rotation, cpath, where, anim, sampler_index);
    out.source = static_cast<std::uint32_t>(c);
    out.source_sampler = static_cast<std::uint32_t>(ch.sampler);
    anim.channels.push_back(out);
}

} // namespace

void import_animations(ImportContext& ctx) {
    const auto& model = ctx.model;
    Scene& scene = ctx.scene;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const auto& src = model.animations[a];
        const std::string where = "animations[" + std::to_string(a) + "]";
        Animation anim;
        anim.name = src.name;
        // Each sampler is read with the width of the first channel that uses it.
        std::vector<int> sampler_index(src.samplers.size(), -1);
        std::uint32_t skipped = 0;
        for (std::size_t c = 0; c < src.channels.size(); ++c) {
            const std::string cpath = where + ".channels[" + std::to_string(c) + "]";
            try { // a channel that cannot be evaluated is skipped and named
                import_channel(ctx, src, c, cpath, where, anim, sampler_index, skipped);
            } catch (const ImportError& e) {
                ctx.skip("SHERPA_ANIMATION_CHANNEL_SKIPPED",
                         std::string(e.what()) + " (" + cpath + " skipped)");
            }
        }
        if (skipped)
            ctx.warn(where + ": " + std::to_string(skipped) +
                     " channel(s) without a node or with an unknown path ignored");
        bool first = true;
        for (const auto& s : anim.samplers) {
            anim.start = first ? s.times.front() : std::min(anim.start, s.times.front());
            anim.end = first ? s.times.back() : std::max(anim.end, s.times.back());
            first = false;
        }
        scene.animations.push_back(std::move(anim));
    }
}

} // namespace sherpa::scene::detail
