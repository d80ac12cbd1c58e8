// Loud about what is not drawn: every extension of extensionsUsed that Sherpa does
// not implement is a warning (Scene::warnings: info, render, the editor's log) and a
// validation message (the Validation dock), per file and per material that names it.
#include "test_support.h"

#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/scene/scene_loader.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

sherpa::scene::LoadResult load_glass() {
    return sherpa::scene::load_scene(
        (sherpa::test::data_dir() / "unsupported_material_extensions.gltf").string());
}

bool contains(const std::vector<std::string>& lines, const std::string& a, const std::string& b) {
    for (const std::string& l : lines)
        if (l.find(a) != std::string::npos && l.find(b) != std::string::npos) return true;
    return false;
}

TEST(UnsupportedExtensions, TransmissionAndThinTransparencyAreWarnings) {
    const sherpa::scene::LoadResult r = load_glass();
    ASSERT_TRUE(r) << r.error;
    const auto& w = r.scene->warnings;
    EXPECT_TRUE(contains(w, "ADOBE_materials_thin_transparency", "materials[0] \"Glass\""));
    EXPECT_TRUE(contains(w, "ADOBE_materials_clearcoat_specular", "materials[0] \"Glass\""));
    EXPECT_FALSE(contains(w, "KHR_materials_emissive_strength", "")) << "drawn: no warning";
}

TEST(UnsupportedExtensions, MessagesPointAtTheNameAndTheMaterial) {
    const sherpa::scene::LoadResult r = load_glass();
    ASSERT_TRUE(r) << r.error;
    std::vector<std::pair<std::string, std::string>> got;
    for (const auto& m : r.scene->validation.messages) {
        // Vendor extensions: the Khronos validator's information that it cannot check them.
        EXPECT_EQ(m.severity, m.code == "UNSUPPORTED_EXTENSION"
                                  ? sherpa::scene::Severity::Information
                                  : sherpa::scene::Severity::Warning);
        got.emplace_back(m.code, m.pointer);
    }
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"UNSUPPORTED_EXTENSION", "/extensionsUsed/1"},
        {"UNSUPPORTED_EXTENSION", "/extensionsUsed/2"},
        {"SHERPA_EXTENSION_NOT_DRAWN", "/extensionsUsed/1"},
        {"SHERPA_EXTENSION_NOT_DRAWN", "/extensionsUsed/2"},
        {"SHERPA_MATERIAL_EXTENSION_NOT_DRAWN",
         "/materials/0/extensions/ADOBE_materials_clearcoat_specular"},
        {"SHERPA_MATERIAL_EXTENSION_NOT_DRAWN",
         "/materials/0/extensions/ADOBE_materials_thin_transparency"},
    };
    EXPECT_EQ(got, expected);
    EXPECT_EQ(r.scene->validation.count(sherpa::scene::Severity::Warning), 4u);
}

TEST(UnsupportedExtensions, PerMaterialListAndUses) {
    const sherpa::scene::LoadResult r = load_glass();
    ASSERT_TRUE(r) << r.error;
    const auto& mats = r.scene->materials;
    ASSERT_GE(mats.size(), 2u);
    EXPECT_EQ(sherpa::scene::unsupported_extensions(mats[0]),
              (std::vector<std::string>{"ADOBE_materials_clearcoat_specular",
                                        "ADOBE_materials_thin_transparency"}));
    EXPECT_TRUE(sherpa::scene::unsupported_extensions(mats[1]).empty());
    const auto uses = sherpa::scene::extension_uses(*r.scene);
    ASSERT_EQ(uses.size(), 3u);
    EXPECT_TRUE(uses[0].supported);
    EXPECT_EQ(uses[0].materials, std::vector<std::uint32_t>{1});
    EXPECT_FALSE(uses[1].supported);
    EXPECT_EQ(uses[1].materials, std::vector<std::uint32_t>{0});
}

// A material naming an extension that extensionsUsed does not declare (an invalid
// file) is still drawn without it, and says so.
TEST(UnsupportedExtensions, UndeclaredMaterialExtensionIsAWarningToo) {
    nlohmann::json doc = sherpa::test::read_json(
        (sherpa::test::data_dir() / "unsupported_material_extensions.gltf").string());
    doc["extensionsUsed"] = {"KHR_materials_emissive_strength",
                             "ADOBE_materials_thin_transparency"};
    const auto path = std::filesystem::temp_directory_path() /
                      ("sherpa_undeclared_" + std::to_string(::getpid()) + ".gltf");
    std::ofstream(path) << doc.dump();
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path.string());
    std::filesystem::remove(path);
    ASSERT_TRUE(r) << r.error;
    EXPECT_TRUE(contains(r.scene->warnings,
                         "materials[0] \"Glass\" is drawn without "
                         "ADOBE_materials_clearcoat_specular",
                         "which Sherpa does not implement"));
    EXPECT_FALSE(
        contains(r.scene->warnings, "is drawn without ADOBE_materials_thin_transparency", ""))
        << "declared: said once, in the extensionsUsed line";
    std::size_t material_messages = 0;
    for (const auto& m : r.scene->validation.messages)
        material_messages += m.code == "SHERPA_MATERIAL_EXTENSION_NOT_DRAWN";
    EXPECT_EQ(material_messages, 2u);
}

// A file whose extensions are all drawn says nothing about extensions.
TEST(UnsupportedExtensions, SupportedFilesStayQuiet) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(
        (sherpa::test::data_dir() / "lights_and_extensions.gltf").string());
    ASSERT_TRUE(r) << r.error;
    for (const auto& m : r.scene->validation.messages)
        EXPECT_NE(m.code.rfind("SHERPA_", 0), 0u) << m.code << " " << m.pointer;
}

} // namespace
