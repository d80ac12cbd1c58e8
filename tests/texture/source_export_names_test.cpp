// File names of `textures --export-source`: a 300-byte image name made the run fail
// (ENAMETOOLONG) and U+202E (right-to-left override) reached the file system, where
// "photo\u202Egnp.exe" shows as "photoexe.png".
#include <gtest/gtest.h>

#include <set>

#include <sherpa/texture/source_export.h>

#include "test_images.h"

namespace {

using namespace sherpa;
using namespace sherpa::tex;
namespace fs = std::filesystem;

scene::Scene generated_images(const std::vector<std::string>& names) {
    scene::Scene s;
    for (const std::string& name : names) {
        const RgbaImage pixels = test::synthetic_image(4, 4, false, 3);
        scene::ImageRecord img;
        img.name = name, img.width = pixels.width, img.height = pixels.height;
        img.pixels = pixels.pixels;
        s.images.push_back(img);
    }
    return s;
}

TEST(SourceExportNames, LongNamesAreShortenedAndKeptApart) {
    const std::string long_a = std::string(300, 'a');
    const std::string long_b = std::string(300, 'a') + "b"; // same first 120 bytes
    // A multi-byte character across the cut is not split.
    const std::string long_utf8 = std::string(119, 'c') + "\xC3\xA9" + std::string(200, 'c');
    const scene::Scene scene = generated_images({long_a, long_b, long_utf8, "short"});
    const std::vector<std::string> names = source_export_names(scene);
    ASSERT_EQ(names.size(), 4u);
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), 4u);
    for (const std::string& n : names) EXPECT_LE(n.size(), 255u) << n;
    EXPECT_EQ(names[0].substr(0, 120), std::string(120, 'a'));
    EXPECT_EQ(names[2].substr(0, 120), std::string(119, 'c') + "_") << "cut before the é";
    EXPECT_EQ(names[3], "short.png");

    const fs::path dir = test::fresh_temp_dir("export-long-names");
    for (const SourceExport& e : export_sources(scene, dir)) {
        EXPECT_EQ(e.error, "") << "image " << e.image;
        EXPECT_TRUE(fs::exists(e.file)) << e.file;
    }
    fs::remove_all(dir);
}

TEST(SourceExportNames, BidiControlsAreDropped) {
    const scene::Scene scene = generated_images({"photo\xE2\x80\xAEgnp.exe",
                                                 "a\xE2\x81\xA6"
                                                 "b\xD8\x9C"
                                                 "c",
                                                 "\xE2\x80\x8F"});
    const std::vector<std::string> names = source_export_names(scene);
    EXPECT_EQ(names[0], "photognp.exe.png");
    EXPECT_EQ(names[1], "abc.png");
    EXPECT_EQ(names[2], "image2_generated.png") << "nothing left: the generic name";
}

} // namespace
