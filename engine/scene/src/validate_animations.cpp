// Animations: channels, their targets and the formats and counts of sampler
// accessors (validate_internal.h). Key values are checked by the data pass.
#include "validate_internal.h"

#include <limits>
#include <map>
#include <tuple>

namespace sherpa::scene::detail {
namespace {

std::string type_of(const Json& acc) {
    const Json& t = Validation::member(acc, "type");
    return t.is_string() ? t.get<std::string>() : std::string();
}

} // namespace

void validate_animations(Validation& v) {
    const Json& animations = v.array("animations");
    const Json& accessors = v.array("accessors");
    const Json& nodes = v.array("nodes");
    for (std::size_t a = 0; a < animations.size(); ++a) {
        const Json& anim = animations[a];
        if (!anim.is_object()) continue;
        const std::string where = ptr("/animations", a);
        const Json& samplers = Validation::member(anim, "samplers");
        const Json& channels = Validation::member(anim, "channels");
        // Samplers: input format and bounds.
        for (std::size_t s = 0; s < samplers.size() && samplers.is_array(); ++s) {
            const Json& sampler = Validation::member(samplers, s);
            const std::int64_t input = ref(v, sampler, "input", "accessors");
            if (input < 0) continue;
            const Json& acc = accessors[static_cast<std::size_t>(input)];
            const std::string ip = ptr(ptr(ptr(where, "samplers"), s), "input");
            v.use_accessor(input, AccessorRole::AnimationInput, ViewRole::Other, ip);
            v.use_accessor(ref(v, sampler, "output", "accessors"), AccessorRole::AnimationOutput,
                           ViewRole::Other, ptr(ptr(ptr(where, "samplers"), s), "output"));
            const bool format_ok = type_of(acc) == "SCALAR" &&
                                   int_or(acc, "componentType", 0) == 5126 &&
                                   Validation::member(acc, "normalized") != true;
            if (!format_ok)
                v.add("ANIMATION_SAMPLER_INPUT_ACCESSOR_INVALID_FORMAT", Severity::Error, ip,
                      "Invalid Animation sampler input accessor format. Must be one of ('{SCALAR, "
                      "FLOAT}').");
            if (!acc.contains("min") || !acc.contains("max"))
                v.add(
                    "ANIMATION_SAMPLER_INPUT_ACCESSOR_WITHOUT_BOUNDS", Severity::Error, ip,
                    "accessor.min and accessor.max must be defined for animation input accessor.");
            if (format_ok) // Khronos reads key times only from a valid input accessor
                v.usages.push_back(
                    {static_cast<std::size_t>(input), AccessorUse::AnimationInput, ip});
        }
        std::map<std::tuple<std::int64_t, std::string>, std::size_t> targets;
        for (std::size_t c = 0; c < channels.size() && channels.is_array(); ++c) {
            const Json& channel = Validation::member(channels, c);
            const std::string cp = ptr(ptr(where, "channels"), c);
            const std::int64_t si = int_or(channel, "sampler", -1);
            if (channel.contains("sampler") && si >= 0 &&
                static_cast<std::size_t>(si) >= samplers.size())
                v.add("UNRESOLVED_REFERENCE", Severity::Error, ptr(cp, "sampler"),
                      "Unresolved reference: " + std::to_string(si) + ".");
            const Json& target = Validation::member(channel, "target");
            const std::string tp = ptr(cp, "target");
            const Json& path_json = Validation::member(target, "path");
            const std::string path =
                path_json.is_string() ? path_json.get<std::string>() : std::string();
            const std::int64_t node = ref(v, target, "node", "nodes");
            std::size_t morphs = 0;
            if (node >= 0) {
                const Json& n = nodes[static_cast<std::size_t>(node)];
                if (path != "weights" && path != "pointer" && n.is_object() && n.contains("matrix"))
                    v.add("ANIMATION_CHANNEL_TARGET_NODE_MATRIX", Severity::Error, tp,
                          "Animation channel cannot target TRS properties of a node with defined "
                          "matrix.");
                if (path != "weights" && path != "pointer" && n.is_object() && n.contains("skin") &&
                    n.contains("mesh"))
                    v.add("ANIMATION_CHANNEL_TARGET_NODE_SKIN", Severity::Warning, ptr(tp, "path"),
                          "Animated TRS properties will not affect a skinned mesh.");
                if (const std::int64_t m = ref(v, n, "mesh", "meshes"); m >= 0) {
                    const Json& prims = Validation::member(
                        v.array("meshes")[static_cast<std::size_t>(m)], "primitives");
                    const Json& t =
                        Validation::member(Validation::member(prims, std::size_t{0}), "targets");
                    morphs = t.is_array() ? t.size() : 0;
                }
                if (path == "weights" && morphs == 0)
                    v.add("ANIMATION_CHANNEL_TARGET_NODE_WEIGHTS_NO_MORPHS", Severity::Error, tp,
                          "Animation channel cannot target WEIGHTS when mesh does not have morph "
                          "targets.");
                const auto key = std::make_tuple(node, path);
                if (const auto it = targets.find(key); it != targets.end())
                    v.add("ANIMATION_DUPLICATE_TARGETS", Severity::Error,
                          ptr(ptr(ptr(where, "channels"), it->second), "target"),
                          "Animation channel has the same target as channel " + std::to_string(c) +
                              ".");
                else
                    targets.emplace(key, c);
            }
            if (si < 0 || static_cast<std::size_t>(si) >= samplers.size() || path.empty() ||
                path == "pointer")
                continue;
            const Json& sampler = Validation::member(samplers, static_cast<std::size_t>(si));
            const std::int64_t input = ref(v, sampler, "input", "accessors");
            const std::int64_t output = ref(v, sampler, "output", "accessors");
            if (output < 0) continue;
            const Json& out = accessors[static_cast<std::size_t>(output)];
            const std::string sp = ptr(cp, "sampler");
            const std::string t = type_of(out);
            const std::int64_t ct = int_or(out, "componentType", 0);
            const bool norm = Validation::member(out, "normalized") == true;
            const bool f = ct == 5126 && !norm;
            const bool nint = norm && ct >= 5120 && ct <= 5123;
            const bool ok = path == "rotation"  ? t == "VEC4" && (f || nint)
                            : path == "weights" ? t == "SCALAR" && (f || nint)
                                                : t == "VEC3" && f;
            if (!ok)
                v.add("ANIMATION_SAMPLER_OUTPUT_ACCESSOR_INVALID_FORMAT", Severity::Error, sp,
                      "Invalid animation sampler output accessor format for path '" + path + "'.");
            const Json& interpolation = Validation::member(sampler, "interpolation");
            const bool cubic = interpolation == "CUBICSPLINE";
            if (input >= 0 && (path != "weights" || morphs > 0)) {
                const std::int64_t keys =
                    int_or(accessors[static_cast<std::size_t>(input)], "count", 0);
                // Counts come from the JSON (up to 2^63 - 1): a product past int64 expects
                // what no count can be.
                std::int64_t expected = 0;
                if (__builtin_mul_overflow(
                        keys,
                        (cubic ? 3 : 1) *
                            (path == "weights" ? static_cast<std::int64_t>(morphs) : 1),
                        &expected))
                    expected = std::numeric_limits<std::int64_t>::max();
                if (int_or(out, "count", 0) != expected)
                    v.add("ANIMATION_SAMPLER_OUTPUT_ACCESSOR_INVALID_COUNT", Severity::Error, sp,
                          "Animation sampler output accessor of count " + std::to_string(expected) +
                              " expected. Found " + std::to_string(int_or(out, "count", 0)) + ".");
                else if (cubic && keys < 2)
                    v.add("ANIMATION_SAMPLER_INPUT_ACCESSOR_TOO_FEW_ELEMENTS", Severity::Error, sp,
                          "Animation sampler output accessor with 'CUBICSPLINE' interpolation must "
                          "have at "
                          "least 2 elements. Got " +
                              std::to_string(keys) + ".");
            }
            if (path == "rotation" && ok) {
                AccessorUsage u{static_cast<std::size_t>(output),
                                AccessorUse::AnimationOutputRotation, sp};
                u.mode =
                    cubic ? 1 : 0; // cubic: every third element is a value, the others tangents
                v.usages.push_back(u);
            }
        }
    }
}

} // namespace sherpa::scene::detail
