// Decompression bombs: images whose headers declare far more texels than their bytes
// hold (tests/data/make_oversized.py writes them). Each is refused from its header,
// before anything sized by it is allocated, with the image's name, its declared size
// and the limit; the texture pipeline marks it undecodable and prepares the rest.
// The same files under a 2 GB address-space limit, through sherpa-cli:
// tests/cli/memory_limit_test.sh.
#include "peak_rss.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/basis.h>
#include <sherpa/texture/image.h>
#include <sherpa/texture/texel_budget.h>
#include <sherpa/texture/texture_pipeline.h>

namespace {

using namespace sherpa::tex;

std::filesystem::path data(const std::string& name) {
    return std::filesystem::path(SHERPA_TEST_DATA_DIR) / name;
}
std::vector<std::uint8_t> bytes_of(const std::string& name) {
    std::ifstream f(data(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

struct Bomb {
    const char* file;
    std::uint32_t width, height;
};
constexpr Bomb kBombs[] = {{"bomb_30000.png", 30000, 30000},
                           {"bomb_65500.jpg", 65500, 65500},
                           {"bomb_16384.webp", 16384, 16384}};

std::string declares(std::uint32_t w, std::uint32_t h) {
    return "declares " + std::to_string(w) + "x" + std::to_string(h) + " texels";
}

TEST(TexelBudget, LimitsAreInclusiveAndTheMessageNamesThem) {
    std::string error;
    EXPECT_TRUE(check_texel_budget(8192, 8192, "a.png", error));
    EXPECT_TRUE(check_texel_budget(16384, 4096, "a.png", error));
    EXPECT_TRUE(check_texel_budget(1, 16384, "a.png", error));
    EXPECT_FALSE(check_texel_budget(8193, 8192, "a.png", error));
    EXPECT_EQ(error, "a.png: declares 8193x8192 texels; Sherpa decodes at most 67108864 texels "
                     "(8192x8192) and 16384 per side per image: not decoded");
    EXPECT_FALSE(check_texel_budget(16385, 1, "", error));
    EXPECT_EQ(error.rfind("declares 16385x1 texels", 0), 0u) << error;
    EXPECT_FALSE(check_texel_budget(std::uint64_t{1} << 40, std::uint64_t{1} << 40, "x", error));
    EXPECT_NE(error.find("1099511627776x1099511627776"), std::string::npos) << error;
}

TEST(DeclaredImageSize, ReadsPngJpegAndWebpHeaders) {
    for (const Bomb& b : kBombs) {
        const auto size = declared_image_size(bytes_of(b.file));
        ASSERT_TRUE(size) << b.file;
        EXPECT_EQ(size->width, b.width) << b.file;
        EXPECT_EQ(size->height, b.height) << b.file;
    }
    // A real JPEG (EXIF and other segments before its frame) agrees with its decoder.
    const std::filesystem::path jpg =
        std::filesystem::path(SHERPA_ASSETS_DIR) / "gltf/VC/glTF/s_04.jpg";
    std::ifstream f(jpg, std::ios::binary);
    const std::vector<std::uint8_t> real{std::istreambuf_iterator<char>(f),
                                         std::istreambuf_iterator<char>()};
    ASSERT_FALSE(real.empty()) << jpg;
    std::uint32_t w = 0, h = 0;
    std::string error;
    ASSERT_TRUE(probe_encoded_image(real, "s_04.jpg", error, &w, &h)) << error;
    const auto size = declared_image_size(real);
    ASSERT_TRUE(size);
    EXPECT_EQ(size->width, w);
    EXPECT_EQ(size->height, h);
    // Cut short or not an image: nothing is claimed.
    std::vector<std::uint8_t> cut = bytes_of("bomb_30000.png");
    cut.resize(20);
    EXPECT_FALSE(declared_image_size(cut));
    EXPECT_FALSE(declared_image_size(bytes_of("bomb_uastc_zstd.ktx2")));
}

TEST(ImageBombs, DecodeAndProbeRefuseThemFromTheHeader) {
    for (const Bomb& b : kBombs) {
        RgbaImage image;
        std::string error;
        EXPECT_FALSE(decode_image_or_ktx2(bytes_of(b.file), b.file, image, error)) << b.file;
        EXPECT_EQ(error.rfind(std::string(b.file) + ": " + declares(b.width, b.height), 0), 0u)
            << error;
        EXPECT_TRUE(image.pixels.empty());
        error.clear();
        EXPECT_FALSE(probe_encoded_image(bytes_of(b.file), b.file, error)) << b.file;
        EXPECT_NE(error.find(declares(b.width, b.height)), std::string::npos) << error;
    }
}

// A 8 KB UASTC KTX2 whose Zstandard level inflates to 256 MiB (16384x16384): refused
// by its header before the level is inflated; probing reads the header only.
// 123 KB of PNG whose 16 zTXt chunks inflate to 7.9 MB each: libpng inflated and kept
// every one while it read the header (126 MB of RSS for a 2x2 image; 64 chunks took
// sherpa-cli info to 635 MB and 26 s). The decoder reads no text: skipped unbuffered.
TEST(ImageBombs, PngTextChunksAreSkippedNotInflated) {
    const auto bytes = bytes_of("ztxt_bomb.png");
    RgbaImage image;
    std::string error;
    const long growth = sherpa::test::peak_rss_growth_kib([&] {
        ASSERT_TRUE(probe_encoded_image(bytes, "ztxt_bomb.png", error)) << error;
        ASSERT_TRUE(decode_encoded_image(bytes, "ztxt_bomb.png", image, error)) << error;
    });
    EXPECT_EQ(image.width, 2u);
    EXPECT_EQ(image.height, 2u);
    EXPECT_EQ(image.pixels[0], 0x80);
    if (growth < 0) GTEST_SKIP() << "no /proc/self/clear_refs: peak RSS not measured";
    EXPECT_LT(growth, 16 * 1024) << "peak RSS grew by " << growth << " KiB";
}

// The image target's reproducers (tests/fuzz/findings/image-*: a PNG that made libpng
// allocate 2.1 GB under OpenImageIO, a JPEG whose damaged IPTC segment OpenImageIO read
// past) probe and decode, or fail with a reason, through the engine's image path; under
// the sanitizer build with no report.
TEST(ImageBombs, FuzzFindingsDecodeOrFailWithAReason) {
    const auto findings = data("../fuzz/findings");
    int replayed = 0;
    for (const auto& dir : std::filesystem::directory_iterator(findings)) {
        if (dir.path().filename().string().rfind("image-", 0) != 0) continue;
        for (const auto& file : std::filesystem::directory_iterator(dir.path())) {
            const std::string name = file.path().filename().string();
            if (name == "finding.txt") continue;
            const auto bytes = bytes_of(file.path().string()); // absolute: data() keeps it
            std::string probe_error, decode_error;
            const bool probed = probe_encoded_image(bytes, name, probe_error);
            EXPECT_TRUE(probed || !probe_error.empty()) << file.path();
            RgbaImage image;
            const bool decoded = decode_encoded_image(bytes, name, image, decode_error);
            EXPECT_TRUE(decoded || !decode_error.empty()) << file.path();
            ++replayed;
        }
    }
    EXPECT_GE(replayed, 2);
}

TEST(ImageBombs, SupercompressedKtx2IsRefusedBeforeInflating) {
    const std::vector<std::uint8_t> ktx2 = bytes_of("bomb_uastc_zstd.ktx2");
    ASSERT_GT(ktx2.size(), 8000u);
    RgbaImage image;
    std::string error;
    EXPECT_FALSE(decode_image_or_ktx2(ktx2, "bomb_uastc_zstd.ktx2", image, error));
    EXPECT_EQ(error.rfind("bomb_uastc_zstd.ktx2: " + declares(16384, 16384), 0), 0u) << error;
    BasisTexture texture;
    EXPECT_FALSE(transcode_ktx2_basis(ktx2, texture, error));
    EXPECT_TRUE(texture.levels.empty());
    EXPECT_FALSE(probe_ktx2_basis(ktx2, error));
    EXPECT_NE(error.find(declares(16384, 16384)), std::string::npos) << error;
}

// Through the texture pipeline (its decode threads) and the image-problem probe of
// `info`: each bomb is one undecodable texture naming its file and size; the good
// image of the same material is prepared.
TEST(ImageBombs, PipelineMarksEachUndecodableAndPreparesTheRest) {
    const sherpa::scene::LoadResult loaded =
        sherpa::scene::load_scene(data("image_bombs.gltf").string());
    ASSERT_TRUE(loaded) << loaded.error;
    PipelineOptions options;
    options.bc7_level = 0;
    options.decode_threads = 4;
    const PreparedTextureSet set = prepare_textures(*loaded.scene, options);
    ASSERT_EQ(set.textures.size(), 5u);
    const std::vector<std::string> files = {"bomb_30000.png", "bomb_65500.jpg", "bomb_16384.webp",
                                            "bomb_uastc_zstd.ktx2", "good_2x2.png"};
    for (const PreparedTexture& t : set.textures) {
        const std::string& file = files.at(std::size_t(t.image));
        if (file == "good_2x2.png") {
            EXPECT_FALSE(t.failed) << t.note;
            EXPECT_EQ(t.width, 2u);
            continue;
        }
        EXPECT_TRUE(t.failed) << file;
        EXPECT_EQ(t.state, CacheState::Undecodable) << file;
        EXPECT_NE(t.note.find("declares"), std::string::npos) << file << ": " << t.note;
        bool warned = false;
        for (const std::string& w : set.warnings)
            warned |= w.find(file) != std::string::npos && w.find("declares") != std::string::npos;
        EXPECT_TRUE(warned) << file << " is named in a warning with its declared size";
    }
    const std::vector<ImageProblem> problems = find_image_problems(*loaded.scene);
    ASSERT_EQ(problems.size(), 4u);
    for (const ImageProblem& p : problems) {
        EXPECT_EQ(p.state, CacheState::Undecodable);
        EXPECT_NE(p.location.find(files.at(std::size_t(p.image))), std::string::npos) << p.location;
        EXPECT_NE(p.reason.find("declares"), std::string::npos) << p.reason;
    }
}

} // namespace
