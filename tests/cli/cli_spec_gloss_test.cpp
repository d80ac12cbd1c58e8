// KHR_materials_pbrSpecularGlossiness: imported with its own fields and shaded by its
// own definition (F0 = specular, roughness = 1 - glossiness, diffuse reflectance =
// diffuse x (1 - max(specular))). No sample model with the extension is in the shared
// assets, so the renders are checked against the identities the two extensions'
// definitions imply, on Suzanne: a dielectric metallic-roughness material (F0 0.04,
// diffuse = base colour) equals spec-gloss with specular 0.04 and diffuse = base /
// 0.96, and a metal (F0 = base colour, no diffuse) equals spec-gloss with specular =
// base colour and no diffuse; a spec-gloss material read as its metal-rough fallback,
// or with the diffuse not scaled by 1 - max(specular), does not match. The
// specularGlossinessTexture is checked the same way against the factor-only material
// its texel and factors multiply to, and the debug views against values computed here.
#include "cli/cli_run.h"
#include "test_support.h"

#include <sherpa/render/debug_views.h>
#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/image.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;
using json = nlohmann::json;

const fs::path& work_dir() {
    static const fs::path dir = [] {
        const fs::path d =
            fs::temp_directory_path() / ("sherpa_specgloss_" + std::to_string(getpid()));
        fs::create_directories(d);
        fs::copy_file(test::assets_dir() / "gltf" / "Suzanne" / "glTF" / "Suzanne.bin",
                      d / "Suzanne.bin", fs::copy_options::overwrite_existing);
        return d;
    }();
    return dir;
}

// Suzanne with one material and no textures.
std::string suzanne_with(const std::string& name, const json& material, bool spec_gloss) {
    json doc = test::read_json(test::gltf_asset("Suzanne"));
    doc.erase("textures");
    doc.erase("images");
    doc.erase("samplers");
    doc["materials"] = json::array({material});
    if (spec_gloss) doc["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
    const fs::path out = work_dir() / name;
    std::ofstream(out) << doc.dump();
    return out.string();
}

json metal_rough(glm::vec3 base, float metallic, float roughness) {
    return {{"pbrMetallicRoughness",
             {{"baseColorFactor", {base.r, base.g, base.b, 1.0}},
              {"metallicFactor", metallic},
              {"roughnessFactor", roughness}}}};
}

// The fallback metal-rough fields say a grey plastic: a renderer that ignores the
// extension draws that instead.
json spec_gloss(glm::vec3 diffuse, glm::vec3 specular, float glossiness) {
    json m = metal_rough(glm::vec3(0.5f), 0.0f, 1.0f);
    m["extensions"]["KHR_materials_pbrSpecularGlossiness"] = {
        {"diffuseFactor", {diffuse.r, diffuse.g, diffuse.b, 1.0}},
        {"specularFactor", {specular.r, specular.g, specular.b}},
        {"glossinessFactor", glossiness}};
    return m;
}

// RGBA8 (--no-bc, no cache): the texels are sampled as written.
std::vector<std::uint8_t> render(const std::string& scene, const std::string& extra = "") {
    const std::string png = scene + extra.substr(extra.find_last_of(' ') + 1) + ".png";
    const test::CliRun r = test::run_cli("render '" + scene + "' -o '" + png +
                                         "' --width 96 --height 96 --validation --no-bc"
                                         " --no-cache --camera eye=0.6,0.8,3:target=0,0,0:fov=40 " +
                                         extra);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    std::uint32_t w = 0, h = 0;
    std::vector<std::uint8_t> rgba;
    std::string error;
    EXPECT_TRUE(sherpa::tex::read_png_rgba8(png, w, h, rgba, error)) << error;
    return rgba;
}

int max_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    if (a.size() != b.size() || a.empty()) return 256;
    int worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

TEST(SpecularGlossiness, ImportedWithItsOwnFields) {
    json m = spec_gloss({0.2f, 0.4f, 0.6f}, {0.1f, 0.2f, 0.3f}, 0.7f);
    const sherpa::scene::LoadResult r =
        sherpa::scene::load_scene(suzanne_with("fields.gltf", m, true));
    ASSERT_TRUE(r) << r.error;
    const sherpa::scene::MaterialInstance& mat = r.scene->materials.at(0);
    ASSERT_TRUE(mat.specular_glossiness);
    EXPECT_EQ(mat.base_color_factor, glm::vec4(0.2f, 0.4f, 0.6f, 1.0f)) << "diffuseFactor";
    EXPECT_EQ(mat.specular_glossiness->specular_factor, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_FLOAT_EQ(mat.specular_glossiness->glossiness_factor, 0.7f);
    // The extension's schema defaults are ones.
    m["extensions"]["KHR_materials_pbrSpecularGlossiness"] = json::object();
    const sherpa::scene::LoadResult d =
        sherpa::scene::load_scene(suzanne_with("defaults.gltf", m, true));
    ASSERT_TRUE(d) << d.error;
    EXPECT_EQ(d.scene->materials.at(0).base_color_factor, glm::vec4(1.0f));
    EXPECT_EQ(d.scene->materials.at(0).specular_glossiness->specular_factor, glm::vec3(1.0f));
    // Required, it is supported (it was refused before).
    json doc = test::read_json(suzanne_with("required.gltf", m, true));
    doc["extensionsRequired"] = {"KHR_materials_pbrSpecularGlossiness"};
    std::ofstream(work_dir() / "required.gltf") << doc.dump();
    EXPECT_TRUE(sherpa::scene::load_scene((work_dir() / "required.gltf").string()));
}

TEST(SpecularGlossiness, ShadedByItsDefinition) {
    const glm::vec3 base(0.5f, 0.3f, 0.2f);
    for (const float roughness : {0.35f, 0.8f}) {
        const std::string r = std::to_string(int(roughness * 100));
        // Dielectric: F0 0.04 and diffuse reflectance base.
        const auto mr =
            render(suzanne_with("mr_d" + r + ".gltf", metal_rough(base, 0, roughness), false));
        const auto sg = render(suzanne_with(
            "sg_d" + r + ".gltf", spec_gloss(base / 0.96f, glm::vec3(0.04f), 1 - roughness), true));
        EXPECT_LE(max_difference(mr, sg), 1) << "dielectric, roughness " << roughness;
        // Without the 1 - max(specular) scaling the diffuse is 4% brighter: visible.
        const auto unscaled = render(suzanne_with(
            "sg_u" + r + ".gltf", spec_gloss(base, glm::vec3(0.04f), 1 - roughness), true));
        EXPECT_GE(max_difference(mr, unscaled), 3) << "the test tells the two apart";
        // Metal: F0 = base colour, no diffuse.
        const auto metal =
            render(suzanne_with("mr_m" + r + ".gltf", metal_rough(base, 1, roughness), false));
        const auto sg_metal = render(suzanne_with(
            "sg_m" + r + ".gltf", spec_gloss(glm::vec3(0.7f), base, 1 - roughness), true));
        // diffuse 0.7 x (1 - max(specular) = 0.5) still adds light: use no diffuse.
        const auto sg_metal_black = render(suzanne_with(
            "sg_mb" + r + ".gltf", spec_gloss(glm::vec3(0.0f), base, 1 - roughness), true));
        EXPECT_LE(max_difference(metal, sg_metal_black), 1) << "metal, roughness " << roughness;
        EXPECT_GE(max_difference(metal, sg_metal), 3);
    }
}

// A uniform 8x8 specular-glossiness texture: sRGB specular, linear glossiness in alpha.
constexpr std::uint8_t kTexel[4] = {200, 150, 90, 153};

float srgb_to_linear(std::uint8_t v) {
    const float c = float(v) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// Spec-gloss material whose specular and glossiness are the factors times kTexel.
std::string spec_gloss_textured(const std::string& name, glm::vec3 diffuse,
                                glm::vec3 specular_factor, float glossiness_factor) {
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < 64; ++i) rgba.insert(rgba.end(), kTexel, kTexel + 4);
    std::string error;
    EXPECT_TRUE(sherpa::tex::write_png((work_dir() / "sg_texel.png").string(), 8, 8, rgba, error))
        << error;
    json m = spec_gloss(diffuse, specular_factor, glossiness_factor);
    m["extensions"]["KHR_materials_pbrSpecularGlossiness"]["specularGlossinessTexture"] = {
        {"index", 0}};
    const std::string path = suzanne_with(name, m, true);
    json doc = test::read_json(path);
    doc["images"] = {{{"uri", "sg_texel.png"}}};
    doc["textures"] = {{{"source", 0}}};
    std::ofstream(path) << doc.dump();
    return path;
}

TEST(SpecularGlossiness, TextureMultipliesTheFactors) {
    const glm::vec3 diffuse(0.3f, 0.2f, 0.1f);
    const glm::vec3 texel_specular(srgb_to_linear(kTexel[0]), srgb_to_linear(kTexel[1]),
                                   srgb_to_linear(kTexel[2]));
    const float texel_glossiness = kTexel[3] / 255.0f;
    const glm::vec3 specular_factor(0.5f, 0.8f, 1.0f);
    for (const float glossiness_factor : {1.0f, 0.5f}) {
        const std::string g = std::to_string(int(glossiness_factor * 10));
        const auto textured = render(
            spec_gloss_textured("sgt" + g + ".gltf", diffuse, specular_factor, glossiness_factor));
        const auto factors =
            render(suzanne_with("sgf" + g + ".gltf",
                                spec_gloss(diffuse, specular_factor * texel_specular,
                                           glossiness_factor * texel_glossiness),
                                true));
        EXPECT_LE(max_difference(textured, factors), 1)
            << "glossiness factor " << glossiness_factor;
        // The texture read as linear (no sRGB decode) gives a visibly different image,
        // and so does the texture ignored.
        const auto linear = render(suzanne_with(
            "sgl" + g + ".gltf",
            spec_gloss(diffuse,
                       specular_factor * glm::vec3(kTexel[0], kTexel[1], kTexel[2]) / 255.0f,
                       glossiness_factor * texel_glossiness),
            true));
        EXPECT_GE(max_difference(textured, linear), 3) << "the test tells the two apart";
        const auto untextured = render(suzanne_with(
            "sgu" + g + ".gltf", spec_gloss(diffuse, specular_factor, glossiness_factor), true));
        EXPECT_GE(max_difference(textured, untextured), 3);
    }
}

// Every pixel of a data view is either the background (the corner's) or `expected`
// (an 8-bit value per channel, within 1); the object covers a good part of the image.
void expect_object_pixels(const std::vector<std::uint8_t>& rgba, glm::vec3 expected,
                          const std::string& what) {
    ASSERT_EQ(rgba.size(), 96u * 96u * 4u) << what;
    const glm::ivec3 want = glm::round(expected * 255.0f);
    int object = 0, other = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        const bool background = std::equal(&rgba[i], &rgba[i + 3], &rgba[0]);
        bool match = true;
        for (int c = 0; c < 3; ++c)
            match = match && std::abs(rgba[i + std::size_t(c)] - want[c]) <= 1;
        object += match;
        other += !match && !background;
    }
    EXPECT_GT(object, 96 * 96 / 5)
        << what << ": expected " << want.r << "," << want.g << "," << want.b;
    EXPECT_EQ(other, 0) << what << ": pixels that are neither background nor the expected value";
}

// The metallic and roughness views show what the shading uses: for spec-gloss, no
// metallic (the flag colour kSpecGlossFlagColor) and roughness 1 - glossiness; the
// specular view shows F0 for both workflows.
TEST(SpecularGlossiness, DebugViewsShowItsOwnFields) {
    const glm::vec3 specular_factor(0.5f, 0.8f, 1.0f);
    const glm::vec3 texel_specular(srgb_to_linear(kTexel[0]), srgb_to_linear(kTexel[1]),
                                   srgb_to_linear(kTexel[2]));
    const std::string sg =
        spec_gloss_textured("views.gltf", glm::vec3(0.3f), specular_factor, 0.5f);
    expect_object_pixels(render(sg, "--view roughness"),
                         glm::vec3(1.0f - 0.5f * kTexel[3] / 255.0f), "spec-gloss roughness");
    expect_object_pixels(render(sg, "--view specular"), specular_factor * texel_specular,
                         "spec-gloss specular");
    const auto& flag = sherpa::render::kSpecGlossFlagColor;
    expect_object_pixels(render(sg, "--view metallic"), glm::vec3(flag[0], flag[1], flag[2]),
                         "spec-gloss metallic");
    // Metal-rough: the views as before, and F0 = mix(0.04, base, metallic).
    const glm::vec3 base(0.5f, 0.3f, 0.2f);
    const std::string mr = suzanne_with("views_mr.gltf", metal_rough(base, 0.25f, 0.6f), false);
    expect_object_pixels(render(mr, "--view roughness"), glm::vec3(0.6f), "metal-rough roughness");
    expect_object_pixels(render(mr, "--view metallic"), glm::vec3(0.25f), "metal-rough metallic");
    expect_object_pixels(render(mr, "--view specular"), glm::mix(glm::vec3(0.04f), base, 0.25f),
                         "metal-rough specular");
}

} // namespace
