// KHR_materials_transmission, KHR_materials_volume, KHR_materials_diffuse_transmission
// and KHR_materials_dispersion: read, range-checked, and set on the material. Every
// value outside its range is a warning naming the property and the fallback drawn
// (docs/materials.md, "Bad input").
#include "gltf_material_values.h"
#include "import_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sherpa::scene::detail {
namespace {

// One number of an extension object: absent gives `fallback` silently; not a number,
// NaN or infinite (as a 32-bit float) gives `fallback` with a warning; outside
// [lo, hi] it is clamped with a warning.
float checked_number(ImportContext& ctx, const tinygltf::Value& e, const char* key, float fallback,
                     float lo, float hi, const std::string& where) {
    if (!e.IsObject() || !e.Has(key)) return fallback;
    const tinygltf::Value& v = e.Get(key);
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
    const float f = static_cast<float>(d);
    const std::string w = where + "." + key;
    if (!std::isfinite(f)) {
        ctx.warn(w + ": " + (v.IsNumber() ? number_text(d) : std::string("not a number")) +
                 " is not a finite number; the default " + number_text(fallback) + " is used");
        return fallback;
    }
    if (f < lo || f > hi) {
        const float c = std::clamp(f, lo, hi);
        ctx.warn(w + ": " + number_text(d) + " is outside " + number_text(lo) + ".." +
                 (std::isinf(hi) ? std::string("infinity") : number_text(hi)) + "; clamped to " +
                 number_text(c));
        return c;
    }
    return f;
}

// An RGB factor whose components lie in [0, hi]: not three finite numbers gives
// `fallback`, components outside are clamped; both with a warning.
glm::vec3 checked_color(ImportContext& ctx, const tinygltf::Value& e, const char* key,
                        glm::vec3 fallback, float hi, const std::string& where) {
    if (!e.IsObject() || !e.Has(key)) return fallback;
    const glm::vec3 c = glm::vec3(vec_or(e, key, glm::vec4(std::nanf("")), 3));
    const std::string w = where + "." + key;
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
        ctx.warn(w + ": not three finite numbers; the default [" + number_text(fallback.x) + ", " +
                 number_text(fallback.y) + ", " + number_text(fallback.z) + "] is used");
        return fallback;
    }
    const glm::vec3 clamped = glm::clamp(c, glm::vec3(0.0f), glm::vec3(hi));
    if (clamped != c) ctx.warn(w + ": components outside 0.." + number_text(hi) + " are clamped");
    return clamped;
}

TextureSlot slot(ImportContext& ctx, const tinygltf::Value& e, const char* key,
                 const std::string& where, TextureRole role) {
    if (!e.IsObject() || !e.Has(key)) return {};
    return read_value_slot(ctx, e.Get(key), where + "." + key, role);
}

const tinygltf::Value* find(const tinygltf::ExtensionMap& extensions, const char* name) {
    const auto it = extensions.find(name);
    return it == extensions.end() ? nullptr : &it->second;
}

constexpr float kInfinity = std::numeric_limits<float>::infinity();

} // namespace

void read_volume_extensions(ImportContext& ctx, const tinygltf::ExtensionMap& extensions,
                            MaterialInstance& m, const std::string& where) {
    const std::string ext = where + ".extensions.";
    if (const tinygltf::Value* e = find(extensions, "KHR_materials_transmission")) {
        const std::string w = ext + "KHR_materials_transmission";
        MaterialTransmission t;
        t.factor = checked_number(ctx, *e, "transmissionFactor", 0.0f, 0.0f, 1.0f, w);
        t.texture = slot(ctx, *e, "transmissionTexture", w, kRoleLinear);
        m.transmission = t;
    }
    if (const tinygltf::Value* e = find(extensions, "KHR_materials_diffuse_transmission")) {
        const std::string w = ext + "KHR_materials_diffuse_transmission";
        MaterialDiffuseTransmission d;
        d.factor = checked_number(ctx, *e, "diffuseTransmissionFactor", 0.0f, 0.0f, 1.0f, w);
        d.texture = slot(ctx, *e, "diffuseTransmissionTexture", w, kRoleLinear);
        d.color_factor =
            checked_color(ctx, *e, "diffuseTransmissionColorFactor", glm::vec3(1.0f), 1.0f, w);
        d.color = slot(ctx, *e, "diffuseTransmissionColorTexture", w, kRoleColor);
        m.diffuse_transmission = d;
    }
    if (const tinygltf::Value* e = find(extensions, "KHR_materials_volume")) {
        const std::string w = ext + "KHR_materials_volume";
        MaterialVolume v;
        v.thickness_factor = checked_number(ctx, *e, "thicknessFactor", 0.0f, 0.0f, kInfinity, w);
        v.thickness = slot(ctx, *e, "thicknessTexture", w, kRoleLinear);
        if (e->IsObject() && e->Has("attenuationDistance")) {
            const tinygltf::Value& d = e->Get("attenuationDistance");
            const double dist = d.IsNumber() ? d.GetNumberAsDouble() : std::nan("");
            // The schema's exclusiveMinimum is 0; +infinity (a 1e39 that overflows the
            // float) is the default itself: no attenuation.
            if (dist > 0.0) {
                v.attenuation_distance = static_cast<float>(dist);
            } else {
                ctx.warn(w + ".attenuationDistance: " +
                         (d.IsNumber() ? number_text(dist) : std::string("not a number")) +
                         " is not a positive distance; no attenuation (infinity) is used");
            }
        }
        v.attenuation_color = checked_color(ctx, *e, "attenuationColor", glm::vec3(1.0f), 1.0f, w);
        // Volume describes what lies under a surface that lets light through: without
        // transmission or diffuse transmission there is nothing to attenuate.
        if (!m.transmission && !m.diffuse_transmission)
            ctx.warn(w + ": the material has neither KHR_materials_transmission nor "
                         "KHR_materials_diffuse_transmission; the volume is not drawn");
        else
            m.volume = v;
    }
    if (const tinygltf::Value* e = find(extensions, "KHR_materials_dispersion")) {
        const std::string w = ext + "KHR_materials_dispersion";
        const float dispersion = checked_number(ctx, *e, "dispersion", 0.0f, 0.0f, kInfinity, w);
        if (!m.volume)
            ctx.warn(w + ": the material has no drawn KHR_materials_volume (dispersion applies "
                         "to refraction through a volume); not drawn");
        else
            m.dispersion = dispersion;
    }
}

} // namespace sherpa::scene::detail
