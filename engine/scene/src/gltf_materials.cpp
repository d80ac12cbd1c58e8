// glTF samplers, images, textures and materials -> engine records.
#include "accessor_reader.h"
#include "gltf_material_layers.h"
#include "gltf_material_values.h"
#include "import_context.h"
#include "import_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {
namespace {

float number_or(const tinygltf::Value& obj, const char* key, float fallback) {
    if (!obj.IsObject() || !obj.Has(key)) return fallback;
    const auto& v = obj.Get(key);
    return v.IsNumber() ? static_cast<float>(v.GetNumberAsDouble()) : fallback;
}

glm::vec2 vec2_or(const tinygltf::Value& obj, const char* key, glm::vec2 fallback) {
    if (!obj.IsObject() || !obj.Has(key)) return fallback;
    const auto& v = obj.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
        return fallback;
    return {static_cast<float>(v.Get(0).GetNumberAsDouble()),
            static_cast<float>(v.Get(1).GetNumberAsDouble())};
}

TextureSlot read_slot(ImportContext& ctx, int index, int tex_coord,
                      const tinygltf::ExtensionMap& ext, const std::string& where,
                      TextureRole role) {
    TextureSlot slot;
    if (index < 0) return slot;
    if (static_cast<std::size_t>(index) >= ctx.scene.textures.size())
        fail(where + ".index: texture " + std::to_string(index) + " out of range (file has " +
             std::to_string(ctx.scene.textures.size()) + " textures)");
    if (tex_coord < 0) fail(where + ".texCoord: " + std::to_string(tex_coord) + " is negative");
    slot.texture = index;
    slot.tex_coord = static_cast<std::uint32_t>(tex_coord);
    if (const auto it = ext.find("KHR_texture_transform"); it != ext.end()) {
        const auto& t = it->second;
        slot.transform.present = true;
        slot.transform.offset = vec2_or(t, "offset", glm::vec2(0.0f));
        slot.transform.scale = vec2_or(t, "scale", glm::vec2(1.0f));
        slot.transform.rotation = number_or(t, "rotation", 0.0f);
        if (t.IsObject() && t.Has("texCoord") && t.Get("texCoord").IsNumber())
            slot.tex_coord =
                static_cast<std::uint32_t>(std::max(0, t.Get("texCoord").GetNumberAsInt()));
    }
    if (slot.tex_coord > 1)
        ctx.warn(where + ": uses TEXCOORD_" + std::to_string(slot.tex_coord) +
                 "; Sherpa keeps TEXCOORD_0 and TEXCOORD_1 only, so it samples with zero UVs");
    ctx.scene.textures[static_cast<std::size_t>(index)].roles |= role;
    return slot;
}

} // namespace

// A textureInfo inside an extension object (tinygltf leaves those as JSON values).
TextureSlot read_value_slot(ImportContext& ctx, const tinygltf::Value& info,
                            const std::string& where, TextureRole role) {
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsNumber()) {
        if (info.IsObject()) fail(where + ".index: required number is missing");
        return {};
    }
    tinygltf::ExtensionMap ext;
    if (info.Has("extensions") && info.Get("extensions").IsObject())
        for (const auto& key : info.Get("extensions").Keys())
            ext[key] = info.Get("extensions").Get(key);
    const int tex_coord = info.Has("texCoord") && info.Get("texCoord").IsNumber()
                              ? info.Get("texCoord").GetNumberAsInt()
                              : 0;
    return read_slot(ctx, info.Get("index").GetNumberAsInt(), tex_coord, ext, where, role);
}

glm::vec4 vec_or(const tinygltf::Value& obj, const char* key, glm::vec4 fallback, int n) {
    if (!obj.IsObject() || !obj.Has(key)) return fallback;
    const auto& v = obj.Get(key);
    if (!v.IsArray() || v.ArrayLen() != std::size_t(n)) return fallback;
    glm::vec4 out = fallback;
    for (int i = 0; i < n; ++i) {
        if (!v.Get(i).IsNumber()) return fallback;
        out[i] = static_cast<float>(v.Get(i).GetNumberAsDouble());
    }
    return out;
}

namespace {

// KHR_materials_pbrSpecularGlossiness: its diffuse replaces the base colour; the
// extension's defaults are those of its schema (all ones).
void read_specular_glossiness(ImportContext& ctx, const tinygltf::Value& e, MaterialInstance& m,
                              const std::string& where) {
    const std::string w = where + ".extensions.KHR_materials_pbrSpecularGlossiness";
    SpecularGlossiness sg;
    m.base_color_factor = vec_or(e, "diffuseFactor", glm::vec4(1.0f), 4);
    sg.specular_factor = glm::vec3(vec_or(e, "specularFactor", glm::vec4(1.0f), 3));
    sg.glossiness_factor = number_or(e, "glossinessFactor", 1.0f);
    if (!core::is_finite(glm::vec3(m.base_color_factor)) || !std::isfinite(m.base_color_factor.w) ||
        !core::is_finite(sg.specular_factor) || !std::isfinite(sg.glossiness_factor))
        fail(w + ": diffuseFactor, specularFactor and glossinessFactor must be finite");
    m.base_color = e.Has("diffuseTexture") ? read_value_slot(ctx, e.Get("diffuseTexture"),
                                                             w + ".diffuseTexture", kRoleColor)
                                           : TextureSlot{};
    if (e.Has("specularGlossinessTexture"))
        sg.specular_glossiness = read_value_slot(ctx, e.Get("specularGlossinessTexture"),
                                                 w + ".specularGlossinessTexture", kRoleColor);
    m.specular_glossiness = sg;
}

// KHR_materials_ior: ior >= 1, or exactly 0 (F0 = 1: the specular-glossiness
// conversion). Anything else (negative, between 0 and 1, NaN, infinite, not a number)
// is a warning and the extension's default, 1.5, is drawn.
float read_ior(ImportContext& ctx, const tinygltf::Value& e, const std::string& where) {
    const std::string w = where + ".extensions.KHR_materials_ior.ior";
    if (!e.IsObject() || !e.Has("ior")) return kDefaultIor;
    const tinygltf::Value& v = e.Get("ior");
    const double ior = v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
    // Checked as the float the GPU gets (1e39 is a finite double but an infinite float).
    const float f = static_cast<float>(ior);
    if (std::isfinite(f) && (f >= 1.0f || f == 0.0f)) return f;
    ctx.warn(w + ": " + (v.IsNumber() ? number_text(ior) : std::string("not a number")) +
             " is not an index of refraction (>= 1, or 0); 1.5 is used");
    return kDefaultIor;
}

// KHR_materials_specular. Factors outside their range are warned and clamped (specular
// to 0..1, each colour component to >= 0); NaN or infinite ones take the default.
MaterialSpecular read_specular(ImportContext& ctx, const tinygltf::Value& e,
                               const std::string& where) {
    const std::string w = where + ".extensions.KHR_materials_specular";
    MaterialSpecular s;
    const double nan = std::nan("");
    const auto number = [&](const char* key, double fallback) {
        if (!e.IsObject() || !e.Has(key)) return fallback;
        const tinygltf::Value& v = e.Get(key);
        return v.IsNumber() ? v.GetNumberAsDouble() : nan;
    };
    const double factor = number("specularFactor", 1.0);
    if (!std::isfinite(static_cast<float>(factor))) {
        ctx.warn(w + ".specularFactor: not a finite number; the default 1 is used");
    } else if (factor < 0.0 || factor > 1.0) {
        s.specular_factor = static_cast<float>(std::clamp(factor, 0.0, 1.0));
        ctx.warn(w + ".specularFactor: " + number_text(factor) + " is outside 0..1; clamped to " +
                 number_text(s.specular_factor));
    } else {
        s.specular_factor = static_cast<float>(factor);
    }
    if (e.IsObject() && e.Has("specularColorFactor")) {
        const glm::vec4 c = vec_or(e, "specularColorFactor", glm::vec4(nan), 3);
        if (!core::is_finite(glm::vec3(c))) {
            ctx.warn(w + ".specularColorFactor: not three finite numbers; the default [1, 1, 1] "
                         "is used");
        } else if (glm::any(glm::lessThan(glm::vec3(c), glm::vec3(0.0f)))) {
            s.specular_color_factor = glm::max(glm::vec3(c), glm::vec3(0.0f));
            ctx.warn(w + ".specularColorFactor: negative components are clamped to 0");
        } else {
            s.specular_color_factor = glm::vec3(c);
        }
    }
    if (e.IsObject() && e.Has("specularTexture"))
        s.specular =
            read_value_slot(ctx, e.Get("specularTexture"), w + ".specularTexture", kRoleLinear);
    if (e.IsObject() && e.Has("specularColorTexture"))
        s.specular_color = read_value_slot(ctx, e.Get("specularColorTexture"),
                                           w + ".specularColorTexture", kRoleColor);
    return s;
}

AlphaMode parse_alpha_mode(const std::string& s, const std::string& where) {
    if (s.empty() || s == "OPAQUE") return AlphaMode::Opaque;
    if (s == "MASK") return AlphaMode::Mask;
    if (s == "BLEND") return AlphaMode::Blend;
    fail(where + ".alphaMode: \"" + s + "\" is not OPAQUE, MASK or BLEND");
}

// normalTexture.scale multiplies the sampled normal's XY before normalisation: past
// about 1000 the result no longer changes, while 1e30 overflows to a black surface.
constexpr float kMaxNormalScale = 1000.0f;
// Emitted radiance beyond this is warned about (the path tracer's sample cap).
constexpr float kMaxEmissiveRadiance = 1e20f;

// Factors JSON can state but shading cannot use (1e39 reads as infinity, a huge
// normal scale overflows): reset or clamped, with a warning naming the property.
void check_factors(ImportContext& ctx, MaterialInstance& m, const std::string& where) {
    const MaterialInstance defaults;
    auto reset = [&](bool bad, auto& value, const auto& fallback, const char* name) {
        if (!bad) return;
        value = fallback;
        ctx.warn(where + "." + name + ": not finite; the glTF default is used");
    };
    reset(!core::is_finite(glm::vec3(m.base_color_factor)) || !std::isfinite(m.base_color_factor.w),
          m.base_color_factor, defaults.base_color_factor, "pbrMetallicRoughness.baseColorFactor");
    reset(!core::is_finite(m.emissive_factor), m.emissive_factor, defaults.emissive_factor,
          "emissiveFactor");
    reset(!std::isfinite(m.metallic_factor), m.metallic_factor, defaults.metallic_factor,
          "pbrMetallicRoughness.metallicFactor");
    reset(!std::isfinite(m.roughness_factor), m.roughness_factor, defaults.roughness_factor,
          "pbrMetallicRoughness.roughnessFactor");
    reset(!std::isfinite(m.occlusion_strength), m.occlusion_strength, defaults.occlusion_strength,
          "occlusionTexture.strength");
    reset(!std::isfinite(m.emissive_strength), m.emissive_strength, defaults.emissive_strength,
          "extensions.KHR_materials_emissive_strength.emissiveStrength");
    // Kept as written, but said: no renderer can sum radiance this large (the path
    // tracer caps a sample's luminance at kMaxEmissiveRadiance and samples no light
    // beyond it).
    const float peak = std::max({m.emissive_factor.r, m.emissive_factor.g, m.emissive_factor.b});
    if (peak > 0.0f && !(peak * m.emissive_strength <= kMaxEmissiveRadiance))
        ctx.warn(where + ".extensions.KHR_materials_emissive_strength.emissiveStrength: " +
                 number_text(m.emissive_strength) + " makes emission beyond " +
                 number_text(kMaxEmissiveRadiance) +
                 ", more than a renderer can sum; the path tracer caps it there");
    if (!std::isfinite(m.normal_scale) || std::abs(m.normal_scale) > kMaxNormalScale) {
        const float clamped = std::isnan(m.normal_scale)
                                  ? 1.0f
                                  : std::clamp(m.normal_scale, -kMaxNormalScale, kMaxNormalScale);
        ctx.warn(where + ".normalTexture.scale: " + number_text(m.normal_scale) +
                 " would overflow shading; clamped to " + number_text(clamped));
        m.normal_scale = clamped;
    }
}

} // namespace

std::uint32_t ImportContext::default_material_id() {
    if (default_material < 0) {
        MaterialInstance m;
        m.name = "sherpa:default";
        default_material = static_cast<std::int32_t>(scene.materials.size());
        scene.materials.push_back(m);
    }
    return static_cast<std::uint32_t>(default_material);
}

namespace {

// The image a texture shows: an image extension's source (KHR_texture_basisu: KTX2,
// EXT_texture_webp: WebP; both decoded by the texture pipeline) when the texture
// names one, else the core `source`, which is then the fallback for viewers without
// the extension. Every index is range-checked.
int texture_source(const tinygltf::Texture& t, std::size_t images, const std::string& where) {
    const auto check = [&](int index, const std::string& at) {
        if (index >= static_cast<int>(images))
            fail(at + ": image " + std::to_string(index) + " out of range (file has " +
                 std::to_string(images) + " images)");
        return index;
    };
    check(t.source, where + ".source");
    for (const char* ext : {"KHR_texture_basisu", "EXT_texture_webp"}) {
        const auto it = t.extensions.find(ext);
        if (it == t.extensions.end() || !it->second.Has("source")) continue;
        const tinygltf::Value& v = it->second.Get("source");
        if (!v.IsNumber() || v.GetNumberAsInt() < 0)
            fail(where + ".extensions." + ext + ".source: not an image index");
        return check(v.GetNumberAsInt(), where + ".extensions." + ext + ".source");
    }
    return t.source;
}

} // namespace

void import_samplers_images_textures(ImportContext& ctx) {
    const auto& model = ctx.model;
    Scene& scene = ctx.scene;
    for (std::size_t i = 0; i < model.samplers.size(); ++i) {
        const auto& s = model.samplers[i];
        // A value out of its list (the validator's VALUE_NOT_IN_LIST warning) is read as
        // unspecified: the sampler and its textures are still shown, and the note says so.
        auto listed = [&](int value, std::initializer_list<int> allowed, const char* field,
                          const char* instead) {
            if (value == -1) return 0; // tinygltf's "absent": unspecified
            for (int a : allowed)
                if (value == a) return value;
            ctx.warn("samplers[" + std::to_string(i) + "]." + field + ": " + std::to_string(value) +
                     " is not a " + field + " value; " + instead + " is used");
            return 0;
        };
        scene.samplers.push_back(
            sampler_from_gltf(listed(s.magFilter, {9728, 9729}, "magFilter", "linear filtering"),
                              listed(s.minFilter, {9728, 9729, 9984, 9985, 9986, 9987}, "minFilter",
                                     "trilinear filtering"),
                              listed(s.wrapS, {33071, 33648, 10497}, "wrapS", "repeat"),
                              listed(s.wrapT, {33071, 33648, 10497}, "wrapT", "repeat")));
    }
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        const auto& img = model.images[i];
        ImageRecord rec;
        rec.name = img.name;
        rec.uri = img.uri.rfind("data:", 0) == 0 ? img.uri.substr(0, img.uri.find(',')) + ",..."
                                                 : img.uri;
        rec.buffer_view = img.bufferView;
        rec.mime_type = img.mimeType;
        if (img.bufferView >= static_cast<int>(model.bufferViews.size()))
            fail("images[" + std::to_string(i) + "].bufferView: index " +
                 std::to_string(img.bufferView) + " out of range");
        // The custom image loader (gltf_import.cpp) stored the encoded bytes of URIs
        // undecoded; bufferView bytes are taken here, range-checked.
        if (img.bufferView >= 0) {
            const auto view =
                buffer_view_bytes(model, img.bufferView, "images[" + std::to_string(i) + "]");
            rec.encoded.assign(view.begin(), view.end());
        } else {
            rec.encoded = img.image;
        }
        rec.byte_size = rec.encoded.size();
        if (rec.mime_type.empty()) {
            const auto dot = img.uri.rfind('.');
            const std::string ext = dot == std::string::npos ? "" : img.uri.substr(dot + 1);
            if (ext == "png")
                rec.mime_type = "image/png";
            else if (ext == "jpg" || ext == "jpeg")
                rec.mime_type = "image/jpeg";
            else if (ext == "webp")
                rec.mime_type = "image/webp";
            else if (ext == "ktx2")
                rec.mime_type = "image/ktx2";
            else if (img.uri.rfind("data:image/", 0) == 0)
                rec.mime_type = img.uri.substr(5, img.uri.find(';') - 5);
        }
        scene.images.push_back(std::move(rec));
    }
    for (std::size_t i = 0; i < model.textures.size(); ++i) {
        const auto& t = model.textures[i];
        const std::string where = "textures[" + std::to_string(i) + "]";
        TextureRecord rec;
        rec.name = t.name;
        const int source = texture_source(t, model.images.size(), where);
        if (t.sampler >= static_cast<int>(model.samplers.size()))
            fail(where + ".sampler: " + std::to_string(t.sampler) + " out of range (file has " +
                 std::to_string(model.samplers.size()) + " samplers)");
        if (source < 0)
            ctx.warn(where + ": no image source; materials using it read default textures");
        rec.image = source;
        rec.sampler = t.sampler;
        scene.textures.push_back(std::move(rec));
    }
    scene.counts.samplers = model.samplers.size();
    scene.counts.images = model.images.size();
    scene.counts.textures = model.textures.size();
}

void import_material(ImportContext& ctx, std::size_t i);

void import_materials(ImportContext& ctx) {
    const auto& model = ctx.model;
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        try {
            import_material(ctx, i);
        } catch (const ImportError& e) { // shown with the default material's values
            MaterialInstance m;
            m.name = model.materials[i].name;
            m.gltf_index = static_cast<std::int32_t>(i);
            ctx.scene.materials.push_back(std::move(m));
            ctx.skip("SHERPA_MATERIAL_DEFAULTED",
                     std::string(e.what()) + " (default material values used)");
        }
    }
    ctx.scene.counts.materials = model.materials.size();
}

void import_material(ImportContext& ctx, std::size_t i) {
    const auto& model = ctx.model;
    {
        const auto& src = model.materials[i];
        const std::string where = "materials[" + std::to_string(i) + "]";
        MaterialInstance m;
        m.name = src.name;
        m.gltf_index = static_cast<std::int32_t>(i);
        const auto& pbr = src.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            m.base_color_factor = {pbr.baseColorFactor[0], pbr.baseColorFactor[1],
                                   pbr.baseColorFactor[2], pbr.baseColorFactor[3]};
        if (src.emissiveFactor.size() == 3)
            m.emissive_factor = {src.emissiveFactor[0], src.emissiveFactor[1],
                                 src.emissiveFactor[2]};
        m.metallic_factor = static_cast<float>(pbr.metallicFactor);
        m.roughness_factor = static_cast<float>(pbr.roughnessFactor);
        m.normal_scale = static_cast<float>(src.normalTexture.scale);
        m.occlusion_strength = static_cast<float>(src.occlusionTexture.strength);
        m.alpha_cutoff = static_cast<float>(src.alphaCutoff);
        m.alpha_mode = parse_alpha_mode(src.alphaMode, where);
        m.double_sided = src.doubleSided;
        if (const auto it = src.extensions.find("KHR_materials_emissive_strength");
            it != src.extensions.end())
            m.emissive_strength = number_or(it->second, "emissiveStrength", 1.0f);
        check_factors(ctx, m, where); // after every factor it checks is read
        m.unlit = src.extensions.count("KHR_materials_unlit") != 0;
        for (const auto& entry : src.extensions) m.extensions.push_back(entry.first); // sorted
        m.base_color = read_slot(ctx, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                 pbr.baseColorTexture.extensions,
                                 where + ".pbrMetallicRoughness.baseColorTexture", kRoleColor);
        m.metallic_roughness = read_slot(
            ctx, pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
            pbr.metallicRoughnessTexture.extensions,
            where + ".pbrMetallicRoughness.metallicRoughnessTexture", kRoleLinear);
        m.normal = read_slot(ctx, src.normalTexture.index, src.normalTexture.texCoord,
                             src.normalTexture.extensions, where + ".normalTexture", kRoleNormal);
        m.occlusion =
            read_slot(ctx, src.occlusionTexture.index, src.occlusionTexture.texCoord,
                      src.occlusionTexture.extensions, where + ".occlusionTexture", kRoleLinear);
        m.emissive =
            read_slot(ctx, src.emissiveTexture.index, src.emissiveTexture.texCoord,
                      src.emissiveTexture.extensions, where + ".emissiveTexture", kRoleColor);
        if (const auto it = src.extensions.find("KHR_materials_pbrSpecularGlossiness");
            it != src.extensions.end())
            read_specular_glossiness(ctx, it->second, m, where);
        if (const auto it = src.extensions.find("KHR_materials_ior"); it != src.extensions.end())
            m.ior = read_ior(ctx, it->second, where);
        if (const auto it = src.extensions.find("KHR_materials_specular");
            it != src.extensions.end())
            m.specular = read_specular(ctx, it->second, where);
        read_volume_extensions(ctx, src.extensions, m, where);
        if (const auto it = src.extensions.find("KHR_materials_clearcoat");
            it != src.extensions.end())
            m.clearcoat = read_clearcoat(ctx, it->second, where);
        if (const auto it = src.extensions.find("KHR_materials_sheen"); it != src.extensions.end())
            m.sheen = read_sheen(ctx, it->second, where);
        if (const auto it = src.extensions.find("KHR_materials_anisotropy");
            it != src.extensions.end())
            m.anisotropy = read_anisotropy(ctx, it->second, where);
        if (const auto it = src.extensions.find("KHR_materials_iridescence");
            it != src.extensions.end())
            m.iridescence = read_iridescence(ctx, it->second, where);
        ctx.scene.materials.push_back(std::move(m));
    }
}

} // namespace sherpa::scene::detail
