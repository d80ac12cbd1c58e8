// KHR_animation_pointer targets: JSON pointers resolved against the scene once at
// import, values sampled like node channels and written into copies of the scene's
// materials, lights, cameras and node visibility.
#include "animation_pointer_material.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/animation_pointer.h>
#include <sherpa/scene/scene.h>

#include <algorithm>
#include <array>
#include <charconv>

namespace sherpa::scene {
namespace {

struct Named {
    std::string_view path; // after the object index
    PointerProperty property;
    const char* extension; // the extension the object must use, or null
};

constexpr Named kLight[] = {
    {"color", PointerProperty::LightColor, nullptr},
    {"intensity", PointerProperty::LightIntensity, nullptr},
    {"range", PointerProperty::LightRange, nullptr},
    {"spot/innerConeAngle", PointerProperty::SpotInnerCone, nullptr},
    {"spot/outerConeAngle", PointerProperty::SpotOuterCone, nullptr},
};

constexpr Named kCamera[] = {
    {"perspective/yfov", PointerProperty::CameraYfov, nullptr},
    {"perspective/aspectRatio", PointerProperty::CameraAspect, nullptr},
    {"perspective/znear", PointerProperty::CameraZnear, nullptr},
    {"perspective/zfar", PointerProperty::CameraZfar, nullptr},
    {"orthographic/znear", PointerProperty::CameraOrthographicZnear, nullptr},
    {"orthographic/zfar", PointerProperty::CameraOrthographicZfar, nullptr},
    {"orthographic/xmag", PointerProperty::CameraXmag, nullptr},
    {"orthographic/ymag", PointerProperty::CameraYmag, nullptr},
};

// "/materials/3/emissiveFactor" -> prefix "/materials/", index 3, rest "emissiveFactor".
bool split_index(std::string_view pointer, std::string_view prefix, std::uint32_t& index,
                 std::string_view& rest) {
    if (pointer.substr(0, prefix.size()) != prefix) return false;
    const std::string_view tail = pointer.substr(prefix.size());
    const std::size_t slash = tail.find('/');
    if (slash == 0 || slash == std::string_view::npos) return false;
    const auto [end, ec] = std::from_chars(tail.data(), tail.data() + slash, index);
    if (ec != std::errc() || end != tail.data() + slash) return false;
    rest = tail.substr(slash + 1);
    return true;
}

} // namespace

std::string_view to_string(PointerProperty p) {
    static constexpr std::string_view kNames[] = {"baseColorFactor",
                                                  "emissiveFactor",
                                                  "metallicFactor",
                                                  "roughnessFactor",
                                                  "alphaCutoff",
                                                  "normalScale",
                                                  "occlusionStrength",
                                                  "emissiveStrength",
                                                  "ior",
                                                  "specularFactor",
                                                  "specularColorFactor",
                                                  "clearcoatFactor",
                                                  "clearcoatRoughnessFactor",
                                                  "clearcoatNormalScale",
                                                  "transmissionFactor",
                                                  "thicknessFactor",
                                                  "attenuationDistance",
                                                  "attenuationColor",
                                                  "sheenColorFactor",
                                                  "sheenRoughnessFactor",
                                                  "iridescenceFactor",
                                                  "iridescenceIor",
                                                  "iridescenceThicknessMinimum",
                                                  "iridescenceThicknessMaximum",
                                                  "anisotropyStrength",
                                                  "anisotropyRotation",
                                                  "dispersion",
                                                  "diffuseTransmissionFactor",
                                                  "diffuseTransmissionColorFactor",
                                                  "textureOffset",
                                                  "textureRotation",
                                                  "textureScale",
                                                  "lightColor",
                                                  "lightIntensity",
                                                  "lightRange",
                                                  "spotInnerCone",
                                                  "spotOuterCone",
                                                  "cameraYfov",
                                                  "cameraAspect",
                                                  "cameraZnear",
                                                  "cameraZfar",
                                                  "cameraOrthographicZnear",
                                                  "cameraOrthographicZfar",
                                                  "cameraXmag",
                                                  "cameraYmag",
                                                  "nodeVisible"};
    static_assert(std::size(kNames) == std::size_t(PointerProperty::NodeVisible) + 1);
    return kNames[static_cast<std::size_t>(p)];
}

std::uint32_t pointer_width(PointerProperty p) {
    switch (p) {
    case PointerProperty::BaseColorFactor:
        return 4;
    case PointerProperty::EmissiveFactor:
    case PointerProperty::SpecularColorFactor:
    case PointerProperty::AttenuationColor:
    case PointerProperty::SheenColorFactor:
    case PointerProperty::DiffuseTransmissionColorFactor:
    case PointerProperty::LightColor:
        return 3;
    case PointerProperty::TextureOffset:
    case PointerProperty::TextureScale:
        return 2;
    default:
        return 1;
    }
}

std::string resolve_animation_pointer(const Scene& scene, std::string_view pointer,
                                      AnimatedTarget& out) {
    std::uint32_t index = 0;
    std::string_view rest;
    out = {};
    if (split_index(pointer, "/materials/", index, rest)) {
        const auto it = std::find_if(
            scene.materials.begin(), scene.materials.end(),
            [&](const MaterialInstance& m) { return m.gltf_index == std::int32_t(index); });
        if (it == scene.materials.end())
            return "material " + std::to_string(index) + " does not exist";
        return resolve_material_pointer(*it, index, rest, out);
    }
    if (split_index(pointer, "/extensions/KHR_lights_punctual/lights/", index, rest)) {
        if (index >= scene.lights.size())
            return "light " + std::to_string(index) + " does not exist";
        out.object = index;
        for (const Named& n : kLight)
            if (rest == n.path) {
                const bool spot = n.property == PointerProperty::SpotInnerCone ||
                                  n.property == PointerProperty::SpotOuterCone;
                if (spot && scene.lights[index].type != LightType::Spot)
                    return "light " + std::to_string(index) + " is not a spot light";
                out.property = n.property;
                return {};
            }
        return "not an animatable light property (color, intensity, range, spot cone angles)";
    }
    if (split_index(pointer, "/cameras/", index, rest)) {
        if (index >= scene.cameras.size())
            return "camera " + std::to_string(index) + " does not exist";
        out.object = index;
        const bool perspective = scene.cameras[index].type == CameraType::Perspective;
        for (const Named& n : kCamera)
            if (rest == n.path) {
                if ((rest.substr(0, 12) == "perspective/") != perspective)
                    return "camera " + std::to_string(index) + " is " +
                           (perspective ? "perspective" : "orthographic");
                out.property = n.property;
                return {};
            }
        return "not an animatable camera property (yfov, aspectRatio, znear, zfar, xmag, ymag)";
    }
    if (split_index(pointer, "/nodes/", index, rest)) {
        if (index >= scene.nodes.size()) return "node " + std::to_string(index) + " does not exist";
        if (rest != "extensions/KHR_node_visibility/visible")
            return "not an animatable node property (translation, rotation, scale, weights, "
                   "extensions/KHR_node_visibility/visible)";
        out.object = index;
        out.property = PointerProperty::NodeVisible;
        return {};
    }
    return "not a target Sherpa animates (materials, KHR_lights_punctual lights, cameras, nodes)";
}

std::string pointer_of(const AnimatedTarget& t) {
    const std::string i = std::to_string(t.object);
    if (const std::string path = material_pointer_path(t); !path.empty())
        return "/materials/" + i + "/" + path;
    for (const Named& n : kLight)
        if (n.property == t.property)
            return "/extensions/KHR_lights_punctual/lights/" + i + "/" + std::string(n.path);
    if (t.property == PointerProperty::NodeVisible)
        return "/nodes/" + i + "/extensions/KHR_node_visibility/visible";
    for (const Named& n : kCamera)
        if (n.property == t.property) return "/cameras/" + i + "/" + std::string(n.path);
    return {};
}

std::vector<AnimatedProperty> evaluate_pointer_channels(const Scene& scene, std::int32_t animation,
                                                        double time) {
    std::vector<AnimatedProperty> out;
    if (animation < 0 || std::size_t(animation) >= scene.animations.size()) return out;
    const Animation& anim = scene.animations[std::size_t(animation)];
    for (const PointerChannel& c : anim.pointers) {
        AnimatedProperty p;
        p.target = c.target;
        const AnimationSampler& s = anim.samplers[c.sampler];
        if (c.target.property == PointerProperty::NodeVisible) {
            // A boolean steps whatever the interpolation: the key at or before `time`.
            AnimationSampler step = s;
            step.interpolation = Interpolation::Step;
            if (s.interpolation == Interpolation::CubicSpline) {
                step.values.clear();
                for (std::size_t k = 0; k < s.times.size(); ++k)
                    step.values.push_back(s.values[3 * k + 1]);
            }
            sample_animation(step, AnimationPath::Translation, time, p.value);
        } else {
            sample_animation(s, AnimationPath::Translation, time, p.value);
        }
        out.push_back(p);
    }
    return out;
}

std::vector<std::uint32_t> apply_animated_properties(std::span<const AnimatedProperty> values,
                                                     std::span<MaterialInstance> materials,
                                                     std::span<Light> lights,
                                                     std::span<Camera> cameras,
                                                     std::vector<bool>* visible) {
    std::vector<std::uint32_t> changed;
    for (const AnimatedProperty& p : values) {
        const float* v = p.value;
        const std::uint32_t o = p.target.object;
        switch (p.target.property) {
        case PointerProperty::LightColor:
            if (o < lights.size()) lights[o].color = {v[0], v[1], v[2]};
            continue;
        case PointerProperty::LightIntensity:
            if (o < lights.size()) lights[o].intensity = v[0];
            continue;
        case PointerProperty::LightRange:
            if (o < lights.size()) lights[o].range = v[0];
            continue;
        case PointerProperty::SpotInnerCone:
            if (o < lights.size()) lights[o].inner_cone = v[0];
            continue;
        case PointerProperty::SpotOuterCone:
            if (o < lights.size()) lights[o].outer_cone = v[0];
            continue;
        case PointerProperty::CameraYfov:
            if (o < cameras.size()) cameras[o].yfov = v[0];
            continue;
        case PointerProperty::CameraAspect:
            if (o < cameras.size()) cameras[o].aspect = v[0];
            continue;
        case PointerProperty::CameraZnear:
        case PointerProperty::CameraOrthographicZnear:
            if (o < cameras.size()) cameras[o].znear = v[0];
            continue;
        case PointerProperty::CameraZfar:
        case PointerProperty::CameraOrthographicZfar:
            if (o < cameras.size()) cameras[o].zfar = v[0];
            continue;
        case PointerProperty::CameraXmag:
            if (o < cameras.size()) cameras[o].xmag = v[0];
            continue;
        case PointerProperty::CameraYmag:
            if (o < cameras.size()) cameras[o].ymag = v[0];
            continue;
        case PointerProperty::NodeVisible:
            if (visible && o < visible->size()) (*visible)[o] = v[0] != 0.0f;
            continue;
        default:
            break;
        }
        if (o >= materials.size() || !apply_material_property(p, materials[o])) continue;
        changed.push_back(o);
    }
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    return changed;
}

} // namespace sherpa::scene
