// KHR_texture_basisu and EXT_texture_webp: BoxTextured with its texture pointed at a
// KTX2 (ETC1S/BasisLZ and UASTC/Zstandard, made by the reference `basisu` tool in the
// basisu corpus fixture) or a WebP (written by OpenImageIO's oiiotool) image. The
// importer picks the extension's image (the core `source` is the fallback), info
// --json names each image's container, and the scene renders validation-clean
// through the texture pipeline (which transcodes KTX2 by its identifier).
#include "cli/cli_run.h"
#include "test_support.h"

#include <sherpa/scene/scene_loader.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

const fs::path& work_dir() {
    static const fs::path dir = [] {
        const fs::path d =
            fs::temp_directory_path() / ("sherpa_texture_ext_" + std::to_string(::getpid()));
        fs::create_directories(d);
        const fs::path box = test::assets_dir() / "gltf" / "BoxTextured" / "glTF";
        for (const char* f : {"BoxTextured0.bin", "CesiumLogoFlat.png"})
            fs::copy_file(box / f, d / f, fs::copy_options::overwrite_existing);
        const fs::path corpus = fs::path(SHERPA_BASISU_CACHE) / "corpus";
        fs::copy_file(corpus / "logo211_etc1s.ktx2", d / "logo_etc1s.ktx2",
                      fs::copy_options::overwrite_existing);
        fs::copy_file(corpus / "logo211_uastc_zstd.ktx2", d / "logo_uastc.ktx2",
                      fs::copy_options::overwrite_existing);
        const std::string cmd = "oiiotool '" + (d / "CesiumLogoFlat.png").string() + "' -o '" +
                                (d / "logo.webp").string() + "'";
        if (std::system(cmd.c_str()) != 0) ADD_FAILURE() << "oiiotool could not write WebP";
        return d;
    }();
    return dir;
}

// BoxTextured whose only texture is `texture`; images: 0 PNG, 1 WebP, 2 ETC1S, 3 UASTC.
std::string box_with(const std::string& name, const nlohmann::json& texture,
                     const std::vector<std::string>& used) {
    nlohmann::json doc = test::read_json(test::gltf_asset("BoxTextured"));
    doc["images"] = {{{"uri", "CesiumLogoFlat.png"}},
                     {{"uri", "logo.webp"}},
                     {{"uri", "logo_etc1s.ktx2"}},
                     {{"uri", "logo_uastc.ktx2"}}};
    doc["textures"] = nlohmann::json::array({texture});
    doc["extensionsUsed"] = used;
    const fs::path out = work_dir() / name;
    std::ofstream(out) << doc.dump();
    return out.string();
}

nlohmann::json ext_texture(const char* ext, int source, bool fallback) {
    nlohmann::json t = {{"sampler", 0}, {"extensions", {{ext, {{"source", source}}}}}};
    if (fallback) t["source"] = 0;
    return t;
}

struct Case {
    const char* file;
    const char* extension;
    int image;
    const char* container;
    const char* supercompression;
    int width; // of the decoded image (the KTX2 files are the corpus' 211x211 logo)
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.file;
}

class TextureExtension : public ::testing::TestWithParam<Case> {};

TEST_P(TextureExtension, ExtensionImageIsUsedAndRendersValidationClean) {
    const Case& c = GetParam();
    for (const bool fallback : {false, true}) {
        const std::string path =
            box_with(std::string(fallback ? "fb_" : "") + c.file,
                     ext_texture(c.extension, c.image, fallback), {c.extension});
        const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
        ASSERT_TRUE(r) << r.error;
        ASSERT_EQ(r.scene->textures.size(), 1u);
        EXPECT_EQ(r.scene->textures[0].image, c.image) << "the extension's image, not the fallback";
    }
    const std::string path =
        box_with(c.file, ext_texture(c.extension, c.image, true), {c.extension});
    const test::CliRun info = test::run_cli("info '" + path + "' --json", "2>/dev/null");
    ASSERT_EQ(info.exit_code, 0) << info.out;
    const auto j = nlohmann::json::parse(info.out);
    const auto& img = j.at("images_detail").at(c.image);
    EXPECT_EQ(img.at("container"), c.container);
    if (c.supercompression) {
        EXPECT_EQ(img.at("supercompression"), c.supercompression);
        EXPECT_TRUE(img.at("transcode_ms").is_number());
    }
    EXPECT_EQ(j.at("extensions_used").at(0).at("supported"), true);
    // Every image of the file (PNG, WebP, both KTX2) decodes: none is a problem
    // (info once probed KTX2 with OpenImageIO, which cannot read it).
    EXPECT_EQ(j.at("image_problems"), nlohmann::json::array()) << j.at("image_problems");
    const std::string png = (work_dir() / (std::string(c.file) + ".png")).string();
    const test::CliRun render = test::run_cli(
        "render '" + path + "' -o '" + png + "' --width 64 --height 48 --validation --cache-dir '" +
        SHERPA_TEST_TEXTURE_CACHE + "'");
    EXPECT_EQ(render.exit_code, 0) << render.out;
    const test::CliRun textures = test::run_cli("textures '" + path + "' --json --cache-dir '" +
                                                    SHERPA_TEST_TEXTURE_CACHE + "'",
                                                "2>/dev/null");
    ASSERT_EQ(textures.exit_code, 0) << textures.out;
    const auto t = nlohmann::json::parse(textures.out).at("textures").at(0);
    EXPECT_EQ(t.at("image"), c.image);
    EXPECT_EQ(t.at("width"), c.width) << "the KTX2/WebP image was decoded";
}

INSTANTIATE_TEST_SUITE_P(
    Images, TextureExtension,
    ::testing::Values(Case{"webp.gltf", "EXT_texture_webp", 1, "webp", nullptr, 256},
                      Case{"etc1s.gltf", "KHR_texture_basisu", 2, "ktx2-etc1s", "basislz", 211},
                      Case{"uastc.gltf", "KHR_texture_basisu", 3, "ktx2-uastc", "zstd", 211}),
    [](const auto& param_info) {
        return std::string(param_info.param.container).substr(0, 5) == "ktx2-"
                   ? std::string(param_info.param.container).substr(5)
                   : std::string(param_info.param.container);
    });

// A texture whose only extension Sherpa does not read shows its core source.
TEST(TextureExtension, UnknownImageExtensionFallsBackToTheCoreSource) {
    const std::string path =
        box_with("avif.gltf", ext_texture("EXT_texture_avif", 1, true), {"EXT_texture_avif"});
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.scene->textures.at(0).image, 0);
}

// An extension source out of range is named.
TEST(TextureExtension, ExtensionSourceOutOfRangeIsNamed) {
    const std::string path =
        box_with("bad.gltf", ext_texture("KHR_texture_basisu", 9, false), {"KHR_texture_basisu"});
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(path);
    EXPECT_FALSE(r);
    EXPECT_NE(
        r.error.find("textures[0].extensions.KHR_texture_basisu.source: image 9 out of range"),
        std::string::npos)
        << r.error;
}

// Hand-broken KTX2 files (a level index whose offset wraps past 2^64, supercompression
// global data that overruns the file) referenced through KHR_texture_basisu: the file
// still opens, and info names the image's file and the problem (an undecodable image,
// drawn as the missing-texture checker), never a crash.
TEST(TextureExtension, BrokenKtx2NamesTheFileAndTheProblem) {
    const auto put64 = [](std::vector<unsigned char>& b, std::size_t at, std::uint64_t v) {
        for (int i = 0; i < 8; ++i)
            b[at + std::size_t(i)] = static_cast<unsigned char>(v >> (8 * i));
    };
    struct Broken {
        const char* file;
        std::uint64_t at, value, at2, value2;
        const char* problem;
    };
    const std::vector<unsigned char> good = test::read_bytes(work_dir() / "logo_uastc.ktx2");
    for (const Broken& c :
         {Broken{"bad_level_index.ktx2", 80, ~std::uint64_t{0} - 8, 88, 16, "level 0"},
          Broken{"bad_sgd.ktx2", 64, good.size() - 4, 72, 64,
                 "supercompression global data overruns"}}) {
        std::vector<unsigned char> bytes = good;
        put64(bytes, c.at, c.value);
        put64(bytes, c.at2, c.value2);
        std::ofstream(work_dir() / c.file, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        nlohmann::json doc = test::read_json(box_with(std::string(c.file) + ".gltf",
                                                      ext_texture("KHR_texture_basisu", 2, false),
                                                      {"KHR_texture_basisu"}));
        doc["images"][2]["uri"] = c.file;
        const fs::path gltf = work_dir() / (std::string(c.file) + ".gltf");
        std::ofstream(gltf) << doc.dump();
        const test::CliRun info =
            test::run_cli("info '" + gltf.string() + "' --json", "2>/dev/null");
        ASSERT_EQ(info.exit_code, 0) << c.file << ": " << info.out;
        const nlohmann::json problems = nlohmann::json::parse(info.out).at("image_problems");
        ASSERT_EQ(problems.size(), 1u) << c.file << ": " << info.out;
        const nlohmann::json& p = problems.at(0);
        EXPECT_EQ(p.at("state"), "undecodable") << p;
        EXPECT_NE(p.at("location").get<std::string>().find(c.file), std::string::npos) << p;
        EXPECT_NE(p.at("reason").get<std::string>().find(c.problem), std::string::npos) << p;
    }
}

} // namespace
