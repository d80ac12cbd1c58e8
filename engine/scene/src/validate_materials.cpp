// Cameras, materials, textures, images, lights, and objects nothing uses
// (validate_internal.h).
#include "validate_internal.h"

#include <cmath>

namespace sherpa::scene::detail {
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

bool declared(const Validation& v, std::string_view extension) {
    for (const Json& e : v.array("extensionsUsed"))
        if (e.is_string() && e.get_ref<const std::string&>() == extension) return true;
    return false;
}

// A number at obj[key] when it is in [lo, inf), else `fallback` (what the Khronos
// validator reads for an absent or out-of-range value).
double valid_or(const Json& obj, const char* key, double lo, double fallback) {
    const Json& j = Validation::member(obj, key);
    return j.is_number() && j.get<double>() >= lo ? j.get<double>() : fallback;
}

// What the material extensions say about each other and about the material, as the
// Khronos validator reports it (their values are the schema pass's).
void check_material_extensions(Validation& v, const Json& m, const std::string& where) {
    const Json& ext = Validation::member(m, "extensions");
    if (!ext.is_object()) return;
    const std::string base = ptr(where, "extensions");
    auto has = [&](const char* name) {
        return Validation::member(ext, name).is_object() && declared(v, name);
    };
    const Json& normal = Validation::member(m, "normalTexture");
    auto same_texcoord = [&](const Json& ext_object, const char* texture, const char* code,
                             const char* message, const char* name) {
        const Json& t = Validation::member(ext_object, texture);
        if (t.is_object() && normal.is_object() &&
            int_or(t, "texCoord", 0) != int_or(normal, "texCoord", 0))
            v.add(code, Severity::Warning, ptr(ptr(base, name), texture), message);
    };
    for (const char* exclusive : {"KHR_materials_pbrSpecularGlossiness", "KHR_materials_unlit"})
        if (has(exclusive) && ext.size() > 1)
            v.add("MULTIPLE_EXTENSIONS", Severity::Warning, ptr(base, exclusive),
                  "This extension may be incompatible with other extensions for the object.");
    if (has("KHR_materials_volume")) {
        const Json& volume = ext["KHR_materials_volume"];
        const std::string p = ptr(base, "KHR_materials_volume");
        if (!ext.contains("KHR_materials_transmission") &&
            !ext.contains("KHR_materials_diffuse_transmission"))
            v.add("KHR_MATERIALS_VOLUME_NO_TRANSMISSION", Severity::Warning, p,
                  "The volume extension needs to be combined with an extension that allows "
                  "light to transmit through the surface.");
        if (Validation::member(m, "doubleSided") == true &&
            valid_or(volume, "thicknessFactor", 0, 0) > 0)
            v.add("KHR_MATERIALS_VOLUME_DOUBLE_SIDED", Severity::Warning, p,
                  "The volume extension should not be used with double-sided materials.");
    }
    if (has("KHR_materials_dispersion") && !ext.contains("KHR_materials_volume"))
        v.add("KHR_MATERIALS_DISPERSION_NO_VOLUME", Severity::Warning,
              ptr(base, "KHR_materials_dispersion"),
              "The dispersion extension needs to be combined with the volume extension.");
    if (has("KHR_materials_anisotropy"))
        same_texcoord(ext["KHR_materials_anisotropy"], "anisotropyTexture",
                      "KHR_MATERIALS_ANISOTROPY_ANISOTROPY_TEXTURE_TEXCOORD",
                      "Normal and anisotropy textures should use the same texture coords.",
                      "KHR_materials_anisotropy");
    if (has("KHR_materials_clearcoat"))
        same_texcoord(ext["KHR_materials_clearcoat"], "clearcoatNormalTexture",
                      "KHR_MATERIALS_CLEARCOAT_CLEARCOAT_NORMAL_TEXTURE_TEXCOORD",
                      "Normal and clearcoat normal textures should use the same texture coords.",
                      "KHR_materials_clearcoat");
    if (has("KHR_materials_iridescence")) {
        const Json& ir = ext["KHR_materials_iridescence"];
        const std::string p = ptr(base, "KHR_materials_iridescence");
        if (Validation::member(ir, "iridescenceThicknessTexture").is_object()) {
            if (valid_or(ir, "iridescenceThicknessMinimum", 0, 100) ==
                valid_or(ir, "iridescenceThicknessMaximum", 0, 400))
                v.add("KHR_MATERIALS_IRIDESCENCE_THICKNESS_TEXTURE_UNUSED", Severity::Information,
                      ptr(p, "iridescenceThicknessTexture"),
                      "Thickness texture has no effect when the thickness minimum is equal to "
                      "the thickness maximum.");
        } else if (valid_or(ir, "iridescenceThicknessMinimum", 0, -1) >= 0) {
            v.add("KHR_MATERIALS_IRIDESCENCE_THICKNESS_RANGE_WITHOUT_TEXTURE",
                  Severity::Information, ptr(p, "iridescenceThicknessMinimum"),
                  "Thickness minimum has no effect when a thickness texture is not defined.");
        }
    }
}

} // namespace

bool needs_tangent_space(const Validation& v, const Json& material) {
    if (Validation::member(material, "normalTexture").is_object()) return true;
    const Json& ext = Validation::member(material, "extensions");
    const Json& clearcoat = Validation::member(ext, "KHR_materials_clearcoat");
    const Json& anisotropy = Validation::member(ext, "KHR_materials_anisotropy");
    return (Validation::member(clearcoat, "clearcoatNormalTexture").is_object() &&
            declared(v, "KHR_materials_clearcoat")) ||
           (Validation::member(anisotropy, "anisotropyTexture").is_object() &&
            declared(v, "KHR_materials_anisotropy"));
}

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
        check_material_extensions(v, m, where);
        const Json& ext = Validation::member(m, "extensions");
        // Only a strength other than the default 1 (as given, and valid) has an effect
        // to lose.
        if (ext.is_object() && ext.contains("KHR_materials_emissive_strength") &&
            valid_or(ext["KHR_materials_emissive_strength"], "emissiveStrength", 0, 1) != 1) {
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
        if (!n.is_object()) continue;
        for (auto it = n.begin(); it != n.end(); ++it) { // one walk over the keys
            const std::string& key = it.key();
            std::vector<std::uint8_t>* used = key == "mesh"     ? &meshes
                                              : key == "skin"   ? &skins
                                              : key == "camera" ? &cameras
                                                                : nullptr;
            if (used && is_int(*it)) mark(*used, as_int(*it));
        }
    }
    for (const Json& m : v.array("meshes"))
        for (const Json& p : Validation::member(m, "primitives")) {
            for (const auto& [name, a] : Validation::member(p, "attributes").items())
                if (is_int(a)) mark(accessors, as_int(a));
            mark(accessors, int_or(p, "indices", -1));
            mark(materials, int_or(p, "material", -1));
            const Json& variants =
                Validation::member(Validation::member(p, "extensions"), "KHR_materials_variants");
            const Json& mappings = Validation::member(variants, "mappings");
            if (mappings.is_array())
                for (const Json& mapping : mappings)
                    mark(materials, int_or(mapping, "material", -1));
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
    report("materials", materials);
}

} // namespace sherpa::scene::detail
