// Hostile Basis Universal KTX2 input: hand-broken corpus files must end in a
// clear error (or, for flipped payload bits, any result), never a crash or hang.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <random>

#include <sherpa/texture/basis.h>

#include "basisu_corpus.h"

namespace {

using namespace sherpa::tex;

std::vector<std::uint8_t> corpus_bytes(const std::string& name) {
    std::ifstream f(sherpa::test::basis_corpus_dir() / (name + ".ktx2"), std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}
void put64(std::vector<std::uint8_t>& b, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
std::uint64_t get64(const std::vector<std::uint8_t>& b, std::size_t at) {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{b[at + i]} << (8 * i);
    return v;
}
// The error transcode_ktx2_basis gives for `bytes` ("" if it succeeds).
std::string error_of(const std::vector<std::uint8_t>& bytes) {
    BasisTexture t;
    std::string error;
    return transcode_ktx2_basis(bytes, t, error) ? std::string() : error;
}

class BasisuBadInput : public ::testing::Test {
protected:
    void SetUp() override {
        raw = corpus_bytes("logo211_uastc_raw");
        zstd = corpus_bytes("logo211_uastc_zstd");
        ASSERT_GT(raw.size(), 1000u) << "corpus missing: run the basisu_corpus fixture";
        ASSERT_GT(zstd.size(), 1000u);
        ASSERT_EQ(error_of(raw), "");
        ASSERT_EQ(error_of(zstd), "");
    }
    std::vector<std::uint8_t> raw, zstd;
};

TEST_F(BasisuBadInput, EveryTruncationIsAnError) {
    for (std::size_t n = 0; n < zstd.size(); n += 7) {
        const std::vector<std::uint8_t> cut(zstd.begin(), zstd.begin() + std::ptrdiff_t(n));
        EXPECT_NE(error_of(cut), "") << "truncated to " << n << " bytes";
    }
    EXPECT_NE(error_of({raw.begin(), raw.end() - 1}), "");
}

TEST_F(BasisuBadInput, LevelIndexOffsetsAndLengthsThatWrapAreRejected) {
    auto b = raw;
    put64(b, 80, ~std::uint64_t{0} - 8); // level 0 byteOffset near 2^64: offset+length wraps
    EXPECT_NE(error_of(b).find("level 0"), std::string::npos) << error_of(b);
    b = raw;
    put64(b, 88, ~std::uint64_t{0}); // level 0 byteLength
    EXPECT_NE(error_of(b).find("level 0"), std::string::npos) << error_of(b);
    b = raw;
    put64(b, 80 + 24 * 3 + 16, 12345); // level 3 uncompressedByteLength
    EXPECT_NE(error_of(b).find("level 3"), std::string::npos) << error_of(b);
    b = raw;
    put32(b, 40, 40); // levelCount beyond the mip chain
    EXPECT_NE(error_of(b).find("levelCount"), std::string::npos) << error_of(b);
}

TEST_F(BasisuBadInput, CorruptZstandardLevelIsAnError) {
    auto b = zstd;
    const std::uint64_t offset = get64(b, 80);
    for (std::size_t i = 0; i < 16; ++i) b[offset + i] ^= 0xA5;
    EXPECT_NE(error_of(b).find("Zstandard"), std::string::npos) << error_of(b);
}

TEST_F(BasisuBadInput, SupercompressionGlobalDataIsChecked) {
    auto b = zstd;
    put64(b, 64, b.size() - 4), put64(b, 72, 64); // sgd overruns the file
    EXPECT_NE(error_of(b).find("supercompression global data overruns"), std::string::npos)
        << error_of(b);
    b = zstd;
    put64(b, 64, 0), put64(b, 72, 16); // UASTC has no global data
    EXPECT_NE(error_of(b).find("unexpected supercompression global data"), std::string::npos)
        << error_of(b);
    b = zstd;
    put32(b, 44, 7); // unknown supercompressionScheme
    EXPECT_NE(error_of(b).find("supercompressionScheme"), std::string::npos) << error_of(b);
}

TEST_F(BasisuBadInput, HeaderAndDescriptorProblemsAreNamed) {
    auto b = raw;
    put32(b, 12, 37); // VK_FORMAT_R8G8B8A8_UNORM
    EXPECT_NE(error_of(b).find("vkFormat 37"), std::string::npos) << error_of(b);
    b = raw;
    const std::size_t dfd = b[48] | (b[49] << 8);
    b[dfd + 12] = 1; // color model RGBSDA
    EXPECT_NE(error_of(b).find("color model 1"), std::string::npos) << error_of(b);
    b = raw;
    b[dfd + 10] = 0xFF, b[dfd + 11] = 0xFF; // descriptorBlockSize past the DFD
    EXPECT_NE(error_of(b).find("descriptorBlockSize"), std::string::npos) << error_of(b);
    b = raw;
    put32(b, 16, 4); // typeSize
    EXPECT_NE(error_of(b).find("typeSize"), std::string::npos) << error_of(b);
    b = raw;
    put32(b, 20, 1u << 20); // width beyond the supported maximum (the texel budget)
    EXPECT_NE(error_of(b).find("declares 1048576x211 texels"), std::string::npos) << error_of(b);
}

TEST_F(BasisuBadInput, ReservedModeAndBadPatternBlocksAreNamed) {
    auto b = raw;
    const std::uint64_t level0 = get64(b, 80);
    std::fill(b.begin() + std::ptrdiff_t(level0), b.begin() + std::ptrdiff_t(level0 + 16), 0);
    b[level0] = 0x45; // mode code 19 (reserved), 7 bits
    EXPECT_NE(error_of(b).find("reserved UASTC mode"), std::string::npos) << error_of(b);
    // Mode 2 (code 0x1D, 5 bits), 15 hint bits, then PAT = 31 at bit 20 (30 patterns).
    b[level0] = 0x1D, b[level0 + 1] = 0, b[level0 + 2] = 0xF0, b[level0 + 3] = 0x01;
    EXPECT_NE(error_of(b).find("block (0, 0)"), std::string::npos) << error_of(b);
    EXPECT_NE(error_of(b).find("pattern"), std::string::npos) << error_of(b);
}

TEST_F(BasisuBadInput, RandomByteFlipsNeverCrash) {
    std::mt19937 rng(15);
    for (const auto* source : {&raw, &zstd}) {
        for (int trial = 0; trial < 1500; ++trial) {
            auto b = *source;
            const int flips = 1 + int(rng() % 8);
            for (int f = 0; f < flips; ++f) b[rng() % b.size()] ^= std::uint8_t(1u << (rng() % 8));
            BasisTexture t;
            std::string error;
            if (transcode_ktx2_basis(b, t, error)) {
                ASSERT_FALSE(t.levels.empty());
                EXPECT_EQ(t.levels[0].pixels.size(),
                          std::size_t{t.levels[0].width} * t.levels[0].height * 4);
            } else {
                EXPECT_FALSE(error.empty());
            }
        }
    }
}

// ETC1S/BasisLZ: broken supercompression global data and slices.
class BasisuBadEtc1s : public ::testing::Test {
protected:
    void SetUp() override {
        file = corpus_bytes("prop128_etc1s"); // RGB + alpha slices
        ASSERT_GT(file.size(), 1000u) << "corpus missing: run the basisu_corpus fixture";
        ASSERT_EQ(error_of(file), "");
        sgd = get64(file, 64);
        levels = file[40];
    }
    // Byte offset of image descriptor field `field` (0 flags, 1 rgb offset, 2 rgb
    // length, 3 alpha offset, 4 alpha length) of level `level`.
    std::size_t desc(std::size_t level, std::size_t field) const {
        return sgd + 20 + 20 * level + 4 * field;
    }
    std::size_t endpoints_data() const { return sgd + 20 + 20 * levels; }
    std::vector<std::uint8_t> file;
    std::size_t sgd = 0, levels = 0;
};

TEST_F(BasisuBadEtc1s, GlobalDataTooShortOrOverrunIsAnError) {
    auto b = file;
    put64(b, 72, 20); // global data holds no image descriptors
    EXPECT_NE(error_of(b).find("BasisLZ global data too short"), std::string::npos) << error_of(b);
    b = file;
    put32(b, sgd + 4, 0xFFFFFF00u); // endpointsByteLength
    EXPECT_NE(error_of(b).find("overrun"), std::string::npos) << error_of(b);
}

TEST_F(BasisuBadEtc1s, CorruptCodebooksAndTablesAreNamed) {
    auto b = file;
    std::fill_n(b.begin() + std::ptrdiff_t(endpoints_data()), 4, 0); // 0 Huffman symbols
    EXPECT_NE(error_of(b).find("endpoint codebook: bad Huffman table header"), std::string::npos)
        << error_of(b);
    const std::size_t endpoints_length = get64(file, sgd + 4) & 0xFFFFFFFFu;
    const std::size_t selectors_length = get64(file, sgd + 8) & 0xFFFFFFFFu;
    b = file;
    b[endpoints_data() + endpoints_length] = 0x01; // "global selector codebook" bit
    EXPECT_NE(error_of(b).find("global/hybrid"), std::string::npos) << error_of(b);
    b = file;
    std::fill_n(b.begin() + std::ptrdiff_t(endpoints_data() + endpoints_length + selectors_length),
                4, 0);
    EXPECT_NE(error_of(b).find("slice tables"), std::string::npos) << error_of(b);
}

TEST_F(BasisuBadEtc1s, BrokenSlicesAreNamed) {
    auto b = file;
    put32(b, desc(0, 1), 0x7FFFFFF0u); // RGB slice offset past the level
    EXPECT_NE(error_of(b).find("level 0: slice overruns the level"), std::string::npos)
        << error_of(b);
    b = file;
    put32(b, desc(0, 2), 2); // RGB slice cut to 2 bytes: Huffman data runs out
    EXPECT_NE(error_of(b).find("level 0: RGB"), std::string::npos) << error_of(b);
    b = file;
    put32(b, desc(1, 4), 0); // no alpha slice although the DFD declares alpha
    EXPECT_NE(error_of(b).find("level 1: alpha slice missing"), std::string::npos) << error_of(b);
    b = file;
    put32(b, desc(2, 0), 2); // P-frame flag
    EXPECT_NE(error_of(b).find("level 2"), std::string::npos) << error_of(b);
}

TEST_F(BasisuBadEtc1s, RandomByteFlipsNeverCrash) {
    std::mt19937 rng(1515);
    for (int trial = 0; trial < 3000; ++trial) {
        auto b = file;
        const int flips = 1 + int(rng() % 8);
        // Half the trials hit the global data and slices only, past the header.
        const std::size_t from = trial % 2 ? sgd : 0;
        for (int f = 0; f < flips; ++f)
            b[from + rng() % (b.size() - from)] ^= std::uint8_t(1u << (rng() % 8));
        BasisTexture t;
        std::string error;
        if (!transcode_ktx2_basis(b, t, error)) {
            EXPECT_FALSE(error.empty());
        }
    }
}

TEST(BasisuBadFile, FileErrorsNameTheFile) {
    BasisTexture t;
    std::string error;
    EXPECT_FALSE(read_basis_ktx2_file("/nonexistent/broken.ktx2", t, error));
    EXPECT_NE(error.find("broken.ktx2"), std::string::npos) << error;
}

} // namespace
