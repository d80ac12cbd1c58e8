// Material extensions (KHR_materials_ior, _specular, _clearcoat, _sheen, _anisotropy,
// _iridescence): what the
// importer reads and warns about (bad values name their JSON pointer and fall back as
// docs/materials.md says), and the extension buffer's layout: only materials that use
// an extension get a block, a scene without any gets no bytes.
#include "gpu/material_extension_support.h"
#include "test_support.h"

#include <sherpa/render/material_extensions.h>
#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/scene/material_extension_slots.h>
#include <sherpa/scene/scene_loader.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace {

using namespace sherpa;

scene::LoadResult load_data(const std::string& name) {
    return scene::load_scene((test::data_dir() / name).string());
}

const scene::MaterialInstance& material(const scene::Scene& s, const std::string& name) {
    for (const scene::MaterialInstance& m : s.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return s.materials.front();
}

TEST(MaterialExtensions, IorAndSpecularAreDrawnNotWarnedAsMissing) {
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_ior"));
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_specular"));
    const scene::LoadResult r = load_data("material_sweeps/ior_sweep.gltf");
    ASSERT_TRUE(r) << r.error;
    for (const std::string& w : r.scene->warnings)
        EXPECT_EQ(w.find("not implemented"), std::string::npos) << w;
    ASSERT_EQ(r.scene->materials.size(), 10u);
    EXPECT_FLOAT_EQ(*r.scene->materials[0].ior, 1.0f);
    EXPECT_FLOAT_EQ(*r.scene->materials[4].ior, 2.33f);
    EXPECT_FALSE(r.scene->materials[0].specular.has_value());
}

TEST(MaterialExtensions, BadValuesAreWarnedWithTheirPointerAndFallBack) {
    const scene::LoadResult r = load_data("material_extensions_bad.gltf");
    ASSERT_TRUE(r) << r.error;
    const scene::Scene& s = *r.scene;
    // Negative, below 1, infinite (as a float) and non-number ior: warned, 1.5 drawn.
    for (int m : {0, 1, 2, 8}) {
        const std::string p =
            "/materials/" + std::to_string(m) + "/extensions/KHR_materials_ior/ior";
        EXPECT_NE(test::message_at(s, p), nullptr) << p;
        EXPECT_FLOAT_EQ(*s.materials[std::size_t(m)].ior, scene::kDefaultIor) << p;
    }
    // ior 0 is valid (F0 = 1): no message.
    EXPECT_EQ(test::message_at(s, "/materials/5/extensions/KHR_materials_ior/ior"), nullptr);
    EXPECT_FLOAT_EQ(*material(s, "ior zero").ior, 0.0f);
    // specularFactor 2 clamps to 1, -0.5 to 0; a non-finite colour takes [1, 1, 1], a
    // negative component clamps to 0.
    const std::string spec3 = "/materials/3/extensions/KHR_materials_specular/";
    EXPECT_NE(test::message_at(s, spec3 + "specularFactor"), nullptr);
    EXPECT_NE(test::message_at(s, spec3 + "specularColorFactor"), nullptr);
    EXPECT_FLOAT_EQ(material(s, "bad specular").specular->specular_factor, 1.0f);
    EXPECT_EQ(material(s, "bad specular").specular->specular_color_factor, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(material(s, "negative colour").specular->specular_factor, 0.0f);
    EXPECT_EQ(material(s, "negative colour").specular->specular_color_factor,
              glm::vec3(0.0f, 0.5f, 0.25f));
    EXPECT_NE(
        test::message_at(s, "/materials/4/extensions/KHR_materials_specular/specularColorFactor"),
        nullptr);
    // A texture index out of range: the material is drawn with default values, said.
    bool defaulted = false;
    for (const scene::ValidationMessage& m : s.validation.messages)
        defaulted |= m.code == "SHERPA_MATERIAL_DEFAULTED" &&
                     m.message.find("specularTexture") != std::string::npos;
    EXPECT_TRUE(defaulted);
    EXPECT_FALSE(s.materials[7].specular.has_value());
    // A missing image: the slot is kept (the texture pipeline warns and draws white).
    EXPECT_TRUE(material(s, "missing specular texture").specular->specular_color.present());
}

TEST(MaterialExtensions, OnlyMaterialsThatUseAnExtensionHaveBlocks) {
    const scene::LoadResult r = load_data("material_extensions_bad.gltf");
    ASSERT_TRUE(r) << r.error;
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    ASSERT_EQ(b.places.size(), r.scene->materials.size());
    std::size_t words = 0;
    for (std::size_t i = 0; i < b.places.size(); ++i) {
        const scene::MaterialInstance& m = r.scene->materials[i];
        const render::MaterialExtensionPlace& p = b.places[i];
        EXPECT_EQ(p.any(), m.ior.has_value() || m.specular.has_value() || m.clearcoat.has_value() ||
                               m.sheen.has_value() || m.anisotropy.has_value() ||
                               m.iridescence.has_value())
            << i;
        EXPECT_EQ(p.anisotropy != render::kNoExtension, m.anisotropy.has_value()) << i;
        EXPECT_EQ(p.iridescence != render::kNoExtension, m.iridescence.has_value()) << i;
        EXPECT_EQ(p.sheen != render::kNoExtension, m.sheen.has_value()) << i;
        EXPECT_EQ(p.ior != render::kNoExtension, m.ior.has_value()) << i;
        EXPECT_EQ(p.specular != render::kNoExtension, m.specular.has_value()) << i;
        EXPECT_EQ(p.clearcoat != render::kNoExtension, m.clearcoat.has_value()) << i;
        if (!p.any()) continue;
        words += 3 + (m.ior ? 1 : 0) + (m.specular ? 6 : 0) + (m.clearcoat ? 8 : 0) +
                 (m.sheen ? 6 : 0) + (m.anisotropy ? 4 : 0) + (m.iridescence ? 6 : 0);
        render::GPUExtensionIndex index;
        std::memcpy(&index, &b.words[p.index], sizeof index);
        EXPECT_EQ(index.ior, p.ior);
        EXPECT_EQ(index.specular, p.specular);
        EXPECT_EQ(index.clearcoat, p.clearcoat);
        EXPECT_EQ(index.sheen, p.sheen);
        EXPECT_EQ(index.anisotropy, p.anisotropy);
        EXPECT_EQ(index.iridescence, p.iridescence);
        if (m.ior) {
            render::GPUIorBlock ior;
            std::memcpy(&ior, &b.words[p.ior], sizeof ior);
            EXPECT_EQ(ior.ior, *m.ior);
        }
    }
    EXPECT_EQ(b.words.size(), words);
    // "missing specular texture" (material 6): its colour texture resolved through the
    // slot function, the specular texture white.
    render::GPUSpecularBlock spec;
    std::memcpy(&spec, &b.words[b.places[6].specular], sizeof spec);
    EXPECT_EQ(spec.specular_color_tex, 100u);
    EXPECT_EQ(spec.specular_tex, gpu::kWhiteTexture);
    EXPECT_EQ(spec.color_factor, glm::vec4(1.0f));
}

TEST(MaterialExtensions, ASceneWithoutExtensionsHasNoBytes) {
    const scene::LoadResult r = scene::load_scene(test::gltf_asset("DamagedHelmet"));
    ASSERT_TRUE(r) << r.error;
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    EXPECT_EQ(b.bytes(), 0u);
    for (const render::MaterialExtensionPlace& p : b.places) EXPECT_FALSE(p.any());
}

TEST(MaterialExtensions, AnIorOnlyMaterialPaysSixtyFourBytes) {
    const scene::LoadResult r = load_data("material_sweeps/ior_sweep.gltf");
    ASSERT_TRUE(r) << r.error;
    // Its 48-byte index (three words: GPUExtensionIndex) and its 16-byte block.
    EXPECT_EQ(test::extension_layout(*r.scene).bytes(), 10u * 64u);
}

TEST(MaterialExtensions, ClearcoatIsReadAndPacked) {
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_clearcoat"));
    const scene::LoadResult r = load_data("material_sweeps/clearcoat_textures.gltf");
    ASSERT_TRUE(r) << r.error;
    for (const std::string& w : r.scene->warnings)
        EXPECT_EQ(w.find("not implemented"), std::string::npos) << w;
    const scene::MaterialInstance& m = r.scene->materials.at(0);
    ASSERT_TRUE(m.clearcoat.has_value());
    EXPECT_FLOAT_EQ(m.clearcoat->factor, 1.0f);
    EXPECT_FLOAT_EQ(m.clearcoat->roughness_factor, 1.0f);
    EXPECT_EQ(m.clearcoat->clearcoat.texture, 0);
    EXPECT_TRUE(m.clearcoat->clearcoat.transform.present);
    EXPECT_EQ(m.clearcoat->normal.texture, 1);
    // The clearcoat normal map alone asks for tangents and the TEXCOORD_0 stream.
    EXPECT_TRUE(scene::reads_normal_map(m));
    ASSERT_EQ(scene::extension_texture_slots(m).size(), 3u);
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    EXPECT_EQ(b.bytes(), 48u + 128u);
    render::GPUClearcoatBlock c;
    std::memcpy(&c, &b.words[b.places[0].clearcoat], sizeof c);
    EXPECT_EQ(c.factors, glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
    EXPECT_EQ(c.clearcoat_tex, 100u);
    EXPECT_EQ(c.roughness_tex, 100u);
    EXPECT_EQ(c.normal_tex, 101u);
    EXPECT_FLOAT_EQ(c.clearcoat_uv.row0.z, 0.5f); // the offset, in the transform's rows
}

TEST(MaterialExtensions, BadClearcoatValuesAreWarnedAndFallBack) {
    const scene::LoadResult r = load_data("material_extensions_bad.gltf");
    ASSERT_TRUE(r) << r.error;
    const scene::Scene& s = *r.scene;
    const std::string cc9 = "/materials/9/extensions/KHR_materials_clearcoat/";
    const std::string cc10 = "/materials/10/extensions/KHR_materials_clearcoat/";
    // -0.5 clamps to 0; a string roughness takes the default 0.
    EXPECT_NE(test::message_at(s, cc9 + "clearcoatFactor"), nullptr);
    EXPECT_NE(test::message_at(s, cc9 + "clearcoatRoughnessFactor"), nullptr);
    EXPECT_FLOAT_EQ(material(s, "bad clearcoat").clearcoat->factor, 0.0f);
    EXPECT_FLOAT_EQ(material(s, "bad clearcoat").clearcoat->roughness_factor, 0.0f);
    // 2 clamps to 1; 1e39 (infinite as a float) roughness and normal scale: defaults.
    EXPECT_NE(test::message_at(s, cc10 + "clearcoatFactor"), nullptr);
    EXPECT_NE(test::message_at(s, cc10 + "clearcoatRoughnessFactor"), nullptr);
    EXPECT_NE(test::message_at(s, cc10 + "clearcoatNormalTexture/scale"), nullptr);
    const scene::MaterialClearcoat& c = *material(s, "clearcoat out of range").clearcoat;
    EXPECT_FLOAT_EQ(c.factor, 1.0f);
    EXPECT_FLOAT_EQ(c.roughness_factor, 0.0f);
    EXPECT_FLOAT_EQ(c.normal_scale, 1.0f);
}

} // namespace

namespace {

TEST(MaterialExtensions, SheenIsReadAndPacked) {
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_sheen"));
    const scene::LoadResult r = load_data("material_sweeps/sheen_textures.gltf");
    ASSERT_TRUE(r) << r.error;
    const scene::MaterialInstance& m = r.scene->materials.at(0);
    ASSERT_TRUE(m.sheen.has_value());
    EXPECT_EQ(m.sheen->color_factor, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(m.sheen->roughness_factor, 1.0f);
    EXPECT_EQ(m.sheen->color.texture, 0);
    EXPECT_TRUE(m.sheen->roughness.transform.present);
    EXPECT_EQ(scene::extension_texture_slots(m).size(), 2u);
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    EXPECT_EQ(b.bytes(), 48u + 96u);
    render::GPUSheenBlock s;
    std::memcpy(&s, &b.words[b.places[0].sheen], sizeof s);
    EXPECT_EQ(s.factors, glm::vec4(1.0f));
    EXPECT_EQ(s.color_tex, 100u);
    EXPECT_EQ(s.roughness_tex, 100u);
    EXPECT_FLOAT_EQ(s.color_uv.row0.z, 0.5f);
}

TEST(MaterialExtensions, BadSheenValuesAreWarnedAndFallBack) {
    const scene::LoadResult r = load_data("material_extensions_bad.gltf");
    ASSERT_TRUE(r) << r.error;
    const scene::Scene& s = *r.scene;
    const std::string at = "/materials/11/extensions/KHR_materials_sheen/";
    EXPECT_NE(test::message_at(s, at + "sheenColorFactor"), nullptr);
    EXPECT_NE(test::message_at(s, at + "sheenRoughnessFactor"), nullptr);
    const scene::MaterialSheen& sh = *material(s, "bad sheen").sheen;
    EXPECT_EQ(sh.color_factor, glm::vec3(1.0f, 0.0f, 0.5f));
    EXPECT_FLOAT_EQ(sh.roughness_factor, 0.0f);
}

TEST(MaterialExtensions, AnisotropyIsReadAndPackedAndAsksForTangents) {
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_anisotropy"));
    const scene::LoadResult r = load_data("material_sweeps/anisotropy_textures.gltf");
    ASSERT_TRUE(r) << r.error;
    for (const std::string& w : r.scene->warnings)
        EXPECT_EQ(w.find("not implemented"), std::string::npos) << w;
    const scene::MaterialInstance& m = r.scene->materials.at(0);
    ASSERT_TRUE(m.anisotropy.has_value());
    EXPECT_FLOAT_EQ(m.anisotropy->strength, 1.0f);
    EXPECT_FLOAT_EQ(m.anisotropy->rotation, 0.0f);
    EXPECT_EQ(m.anisotropy->texture.texture, 0);
    EXPECT_TRUE(m.anisotropy->texture.transform.present);
    // No normal map, yet the anisotropy's direction lies in the tangent frame: the
    // sphere keeps its authored TANGENT.
    EXPECT_FALSE(scene::reads_normal_map(m));
    EXPECT_TRUE(scene::needs_tangents(m));
    EXPECT_EQ(scene::tangent_uv_set(m), 0u);
    EXPECT_EQ(r.scene->meshes.at(0).provenance_of(scene::VertexAttribute::Tangent),
              scene::Provenance::Authored);
    ASSERT_EQ(scene::extension_texture_slots(m).size(), 1u);
    EXPECT_EQ(scene::extension_texture_slots(m)[0].role, scene::kRoleLinear);
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    EXPECT_EQ(b.bytes(), 48u + 64u);
    render::GPUAnisotropyBlock a;
    std::memcpy(&a, &b.words[b.places[0].anisotropy], sizeof a);
    EXPECT_EQ(a.factors, glm::vec4(1.0f, 1.0f, 0.0f, 0.0f));
    EXPECT_EQ(a.texture, 100u);
    EXPECT_FLOAT_EQ(a.uv.row0.z, 0.5f);
}

// The same sphere without its TANGENT: generated for the anisotropy, as for a normal map.
TEST(MaterialExtensions, AnisotropyWithoutAuthoredTangentsGeneratesThem) {
    std::ifstream in(test::data_dir() / "material_sweeps/anisotropy_textures.gltf");
    nlohmann::json doc = nlohmann::json::parse(in);
    doc["meshes"][0]["primitives"][0]["attributes"].erase("TANGENT");
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "sherpa_anisotropy_no_tangents.gltf";
    std::ofstream(path) << doc.dump();
    const scene::LoadResult r = scene::load_scene(path.string());
    std::filesystem::remove(path);
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->meshes.at(0).provenance_of(scene::VertexAttribute::Tangent),
              scene::Provenance::Generated);
}

TEST(MaterialExtensions, AnisotropyRotationIsStoredAsItsCosineAndSine) {
    const scene::LoadResult r = load_data("material_sweeps/anisotropy_sweep.gltf");
    ASSERT_TRUE(r) << r.error;
    ASSERT_EQ(r.scene->materials.size(), 10u);
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    EXPECT_EQ(b.bytes(), 10u * (48u + 64u));
    // Row 2: strength 0.8 at 0, 30, 60, 90 and 135 degrees.
    const float degrees[] = {0.0f, 30.0f, 60.0f, 90.0f, 135.0f};
    for (int i = 0; i < 5; ++i) {
        render::GPUAnisotropyBlock a;
        std::memcpy(&a, &b.words[b.places[std::size_t(5 + i)].anisotropy], sizeof a);
        const float rad = degrees[i] * 3.14159265f / 180.0f;
        EXPECT_FLOAT_EQ(a.factors.x, 0.8f) << i;
        EXPECT_NEAR(a.factors.y, std::cos(rad), 1e-6f) << i;
        EXPECT_NEAR(a.factors.z, std::sin(rad), 1e-6f) << i;
        EXPECT_EQ(a.texture, gpu::kWhiteTexture) << i;
    }
}

TEST(MaterialExtensions, BadAnisotropyValuesAreWarnedAndFallBack) {
    const scene::LoadResult r = load_data("material_extensions_bad.gltf");
    ASSERT_TRUE(r) << r.error;
    const scene::Scene& s = *r.scene;
    const std::string a12 = "/materials/12/extensions/KHR_materials_anisotropy/";
    const std::string a13 = "/materials/13/extensions/KHR_materials_anisotropy/";
    // 1.5 clamps to 1; a string rotation takes the default 0.
    EXPECT_NE(test::message_at(s, a12 + "anisotropyStrength"), nullptr);
    EXPECT_NE(test::message_at(s, a12 + "anisotropyRotation"), nullptr);
    EXPECT_FLOAT_EQ(material(s, "bad anisotropy").anisotropy->strength, 1.0f);
    EXPECT_FLOAT_EQ(material(s, "bad anisotropy").anisotropy->rotation, 0.0f);
    // -0.5 clamps to 0; 1e39 (infinite as a float) rotation: 0. Its texture's image is
    // missing: the texture pipeline's warning, the slot reads white.
    EXPECT_NE(test::message_at(s, a13 + "anisotropyStrength"), nullptr);
    EXPECT_NE(test::message_at(s, a13 + "anisotropyRotation"), nullptr);
    const scene::MaterialAnisotropy& a = *material(s, "anisotropy not finite").anisotropy;
    EXPECT_FLOAT_EQ(a.strength, 0.0f);
    EXPECT_FLOAT_EQ(a.rotation, 0.0f);
    EXPECT_EQ(a.texture.texture, 0);
}

TEST(MaterialExtensions, IridescenceIsReadAndPacked) {
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_iridescence"));
    const scene::LoadResult r = load_data("material_sweeps/iridescence_textures.gltf");
    ASSERT_TRUE(r) << r.error;
    for (const std::string& w : r.scene->warnings)
        EXPECT_EQ(w.find("not implemented"), std::string::npos) << w;
    const scene::MaterialInstance& m = r.scene->materials.at(0);
    ASSERT_TRUE(m.iridescence.has_value());
    EXPECT_FLOAT_EQ(m.iridescence->factor, 1.0f);
    EXPECT_FLOAT_EQ(m.iridescence->ior, 1.3f); // the default
    EXPECT_FLOAT_EQ(m.iridescence->thickness_minimum, 200.0f);
    EXPECT_FLOAT_EQ(m.iridescence->thickness_maximum, 600.0f);
    EXPECT_TRUE(m.iridescence->thickness.transform.present);
    EXPECT_FALSE(scene::needs_tangents(m));
    ASSERT_EQ(scene::extension_texture_slots(m).size(), 2u);
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    EXPECT_EQ(b.bytes(), 48u + 96u);
    render::GPUIridescenceBlock i;
    std::memcpy(&i, &b.words[b.places[0].iridescence], sizeof i);
    EXPECT_EQ(i.factors, glm::vec4(1.0f, 1.3f, 200.0f, 600.0f));
    EXPECT_EQ(i.texture, 100u);
    EXPECT_EQ(i.thickness_tex, 100u);
    EXPECT_FLOAT_EQ(i.thickness_uv.row0.z, 0.5f);
}

TEST(MaterialExtensions, BadIridescenceValuesAreWarnedAndFallBack) {
    const scene::LoadResult r = load_data("material_extensions_bad.gltf");
    ASSERT_TRUE(r) << r.error;
    const scene::Scene& s = *r.scene;
    const std::string i14 = "/materials/14/extensions/KHR_materials_iridescence/";
    const std::string i15 = "/materials/15/extensions/KHR_materials_iridescence/";
    // 1.5 clamps to 1; an ior below 1 takes the default 1.3; -10 nm clamps to 0.
    EXPECT_NE(test::message_at(s, i14 + "iridescenceFactor"), nullptr);
    EXPECT_NE(test::message_at(s, i14 + "iridescenceIor"), nullptr);
    EXPECT_NE(test::message_at(s, i14 + "iridescenceThicknessMinimum"), nullptr);
    const scene::MaterialIridescence& a = *material(s, "bad iridescence").iridescence;
    EXPECT_FLOAT_EQ(a.factor, 1.0f);
    EXPECT_FLOAT_EQ(a.ior, 1.3f);
    EXPECT_FLOAT_EQ(a.thickness_minimum, 0.0f);
    // A string factor: 0; 1e39 (infinite as a float) ior and maximum: their defaults.
    EXPECT_NE(test::message_at(s, i15 + "iridescenceFactor"), nullptr);
    EXPECT_NE(test::message_at(s, i15 + "iridescenceIor"), nullptr);
    EXPECT_NE(test::message_at(s, i15 + "iridescenceThicknessMaximum"), nullptr);
    const scene::MaterialIridescence& b = *material(s, "iridescence not finite").iridescence;
    EXPECT_FLOAT_EQ(b.factor, 0.0f);
    EXPECT_FLOAT_EQ(b.ior, 1.3f);
    EXPECT_FLOAT_EQ(b.thickness_maximum, 400.0f);
}

} // namespace
