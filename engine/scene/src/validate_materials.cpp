// Cameras, materials, textures, images, lights, and objects nothing uses
// (validate_internal.h).
#include "validate_internal.h"

#include <cmath>

namespace sherpa::detail {
namespace {

double num_or(const Json& obj, const char* key, double fallback) {
    const Json& j = Validation::member(obj, key);
    return j.is_number() ? j.get<double>() : fallback;
}

void mark(std::vector<std::uint8_t>& used, std::int64_t i) {
    if (i >= 0 && static_cast<std::size_t>(i) < used.size()) used[static_cast<std::size_t>(i)] = 1;
}

// Texture indices of every *Texture object under a material.
void textures_of(const Json& j, std::vector<std::uint8_t>& used, int depth) {
    if (depth > 8 || !j.is_object()) return;
    for (const auto& [key, value] : j.items()) {
        if (!value.is_object()) continue;
        if (key.ends_with("Texture") || key.ends_with("texture"))
            mark(used, int_or(value, "index", -1));
        textures_of(value, used, depth + 1);
    }
}

} // namespace

void validate_materials(Validation& v) {
    const Json& cameras = v.array("cameras");
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        const Json& cam = Validation::member(cameras, i);
        const std::string where = ptr("/cameras", i);
        const Json& persp = Validation::member(cam, "perspective");
        const Json& ortho = Validation::member(cam, "orthographic");
        const Json& type = Validation::member(cam, "type");
        if (persp.is_object() && ortho.is_object())
            v.add("ONE_OF_MISMATCH", Severity::Error, where,
                  "Exactly one of ('perspective', 'orthographic') properties must be defined.");
        else if ((type == "perspective" && !persp.is_object()) ||
                 (type == "orthographic" && !ortho.is_object()))
            v.add("UNDEFINED_PROPERTY", Severity::Error, where,
                  "Property '" + type.get<std::string>() + "' must be defined.");
        if (persp.is_object()) {
            const double znear = num_or(persp, "znear", 0), zfar = num_or(persp, "zfar", INFINITY);
            if (persp.contains("zfar") && zfar <= znear)
                v.add("CAMERA_ZFAR_LEQUAL_ZNEAR", Severity::Error, ptr(where, "perspective"),
                      "zfar must be greater than znear.");
            if (num_or(persp, "yfov", 0) >= 3.14159265358979323846)
                v.add("CAMERA_YFOV_GEQUAL_PI", Severity::Warning, ptr(where, "perspective"),
                      "yfov should be less than Pi.");
        }
        if (ortho.is_object()) {
            if (num_or(ortho, "zfar", 1) <= num_or(ortho, "znear", 0))
                v.add("CAMERA_ZFAR_LEQUAL_ZNEAR", Severity::Error, ptr(where, "orthographic"),
                      "zfar must be greater than znear.");
            for (const char* mag : {"xmag", "ymag"}) {
                const Json& m = Validation::member(ortho, mag);
                if (!m.is_number()) continue;
                if (m.get<double>() == 0)
                    v.add("CAMERA_XMAG_YMAG_ZERO", Severity::Error,
                          ptr(ptr(where, "orthographic"), mag), "xmag and ymag must not be zero.");
                else if (m.get<double>() < 0)
                    v.add("CAMERA_XMAG_YMAG_NEGATIVE", Severity::Warning,
                          ptr(ptr(where, "orthographic"), mag),
                          "xmag and ymag should not be negative.");
            }
        }
    }

    const Json& materials = v.array("materials");
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const Json& m = Validation::member(materials, i);
        const std::string where = ptr("/materials", i);
        if (m.contains("alphaCutoff") && Validation::member(m, "alphaMode") != "MASK")
            v.add("MATERIAL_ALPHA_CUTOFF_INVALID_MODE", Severity::Warning,
                  ptr(where, "alphaCutoff"),
                  "Alpha cutoff is supported only for 'MASK' alpha mode.");
        const Json& ext = Validation::member(m, "extensions");
        if (ext.is_object() && ext.contains("KHR_materials_emissive_strength")) {
            const Json& f = Validation::member(m, "emissiveFactor");
            bool zero = !f.is_array();
            if (f.is_array()) {
                zero = true;
                for (const Json& x : f) zero &= x.is_number() && x.get<double>() == 0;
            }
            if (zero)
                v.add("KHR_MATERIALS_EMISSIVE_STRENGTH_ZERO_FACTOR", Severity::Warning,
                      ptr(ptr(where, "extensions"), "KHR_materials_emissive_strength"),
                      "Emissive strength has no effect when the emissive factor is zero or "
                      "undefined.");
        }
    }

    const Json& images = v.array("images");
    for (std::size_t i = 0; i < images.size(); ++i) {
        const Json& img = Validation::member(images, i);
        const std::string where = ptr("/images", i);
        if (img.contains("uri") == img.contains("bufferView"))
            v.add("ONE_OF_MISMATCH", Severity::Error, where,
                  "Exactly one of ('uri', 'bufferView') properties must be defined.");
        if (img.contains("bufferView") && !img.contains("mimeType"))
            v.add("UNSATISFIED_DEPENDENCY", Severity::Error, ptr(where, "bufferView"),
                  "Dependency failed. 'mimeType' must be defined.");
    }

    // A texture's core source must be an image type glTF allows.
    const Json& textures = v.array("textures");
    for (std::size_t t = 0; t < textures.size(); ++t) {
        const std::int64_t src = ref(v, Validation::member(textures, t), "source", "images");
        if (src < 0) continue;
        const Json& mime = Validation::member(
            Validation::member(images, static_cast<std::size_t>(src)), "mimeType");
        if (mime.is_string() && mime != "image/jpeg" && mime != "image/png")
            v.add("TEXTURE_INVALID_IMAGE_MIME_TYPE", Severity::Error,
                  ptr(ptr("/textures", t), "source"),
                  "Invalid MIME type '" + mime.get<std::string>() +
                      "' for the texture source. Valid MIME types are ('image/jpeg', "
                      "'image/png').");
    }

    const Json& lights =
        Validation::member(Validation::member(v.root, "extensions"), "KHR_lights_punctual");
    const Json& list = Validation::member(lights, "lights");
    for (std::size_t i = 0; i < list.size() && list.is_array(); ++i) {
        const Json& light = Validation::member(list, i);
        const std::string lp = ptr("/extensions/KHR_lights_punctual/lights", i);
        const Json& type = Validation::member(light, "type");
        if (type.is_string() && type != "directional" && type != "point" && type != "spot")
            v.add("VALUE_NOT_IN_LIST", Severity::Warning, ptr(lp, "type"),
                  "Invalid value '" + type.get<std::string>() +
                      "'. Valid values are ('directional', 'point', 'spot').");
        const Json& intensity = Validation::member(light, "intensity");
        if (intensity.is_number() && intensity.get<double>() < 0)
            v.add("VALUE_NOT_IN_RANGE", Severity::Error, ptr(lp, "intensity"),
                  "Value " + intensity.dump() + " is out of range.");
        const Json& spot = Validation::member(light, "spot");
        if (!spot.is_object()) continue;
        const double inner = num_or(spot, "innerConeAngle", 0);
        const double outer = num_or(spot, "outerConeAngle", 0.7853981633974483);
        if (outer <= inner)
            v.add("KHR_LIGHTS_PUNCTUAL_LIGHT_SPOT_ANGLES", Severity::Error,
                  ptr(ptr(ptr("/extensions/KHR_lights_punctual/lights", i), "spot"),
                      "outerConeAngle"),
                  "outerConeAngle is less than or equal to innerConeAngle.");
    }
}

void validate_unused(Validation& v) {
    std::vector<std::uint8_t> accessors(v.size("accessors")), meshes(v.size("meshes")),
        skins(v.size("skins")), textures(v.size("textures")), images(v.size("images")),
        materials(v.size("materials")), samplers(v.size("samplers")), cameras(v.size("cameras"));
    for (const Json& n : v.array("nodes")) {
        mark(meshes, int_or(n, "mesh", -1));
        mark(skins, int_or(n, "skin", -1));
        mark(cameras, int_or(n, "camera", -1));
    }
    for (const Json& m : v.array("meshes"))
        for (const Json& p : Validation::member(m, "primitives")) {
            for (const auto& [name, a] : Validation::member(p, "attributes").items())
                if (is_int(a)) mark(accessors, as_int(a));
            mark(accessors, int_or(p, "indices", -1));
            mark(materials, int_or(p, "material", -1));
            const Json& targets = Validation::member(p, "targets");
            if (targets.is_array())
                for (const Json& t : targets)
                    if (t.is_object())
                        for (const auto& [name, a] : t.items())
                            if (is_int(a)) mark(accessors, as_int(a));
        }
    for (const Json& s : v.array("skins")) mark(accessors, int_or(s, "inverseBindMatrices", -1));
    for (std::size_t a = 0; a < v.size("animations"); ++a) {
        const Json& anim = v.array("animations")[a];
        const Json& channels = Validation::member(anim, "channels");
        const Json& anim_samplers = Validation::member(anim, "samplers");
        std::vector<std::uint8_t> used(anim_samplers.is_array() ? anim_samplers.size() : 0);
        for (const Json& c : channels) mark(used, int_or(c, "sampler", -1));
        for (std::size_t s = 0; s < used.size(); ++s) {
            if (!used[s]) {
                v.add("UNUSED_OBJECT", Severity::Information,
                      ptr(ptr(ptr("/animations", a), "samplers"), s), "This object may be unused.");
                continue;
            }
            mark(accessors, int_or(anim_samplers[s], "input", -1));
            mark(accessors, int_or(anim_samplers[s], "output", -1));
        }
    }
    for (const Json& m : v.array("materials")) textures_of(m, textures, 0);
    for (std::size_t t = 0; t < textures.size(); ++t) {
        const Json& tex = v.array("textures")[t];
        mark(samplers, int_or(tex, "sampler", -1));
        if (!textures[t]) continue;
        mark(images, int_or(tex, "source", -1));
        for (const auto& [name, e] : Validation::member(tex, "extensions").items())
            mark(images, int_or(e, "source", -1));
    }
    auto report = [&](const char* key, const std::vector<std::uint8_t>& used) {
        for (std::size_t i = 0; i < used.size(); ++i)
            if (!used[i])
                v.add("UNUSED_OBJECT", Severity::Information, ptr(ptr("", key), i),
                      "This object may be unused.");
    };
    report("accessors", accessors);
    report("meshes", meshes);
    report("skins", skins);
    report("textures", textures);
    report("images", images);
}

} // namespace sherpa::detail
