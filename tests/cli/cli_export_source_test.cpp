// sherpa-cli textures --export-source: every source image as the engine decoded it,
// compared with decoders we did not write: libpng and libjpeg read the PNG/JPEG
// sources directly, and `basisu -unpack` (the basisu corpus fixture) decoded the
// KTX2 files. File names follow the image's file; embedded images get derived names;
// colliding names are made unique.
#include "cli/cli_run.h"
#include "reference/reference_images.h"
#include "test_support.h"

#include <basisu_corpus.h>
#include <sherpa/texture/source_export.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;
namespace test = sherpa::test;

const fs::path kBox = test::assets_dir() / "gltf" / "BoxTextured" / "glTF";
const fs::path kPng = test::assets_dir() / "gltf" / "VC" / "glTF" / "prop128.png"; // alpha 0..217
const fs::path kJpeg = test::assets_dir() / "gltf" / "VC" / "glTF" / "5.jpg";

test::BasisCorpusFile corpus_file(const std::string& name) {
    std::string error;
    for (const auto& f : test::basis_corpus(error))
        if (f.name == name) return f;
    ADD_FAILURE() << "basisu corpus has no " << name << " " << error;
    return {};
}

std::vector<std::uint8_t> file_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// BoxTextured with images: 0 PNG (RGBA), 1 JPEG, 2 ETC1S KTX2 (RGBA), 3 UASTC KTX2
// (RGBA), 4 the PNG again from a subfolder (same stem: a collision), 5 the PNG
// embedded through a bufferView, 6 a file that does not exist.
fs::path make_scene(const fs::path& dir) {
    fs::create_directories(dir / "sub");
    fs::copy_file(kBox / "BoxTextured0.bin", dir / "BoxTextured0.bin",
                  fs::copy_options::overwrite_existing);
    for (const fs::path& to : {dir / "prop128.png", dir / "sub" / "prop128.png"})
        fs::copy_file(kPng, to, fs::copy_options::overwrite_existing);
    fs::copy_file(kJpeg, dir / "five.jpg", fs::copy_options::overwrite_existing);
    fs::copy_file(corpus_file("prop128_etc1s").ktx2, dir / "prop_etc1s.ktx2",
                  fs::copy_options::overwrite_existing);
    fs::copy_file(corpus_file("prop128_uastc_zstd").ktx2, dir / "prop_uastc.ktx2",
                  fs::copy_options::overwrite_existing);
    const auto png = file_bytes(kPng);
    std::ofstream(dir / "embedded.bin", std::ios::binary)
        .write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    nlohmann::json doc = test::read_json(test::gltf_asset("BoxTextured"));
    doc["buffers"].push_back({{"uri", "embedded.bin"}, {"byteLength", png.size()}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", png.size()}});
    const int view = int(doc["bufferViews"].size()) - 1;
    doc["images"] = {
        {{"uri", "prop128.png"}},     {{"uri", "five.jpg"}},
        {{"uri", "prop_etc1s.ktx2"}}, {{"uri", "prop_uastc.ktx2"}},
        {{"uri", "sub/prop128.png"}}, {{"bufferView", view}, {"mimeType", "image/png"}},
        {{"uri", "not_there.png"}}};
    const fs::path out = dir / "box.gltf";
    std::ofstream(out) << doc.dump();
    return out;
}

test::ReferenceImage read_reference(const fs::path& p) {
    test::ReferenceImage img;
    std::string error;
    EXPECT_TRUE(test::read_reference_image(p, img, error)) << error;
    return img;
}

// Counts texels whose channel `c` (or every channel when c < 0) differ.
std::size_t differing(const test::ReferenceImage& a, const test::ReferenceImage& b, int c,
                      int b_channel = -1) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    if (a.width != b.width || a.height != b.height) return ~std::size_t{0};
    std::size_t n = 0;
    for (std::size_t i = 0; i < std::size_t{a.width} * a.height; ++i) {
        bool diff = false;
        for (int k = 0; k < 4; ++k)
            if (c < 0 || k == c)
                diff |= a.rgba[i * 4 + k] != b.rgba[i * 4 + (b_channel < 0 ? k : b_channel)];
        n += diff;
    }
    return n;
}

TEST(ExportSource, EveryImageEqualsAnIndependentDecodeOfItsSource) {
    const fs::path dir = fs::temp_directory_path() / ("sherpa_export_" + std::to_string(getpid()));
    fs::remove_all(dir);
    const fs::path scene = make_scene(dir);
    const fs::path out = dir / "out";
    const test::CliRun run = test::run_cli("textures '" + scene.string() + "' --export-source '" +
                                               out.string() + "' --json",
                                           "2>" + (dir / "stderr.txt").string());
    EXPECT_EQ(run.exit_code, 1) << "image 6 is missing: the export says so" << run.out;
    const auto exported = nlohmann::json::parse(run.out).at("exported");
    ASSERT_EQ(exported.size(), 7u);
    const std::vector<std::string> names = {
        "prop128.png",        "five.png",
        "prop_etc1s.png",     "prop_uastc.png",
        "prop128_image4.png", "image5_bufferView3.png" /* BoxTextured has views 0-2 */,
        "not_there.png"};
    for (std::size_t i = 0; i < names.size(); ++i)
        EXPECT_EQ(fs::path(exported[i].at("file").get<std::string>()).filename(), names[i]);
    std::ifstream err(dir / "stderr.txt");
    const std::string stderr_text{std::istreambuf_iterator<char>(err), {}};
    EXPECT_NE(stderr_text.find("not_there.png: missing"), std::string::npos) << stderr_text;
    EXPECT_FALSE(fs::exists(out / "not_there.png"));

    // PNG (RGBA, unassociated alpha) and its copies: libpng's texels exactly.
    const auto logo = read_reference(kPng);
    for (const char* f : {"prop128.png", "prop128_image4.png"})
        EXPECT_EQ(differing(read_reference(out / f), logo, -1), 0u) << f;
    EXPECT_EQ(differing(read_reference(out / names[5]), logo, -1), 0u) << "bufferView image";
    // JPEG: libjpeg's RGB.
    EXPECT_EQ(differing(read_reference(out / "five.png"), read_reference(kJpeg), -1), 0u);
    // KTX2: level 0 of basisu -unpack (colour, and alpha from its own reference PNG).
    for (const auto& [name, file] : {std::pair{"prop128_etc1s", "prop_etc1s.png"},
                                     std::pair{"prop128_uastc_zstd", "prop_uastc.png"}}) {
        const auto corpus = corpus_file(name);
        const auto ours = read_reference(out / file);
        const auto rgb = read_reference(corpus.reference_rgb(0));
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(differing(ours, rgb, c), 0u) << name << " channel " << c;
        EXPECT_EQ(differing(ours, read_reference(corpus.reference_alpha(0)), 3,
                            corpus.reference_alpha_channel()),
                  0u)
            << name << " alpha";
    }
    fs::remove_all(dir);
}

TEST(ExportSource, NamesAreUniqueAndFileSafe) {
    sherpa::scene::Scene scene;
    scene.source = "/x/scene.gltf";
    auto image = [](std::string uri, std::string name, int view) {
        sherpa::scene::ImageRecord r;
        r.uri = std::move(uri);
        r.name = std::move(name);
        r.buffer_view = view;
        return r;
    };
    scene.images = {image("a.ktx2", "", -1),     image("b/A.png", "", -1),
                    image("", "a_image1", 3),    image("", "", 7),
                    image("", "we/ird:name", 2), image("data:image/png;base64,AAAA", "", -1),
                    image("c%20d.jpg", "", -1)};
    const std::vector<std::string> expected = {"a.png",
                                               "A_image1.png",
                                               "a_image1_image2.png",
                                               "image3_bufferView7.png",
                                               "we_ird_name.png",
                                               "image5_datauri.png",
                                               "c d.png"};
    EXPECT_EQ(sherpa::tex::source_export_names(scene), expected);
}

} // namespace
