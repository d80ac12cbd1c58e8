// KHR_animation_pointer targets: JSON pointers resolved against the scene once at
// import, values sampled like node channels and written into copies of the scene's
// materials, lights, cameras and node visibility.
#include <sherpa/scene/animation.h>
#include <sherpa/scene/animation_pointer.h>
#include <sherpa/scene/scene.h>

#include <algorithm>
#include <array>
#include <charconv>

namespace sherpa {
namespace {

struct Named {
    std::string_view path; // after the object index
    PointerProperty property;
    const char* extension; // the extension the object must use, or null
};

constexpr Named kMaterial[] = {
    {"pbrMetallicRoughness/baseColorFactor", PointerProperty::BaseColorFactor, nullptr},
    {"pbrMetallicRoughness/metallicFactor", PointerProperty::MetallicFactor, nullptr},
    {"pbrMetallicRoughness/roughnessFactor", PointerProperty::RoughnessFactor, nullptr},
    {"emissiveFactor", PointerProperty::EmissiveFactor, nullptr},
    {"alphaCutoff", PointerProperty::AlphaCutoff, nullptr},
    {"normalTexture/scale", PointerProperty::NormalScale, nullptr},
    {"occlusionTexture/strength", PointerProperty::OcclusionStrength, nullptr},
    {"extensions/KHR_materials_emissive_strength/emissiveStrength",
     PointerProperty::EmissiveStrength, "KHR_materials_emissive_strength"},
    {"extensions/KHR_materials_ior/ior", PointerProperty::Ior, "KHR_materials_ior"},
    {"extensions/KHR_materials_specular/specularFactor", PointerProperty::SpecularFactor,
     "KHR_materials_specular"},
    {"extensions/KHR_materials_specular/specularColorFactor", PointerProperty::SpecularColorFactor,
     "KHR_materials_specular"},
};

constexpr std::pair<std::string_view, PointerTextureSlot> kSlots[] = {
    {"pbrMetallicRoughness/baseColorTexture", PointerTextureSlot::BaseColor},
    {"pbrMetallicRoughness/metallicRoughnessTexture", PointerTextureSlot::MetallicRoughness},
    {"normalTexture", PointerTextureSlot::Normal},
    {"occlusionTexture", PointerTextureSlot::Occlusion},
    {"emissiveTexture", PointerTextureSlot::Emissive},
};

constexpr std::pair<std::string_view, PointerProperty> kTransform[] = {
    {"offset", PointerProperty::TextureOffset},
    {"rotation", PointerProperty::TextureRotation},
    {"scale", PointerProperty::TextureScale},
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
    {"orthographic/znear", PointerProperty::CameraZnear, nullptr},
    {"orthographic/zfar", PointerProperty::CameraZfar, nullptr},
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

TextureSlot* slot_of(MaterialInstance& m, PointerTextureSlot s) {
    switch (s) {
    case PointerTextureSlot::BaseColor:
        return &m.base_color;
    case PointerTextureSlot::MetallicRoughness:
        return &m.metallic_roughness;
    case PointerTextureSlot::Normal:
        return &m.normal;
    case PointerTextureSlot::Occlusion:
        return &m.occlusion;
    case PointerTextureSlot::Emissive:
        return &m.emissive;
    }
    return &m.base_color;
}

const TextureSlot* slot_of(const MaterialInstance& m, PointerTextureSlot s) {
    return slot_of(const_cast<MaterialInstance&>(m), s);
}

std::string resolve_material(const Scene& scene, std::uint32_t index, std::string_view rest,
                             AnimatedTarget& out) {
    const auto it = std::find_if(
        scene.materials.begin(), scene.materials.end(),
        [&](const MaterialInstance& m) { return m.gltf_index == std::int32_t(index); });
    if (it == scene.materials.end()) return "material " + std::to_string(index) + " does not exist";
    out.object = index;
    for (const Named& n : kMaterial)
        if (rest == n.path) {
            if (n.extension && std::find(it->extensions.begin(), it->extensions.end(),
                                         n.extension) == it->extensions.end())
                return "materials[" + std::to_string(index) + "] does not use " + n.extension;
            out.property = n.property;
            return {};
        }
    for (const auto& [path, slot] : kSlots) {
        constexpr std::string_view kExt = "/extensions/KHR_texture_transform/";
        if (rest.substr(0, path.size()) != path || rest.substr(path.size(), kExt.size()) != kExt)
            continue;
        const std::string_view field = rest.substr(path.size() + kExt.size());
        for (const auto& [name, property] : kTransform)
            if (field == name) {
                if (!slot_of(*it, slot)->present())
                    return "materials[" + std::to_string(index) + "] has no " + std::string(path);
                out.property = property;
                out.slot = slot;
                return {};
            }
    }
    return "not an animatable material property (supported: the core factors, alphaCutoff, "
           "emissive_strength, ior, specular and KHR_texture_transform)";
}

} // namespace

std::string_view to_string(PointerProperty p) {
    static constexpr std::array<std::string_view, 26> kNames{
        "baseColorFactor",   "emissiveFactor",      "metallicFactor",
        "roughnessFactor",   "alphaCutoff",         "normalScale",
        "occlusionStrength", "emissiveStrength",    "ior",
        "specularFactor",    "specularColorFactor", "textureOffset",
        "textureRotation",   "textureScale",        "lightColor",
        "lightIntensity",    "lightRange",          "spotInnerCone",
        "spotOuterCone",     "cameraYfov",          "cameraAspect",
        "cameraZnear",       "cameraZfar",          "cameraXmag",
        "cameraYmag",        "nodeVisible"};
    return kNames[static_cast<std::size_t>(p)];
}

std::uint32_t pointer_width(PointerProperty p) {
    switch (p) {
    case PointerProperty::BaseColorFactor:
        return 4;
    case PointerProperty::EmissiveFactor:
    case PointerProperty::SpecularColorFactor:
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
    if (split_index(pointer, "/materials/", index, rest))
        return resolve_material(scene, index, rest, out);
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
    if (t.property >= PointerProperty::TextureOffset &&
        t.property <= PointerProperty::TextureScale) {
        const std::string_view field = t.property == PointerProperty::TextureOffset     ? "offset"
                                       : t.property == PointerProperty::TextureRotation ? "rotation"
                                                                                        : "scale";
        return "/materials/" + i + "/" + std::string(kSlots[std::size_t(t.slot)].first) +
               "/extensions/KHR_texture_transform/" + std::string(field);
    }
    for (const Named& n : kMaterial)
        if (n.property == t.property) return "/materials/" + i + "/" + std::string(n.path);
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
            if (o < cameras.size()) cameras[o].znear = v[0];
            continue;
        case PointerProperty::CameraZfar:
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
        if (o >= materials.size()) continue;
        MaterialInstance& m = materials[o];
        switch (p.target.property) {
        case PointerProperty::BaseColorFactor:
            m.base_color_factor = {v[0], v[1], v[2], v[3]};
            break;
        case PointerProperty::EmissiveFactor:
            m.emissive_factor = {v[0], v[1], v[2]};
            break;
        case PointerProperty::MetallicFactor:
            m.metallic_factor = v[0];
            break;
        case PointerProperty::RoughnessFactor:
            m.roughness_factor = v[0];
            break;
        case PointerProperty::AlphaCutoff:
            m.alpha_cutoff = v[0];
            break;
        case PointerProperty::NormalScale:
            m.normal_scale = v[0];
            break;
        case PointerProperty::OcclusionStrength:
            m.occlusion_strength = v[0];
            break;
        case PointerProperty::EmissiveStrength:
            m.emissive_strength = v[0];
            break;
        case PointerProperty::Ior:
            if (m.ior) m.ior = v[0];
            break;
        case PointerProperty::SpecularFactor:
            if (m.specular) m.specular->specular_factor = v[0];
            break;
        case PointerProperty::SpecularColorFactor:
            if (m.specular) m.specular->specular_color_factor = {v[0], v[1], v[2]};
            break;
        case PointerProperty::TextureOffset:
            slot_of(m, p.target.slot)->transform.offset = {v[0], v[1]};
            slot_of(m, p.target.slot)->transform.present = true;
            break;
        case PointerProperty::TextureRotation:
            slot_of(m, p.target.slot)->transform.rotation = v[0];
            slot_of(m, p.target.slot)->transform.present = true;
            break;
        case PointerProperty::TextureScale:
            slot_of(m, p.target.slot)->transform.scale = {v[0], v[1]};
            slot_of(m, p.target.slot)->transform.present = true;
            break;
        default:
            continue;
        }
        changed.push_back(o);
    }
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    return changed;
}

} // namespace sherpa
