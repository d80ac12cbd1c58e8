// The layered material extensions' readers (gltf_material_layers.h).
#include "gltf_material_layers.h"

#include "import_error.h"

#include <algorithm>
#include <cmath>

namespace sherpa::scene::detail {
namespace {

// A number property of an extension object: `fallback` where absent; NaN where it is
// not a number (then warned as not finite by the callers).
double number(const tinygltf::Value& e, const char* key, double fallback) {
    if (!e.IsObject() || !e.Has(key)) return fallback;
    const tinygltf::Value& v = e.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
}

// A factor defined on lo..hi: clamped with a warning outside, the default with a
// warning where not finite (checked as the float the GPU gets: 1e39 is infinite there).
float ranged(ImportContext& ctx, const tinygltf::Value& e, const char* key, double fallback,
             double lo, double hi, const std::string& w) {
    const double v = number(e, key, fallback);
    const std::string at = w + "." + key + ": ";
    if (!std::isfinite(static_cast<float>(v))) {
        ctx.warn(at + "not a finite number; the default " + number_text(fallback) + " is used");
        return static_cast<float>(fallback);
    }
    if (v < lo || v > hi) {
        const float c = static_cast<float>(std::clamp(v, lo, hi));
        ctx.warn(at + number_text(v) + " is outside " + number_text(lo) + ".." + number_text(hi) +
                 "; clamped to " + number_text(c));
        return c;
    }
    return static_cast<float>(v);
}

TextureSlot slot(ImportContext& ctx, const tinygltf::Value& e, const char* key,
                 const std::string& w, TextureRole role) {
    if (!e.IsObject() || !e.Has(key)) return {};
    return read_value_slot(ctx, e.Get(key), w + "." + key, role);
}

// normalTextureInfo.scale of an extension's normal map: any finite number (as the core
// normalTexture's); not finite: 1.
constexpr double kMaxNormalScale = 1000.0; // as the core normal map's (gltf_materials.cpp)

float normal_scale(ImportContext& ctx, const tinygltf::Value& e, const char* key,
                   const std::string& w) {
    if (!e.IsObject() || !e.Has(key)) return 1.0f;
    return ranged(ctx, e.Get(key), "scale", 1.0, -kMaxNormalScale, kMaxNormalScale, w + "." + key);
}

} // namespace

MaterialClearcoat read_clearcoat(ImportContext& ctx, const tinygltf::Value& e,
                                 const std::string& where) {
    const std::string w = where + ".extensions.KHR_materials_clearcoat";
    MaterialClearcoat c;
    c.factor = ranged(ctx, e, "clearcoatFactor", 0.0, 0.0, 1.0, w);
    c.roughness_factor = ranged(ctx, e, "clearcoatRoughnessFactor", 0.0, 0.0, 1.0, w);
    c.clearcoat = slot(ctx, e, "clearcoatTexture", w, kRoleLinear);
    c.roughness = slot(ctx, e, "clearcoatRoughnessTexture", w, kRoleLinear);
    c.normal = slot(ctx, e, "clearcoatNormalTexture", w, kRoleNormal);
    c.normal_scale = normal_scale(ctx, e, "clearcoatNormalTexture", w);
    return c;
}

MaterialSheen read_sheen(ImportContext& ctx, const tinygltf::Value& e, const std::string& where) {
    const std::string w = where + ".extensions.KHR_materials_sheen";
    MaterialSheen s;
    if (e.IsObject() && e.Has("sheenColorFactor")) {
        const tinygltf::Value& v = e.Get("sheenColorFactor");
        bool numbers = v.IsArray() && v.ArrayLen() == 3;
        glm::dvec3 c(0.0);
        for (int i = 0; numbers && i < 3; ++i) {
            numbers = v.Get(i).IsNumber() && std::isfinite(float(v.Get(i).GetNumberAsDouble()));
            if (numbers) c[i] = v.Get(i).GetNumberAsDouble();
        }
        if (!numbers) {
            ctx.warn(w + ".sheenColorFactor: not three finite numbers; the default [0, 0, 0] "
                         "(no sheen) is used");
        } else if (glm::any(glm::lessThan(c, glm::dvec3(0.0))) ||
                   glm::any(glm::greaterThan(c, glm::dvec3(1.0)))) {
            s.color_factor = glm::vec3(glm::clamp(c, 0.0, 1.0));
            ctx.warn(w + ".sheenColorFactor: components outside 0..1 are clamped");
        } else {
            s.color_factor = glm::vec3(c);
        }
    }
    s.roughness_factor = ranged(ctx, e, "sheenRoughnessFactor", 0.0, 0.0, 1.0, w);
    s.color = slot(ctx, e, "sheenColorTexture", w, kRoleColor);
    s.roughness = slot(ctx, e, "sheenRoughnessTexture", w, kRoleLinear);
    return s;
}

// anisotropyRotation is any finite angle (radians); it is kept as written within a
// bound where a float still resolves a fraction of a turn.
constexpr double kMaxRotation = 1.0e6;

MaterialAnisotropy read_anisotropy(ImportContext& ctx, const tinygltf::Value& e,
                                   const std::string& where) {
    const std::string w = where + ".extensions.KHR_materials_anisotropy";
    MaterialAnisotropy a;
    a.strength = ranged(ctx, e, "anisotropyStrength", 0.0, 0.0, 1.0, w);
    a.rotation = ranged(ctx, e, "anisotropyRotation", 0.0, -kMaxRotation, kMaxRotation, w);
    a.texture = slot(ctx, e, "anisotropyTexture", w, kRoleLinear);
    return a;
}

// The film's thickness bounds, in nanometres: any non-negative value up to 10^6 nm
// (a millimetre; far beyond visible interference, where the film's colours average
// out).
constexpr double kMaxFilmThickness = 1.0e6;

MaterialIridescence read_iridescence(ImportContext& ctx, const tinygltf::Value& e,
                                     const std::string& where) {
    const std::string w = where + ".extensions.KHR_materials_iridescence";
    MaterialIridescence i;
    i.factor = ranged(ctx, e, "iridescenceFactor", 0.0, 0.0, 1.0, w);
    // The film's index: at least 1 (the schema's minimum); below it, or not a number,
    // the default 1.3.
    const double ior = number(e, "iridescenceIor", 1.3);
    if (!std::isfinite(static_cast<float>(ior)) || ior < 1.0) {
        ctx.warn(w + ".iridescenceIor: " +
                 (std::isfinite(static_cast<float>(ior)) ? number_text(ior) + " is below 1"
                                                         : std::string("not a finite number")) +
                 "; the default 1.3 is used");
        i.ior = 1.3f;
    } else {
        i.ior = static_cast<float>(ior);
    }
    i.thickness_minimum =
        ranged(ctx, e, "iridescenceThicknessMinimum", 100.0, 0.0, kMaxFilmThickness, w);
    i.thickness_maximum =
        ranged(ctx, e, "iridescenceThicknessMaximum", 400.0, 0.0, kMaxFilmThickness, w);
    i.texture = slot(ctx, e, "iridescenceTexture", w, kRoleLinear);
    i.thickness = slot(ctx, e, "iridescenceThicknessTexture", w, kRoleLinear);
    return i;
}

} // namespace sherpa::scene::detail
