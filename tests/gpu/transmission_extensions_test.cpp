// The transmission family (KHR_materials_transmission, _volume, _diffuse_transmission,
// _dispersion): what the importer reads and warns about (each bad value named by its
// JSON pointer, with the fallback docs/materials.md gives), and their blocks in the
// extension buffer: only materials that use one get it.
#include "gpu/material_extension_support.h"
#include "test_support.h"

#include <sherpa/render/material_extensions.h>
#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/scene/scene_loader.h>

#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

namespace {

using namespace sherpa;

template <typename Block>
Block block_at(const render::MaterialExtensionBuffer& b, std::uint32_t w) {
    Block out;
    std::memcpy(&out, &b.words.at(w), sizeof out);
    return out;
}

TEST(TransmissionExtensions, DrawnOnesAreSupported) {
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_transmission"));
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_volume"));
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_dispersion"));
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_diffuse_transmission"));
    const scene::LoadResult r =
        scene::load_scene((test::data_dir() / "material_sweeps/volume_sweep.gltf").string());
    ASSERT_TRUE(r) << r.error;
    for (const std::string& w : r.scene->warnings)
        EXPECT_EQ(w.find("not implemented"), std::string::npos) << w;
    const scene::MaterialInstance& m = r.scene->materials[0];
    ASSERT_TRUE(m.transmission && m.volume);
    EXPECT_FLOAT_EQ(m.transmission->factor, 1.0f);
    EXPECT_FLOAT_EQ(m.volume->thickness_factor, 0.8f);
    EXPECT_FLOAT_EQ(m.volume->attenuation_distance, 0.1f);
    EXPECT_TRUE(std::isinf(r.scene->materials[4].volume->attenuation_distance));
}

TEST(TransmissionExtensions, BadValuesAreWarnedWithTheirPointerAndFallBack) {
    const scene::LoadResult r =
        scene::load_scene((test::data_dir() / "transmission_bad.gltf").string());
    ASSERT_TRUE(r) << r.error;
    const scene::Scene& s = *r.scene;
    const std::string t = "/extensions/KHR_materials_transmission/transmissionFactor";
    // -0.5 clamps to 0; a string and 1e39 (infinite as a float) take the default 0.
    for (int m : {0, 1, 4}) {
        const std::string p = "/materials/" + std::to_string(m) + t;
        EXPECT_NE(test::message_at(s, p), nullptr) << p;
        ASSERT_TRUE(s.materials[std::size_t(m)].transmission) << p;
        EXPECT_EQ(s.materials[std::size_t(m)].transmission->factor, 0.0f) << p;
    }
    // A volume without transmission: warned, not drawn.
    EXPECT_NE(test::message_at(s, "/materials/2/extensions/KHR_materials_volume"), nullptr);
    EXPECT_FALSE(s.materials[2].volume.has_value());
    // A negative thickness clamps to 0, a zero distance means none (infinity), colour
    // components clamp to 0..1.
    const std::string v = "/materials/3/extensions/KHR_materials_volume/";
    EXPECT_NE(test::message_at(s, v + "thicknessFactor"), nullptr);
    EXPECT_NE(test::message_at(s, v + "attenuationDistance"), nullptr);
    EXPECT_NE(test::message_at(s, v + "attenuationColor"), nullptr);
    ASSERT_TRUE(s.materials[3].volume);
    EXPECT_EQ(s.materials[3].volume->thickness_factor, 0.0f);
    EXPECT_TRUE(std::isinf(s.materials[3].volume->attenuation_distance));
    EXPECT_EQ(s.materials[3].volume->attenuation_color, glm::vec3(1.0f, 0.0f, 0.5f));
    // Dispersion needs a volume; a negative one clamps to 0.
    EXPECT_NE(test::message_at(s, "/materials/5/extensions/KHR_materials_dispersion"), nullptr);
    EXPECT_FALSE(s.materials[5].dispersion.has_value());
    EXPECT_NE(test::message_at(s, "/materials/6/extensions/KHR_materials_dispersion/dispersion"),
              nullptr);
    EXPECT_EQ(*s.materials[6].dispersion, 0.0f);
    // Diffuse transmission: 1.5 clamps to 1, a non-number colour takes [1, 1, 1].
    const std::string d = "/materials/7/extensions/KHR_materials_diffuse_transmission/";
    EXPECT_NE(test::message_at(s, d + "diffuseTransmissionFactor"), nullptr);
    EXPECT_NE(test::message_at(s, d + "diffuseTransmissionColorFactor"), nullptr);
    ASSERT_TRUE(s.materials[7].diffuse_transmission);
    EXPECT_EQ(s.materials[7].diffuse_transmission->factor, 1.0f);
    EXPECT_EQ(s.materials[7].diffuse_transmission->color_factor, glm::vec3(1.0f));
    // The good one: its texture slots keep their TEXCOORD set and transform.
    const scene::MaterialInstance& good = s.materials[8];
    ASSERT_TRUE(good.transmission && good.volume);
    EXPECT_EQ(good.transmission->texture.texture, 0);
    EXPECT_EQ(good.transmission->texture.tex_coord, 1u);
    EXPECT_TRUE(good.transmission->texture.transform.present);
    EXPECT_EQ(good.transmission->texture.transform.scale, glm::vec2(2.0f));
    EXPECT_TRUE(good.volume->thickness.present());
    EXPECT_EQ(test::message_at(s, "/materials/8/extensions/KHR_materials_transmission/"
                                  "transmissionFactor"),
              nullptr);
}

TEST(TransmissionExtensions, BlocksHoldTheValuesAndOnlyUsersPay) {
    const scene::LoadResult r =
        scene::load_scene((test::data_dir() / "transmission_bad.gltf").string());
    ASSERT_TRUE(r) << r.error;
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    std::size_t words = 0;
    for (std::size_t i = 0; i < b.places.size(); ++i) {
        const scene::MaterialInstance& m = r.scene->materials[i];
        const render::MaterialExtensionPlace& p = b.places[i];
        EXPECT_EQ(p.transmission != render::kNoExtension, m.transmission.has_value()) << i;
        EXPECT_EQ(p.volume != render::kNoExtension, m.volume.has_value()) << i;
        EXPECT_EQ(p.diffuse_transmission != render::kNoExtension,
                  m.diffuse_transmission.has_value())
            << i;
        EXPECT_EQ(p.dispersion != render::kNoExtension, m.dispersion.has_value()) << i;
        if (!p.any()) continue;
        words += 3 + (m.transmission ? 3 : 0) + (m.volume ? 4 : 0) +
                 (m.diffuse_transmission ? 6 : 0) + (m.dispersion ? 1 : 0);
        const auto index = block_at<render::GPUExtensionIndex>(b, p.index);
        EXPECT_EQ(index.transmission, p.transmission);
        EXPECT_EQ(index.volume, p.volume);
        EXPECT_EQ(index.diffuse_transmission, p.diffuse_transmission);
        EXPECT_EQ(index.dispersion, p.dispersion);
    }
    EXPECT_EQ(b.words.size(), words);
    // Only materials whose transmission can be non-zero make the renderer draw the
    // transmission background: 3, 5, 6 (factor 1) and 8 (0.5).
    EXPECT_EQ(b.transmissive_materials, 4u);
    const auto t = block_at<render::GPUTransmissionBlock>(b, b.places[8].transmission);
    EXPECT_EQ(t.factor, 0.5f);
    EXPECT_EQ(t.texture, 100u);
    EXPECT_EQ(t.uv.row0.w, 1.0f);  // TEXCOORD_1
    EXPECT_EQ(t.uv.row0.x, 2.0f);  // scale
    EXPECT_EQ(t.uv.row0.z, 0.25f); // offset
    const auto v = block_at<render::GPUVolumeBlock>(b, b.places[8].volume);
    EXPECT_EQ(v.attenuation, glm::vec4(0.5f, 0.25f, 1.0f, 2.0f));
    EXPECT_EQ(v.thickness_factor, 0.3f);
    EXPECT_EQ(v.thickness_tex, 100u);
}

TEST(TransmissionExtensions, ASceneWithoutThemPaysNothing) {
    const scene::LoadResult r =
        scene::load_scene((test::data_dir() / "material_sweeps/ior_sweep.gltf").string());
    ASSERT_TRUE(r) << r.error;
    const render::MaterialExtensionBuffer b = test::extension_layout(*r.scene);
    EXPECT_EQ(b.transmissive_materials, 0u);
    for (const render::MaterialExtensionPlace& p : b.places) {
        EXPECT_EQ(p.transmission, render::kNoExtension);
        EXPECT_EQ(p.volume, render::kNoExtension);
    }
}

} // namespace
