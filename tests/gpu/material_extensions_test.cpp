// Material extensions (KHR_materials_ior, KHR_materials_specular): what the importer
// reads and warns about (bad values name their JSON pointer and fall back as
// docs/materials.md says), and the extension buffer's layout: only materials that use
// an extension get a block, a scene without any gets no bytes.
#include "test_support.h"

#include <sherpa/render/material_extensions.h>
#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/scene/scene_loader.h>

#include <cstring>

#include <gtest/gtest.h>

namespace {

using namespace sherpa;

LoadResult load_data(const std::string& name) {
    return load_scene((test::data_dir() / name).string());
}

const ValidationMessage* message_at(const Scene& s, const std::string& pointer) {
    for (const ValidationMessage& m : s.validation.messages)
        if (m.pointer == pointer) return &m;
    return nullptr;
}

const MaterialInstance& material(const Scene& s, const std::string& name) {
    for (const MaterialInstance& m : s.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return s.materials.front();
}

gpu::MaterialExtensionBuffer layout(const Scene& s) {
    return gpu::build_material_extensions(s.materials, [](const TextureSlot& slot, TextureRole) {
        return slot.present() ? 100u + std::uint32_t(slot.texture) : gpu::kWhiteTexture;
    });
}

TEST(MaterialExtensions, IorAndSpecularAreDrawnNotWarnedAsMissing) {
    EXPECT_TRUE(is_supported_gltf_extension("KHR_materials_ior"));
    EXPECT_TRUE(is_supported_gltf_extension("KHR_materials_specular"));
    const LoadResult r = load_data("material_sweeps/ior_sweep.gltf");
    ASSERT_TRUE(r) << r.error;
    for (const std::string& w : r.scene->warnings)
        EXPECT_EQ(w.find("not implemented"), std::string::npos) << w;
    ASSERT_EQ(r.scene->materials.size(), 10u);
    EXPECT_FLOAT_EQ(*r.scene->materials[0].ior, 1.0f);
    EXPECT_FLOAT_EQ(*r.scene->materials[4].ior, 2.33f);
    EXPECT_FALSE(r.scene->materials[0].specular.has_value());
}

TEST(MaterialExtensions, BadValuesAreWarnedWithTheirPointerAndFallBack) {
    const LoadResult r = load_data("material_extensions_bad.gltf");
    ASSERT_TRUE(r) << r.error;
    const Scene& s = *r.scene;
    // Negative, below 1, infinite (as a float) and non-number ior: warned, 1.5 drawn.
    for (int m : {0, 1, 2, 8}) {
        const std::string p =
            "/materials/" + std::to_string(m) + "/extensions/KHR_materials_ior/ior";
        EXPECT_NE(message_at(s, p), nullptr) << p;
        EXPECT_FLOAT_EQ(*s.materials[std::size_t(m)].ior, kDefaultIor) << p;
    }
    // ior 0 is valid (F0 = 1): no message.
    EXPECT_EQ(message_at(s, "/materials/5/extensions/KHR_materials_ior/ior"), nullptr);
    EXPECT_FLOAT_EQ(*material(s, "ior zero").ior, 0.0f);
    // specularFactor 2 clamps to 1, -0.5 to 0; a non-finite colour takes [1, 1, 1], a
    // negative component clamps to 0.
    const std::string spec3 = "/materials/3/extensions/KHR_materials_specular/";
    EXPECT_NE(message_at(s, spec3 + "specularFactor"), nullptr);
    EXPECT_NE(message_at(s, spec3 + "specularColorFactor"), nullptr);
    EXPECT_FLOAT_EQ(material(s, "bad specular").specular->specular_factor, 1.0f);
    EXPECT_EQ(material(s, "bad specular").specular->specular_color_factor, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(material(s, "negative colour").specular->specular_factor, 0.0f);
    EXPECT_EQ(material(s, "negative colour").specular->specular_color_factor,
              glm::vec3(0.0f, 0.5f, 0.25f));
    EXPECT_NE(message_at(s, "/materials/4/extensions/KHR_materials_specular/specularColorFactor"),
              nullptr);
    // A texture index out of range: the material is drawn with default values, said.
    bool defaulted = false;
    for (const ValidationMessage& m : s.validation.messages)
        defaulted |= m.code == "SHERPA_MATERIAL_DEFAULTED" &&
                     m.message.find("specularTexture") != std::string::npos;
    EXPECT_TRUE(defaulted);
    EXPECT_FALSE(s.materials[7].specular.has_value());
    // A missing image: the slot is kept (the texture pipeline warns and draws white).
    EXPECT_TRUE(material(s, "missing specular texture").specular->specular_color.present());
}

TEST(MaterialExtensions, OnlyMaterialsThatUseAnExtensionHaveBlocks) {
    const LoadResult r = load_data("material_extensions_bad.gltf");
    ASSERT_TRUE(r) << r.error;
    const gpu::MaterialExtensionBuffer b = layout(*r.scene);
    ASSERT_EQ(b.places.size(), r.scene->materials.size());
    std::size_t words = 0;
    for (std::size_t i = 0; i < b.places.size(); ++i) {
        const MaterialInstance& m = r.scene->materials[i];
        const gpu::MaterialExtensionPlace& p = b.places[i];
        EXPECT_EQ(p.any(), m.ior.has_value() || m.specular.has_value()) << i;
        EXPECT_EQ(p.ior != gpu::kNoExtension, m.ior.has_value()) << i;
        EXPECT_EQ(p.specular != gpu::kNoExtension, m.specular.has_value()) << i;
        if (!p.any()) continue;
        words += 2 + (m.ior ? 1 : 0) + (m.specular ? 6 : 0); // the index is two words
        gpu::GPUExtensionIndex index;
        std::memcpy(&index, &b.words[p.index], sizeof index);
        EXPECT_EQ(index.ior, p.ior);
        EXPECT_EQ(index.specular, p.specular);
        if (m.ior) {
            gpu::GPUIorBlock ior;
            std::memcpy(&ior, &b.words[p.ior], sizeof ior);
            EXPECT_EQ(ior.ior, *m.ior);
        }
    }
    EXPECT_EQ(b.words.size(), words);
    // "missing specular texture" (material 6): its colour texture resolved through the
    // slot function, the specular texture white.
    gpu::GPUSpecularBlock spec;
    std::memcpy(&spec, &b.words[b.places[6].specular], sizeof spec);
    EXPECT_EQ(spec.specular_color_tex, 100u);
    EXPECT_EQ(spec.specular_tex, gpu::kWhiteTexture);
    EXPECT_EQ(spec.color_factor, glm::vec4(1.0f));
}

TEST(MaterialExtensions, ASceneWithoutExtensionsHasNoBytes) {
    const LoadResult r = load_scene(test::gltf_asset("DamagedHelmet"));
    ASSERT_TRUE(r) << r.error;
    const gpu::MaterialExtensionBuffer b = layout(*r.scene);
    EXPECT_EQ(b.bytes(), 0u);
    for (const gpu::MaterialExtensionPlace& p : b.places) EXPECT_FALSE(p.any());
}

TEST(MaterialExtensions, AnIorOnlyMaterialPaysFortyEightBytes) {
    const LoadResult r = load_data("material_sweeps/ior_sweep.gltf");
    ASSERT_TRUE(r) << r.error;
    // Its 32-byte index (two words: GPUExtensionIndex) and its 16-byte block.
    EXPECT_EQ(layout(*r.scene).bytes(), 10u * 48u);
}

} // namespace
