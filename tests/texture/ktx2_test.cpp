// KTX2 writer/reader: round trips, validation of damaged files, and acceptance by
// an independent reader (the npm package ktx-parse, run through Node).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include <sherpa/core/file_io.h>
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/ktx2.h>

#include "test_images.h"

using namespace sherpa;
using namespace sherpa::tex;

namespace {

Ktx2Texture sample_texture(VkFormat format, std::uint32_t w, std::uint32_t h,
                           std::uint32_t levels) {
    Ktx2Texture t;
    t.format = format, t.width = w, t.height = h;
    for (std::uint32_t l = 0; l < levels; ++l) {
        std::vector<std::uint8_t> data(level_size(format, mip_extent(w, l), mip_extent(h, l)));
        for (std::size_t i = 0; i < data.size(); ++i)
            data[i] = static_cast<std::uint8_t>(i * 31 + l * 7);
        t.levels.push_back(std::move(data));
    }
    t.metadata = {{"sherpa.source-hash", "00ff"}, {"sherpa.settings", "bc7-srgb;q1"}};
    return t;
}

} // namespace

TEST(Ktx2, RoundTripsEveryFormatAndOddSizes) {
    for (VkFormat f : {VkFormat::Bc7SrgbBlock, VkFormat::Bc7UnormBlock, VkFormat::Bc5UnormBlock,
                       VkFormat::R8G8B8A8Srgb, VkFormat::R8G8B8A8Unorm}) {
        for (auto [w, h, levels] :
             {std::tuple{1u, 1u, 1u}, {5u, 3u, 3u}, {64u, 16u, 7u}, {13u, 130u, 8u}}) {
            SCOPED_TRACE(std::string(vk_format_name(f)) + " " + std::to_string(w) + "x" +
                         std::to_string(h));
            const Ktx2Texture in = sample_texture(f, w, h, levels);
            const auto bytes = write_ktx2(in);
            Ktx2Texture out;
            std::string error;
            ASSERT_TRUE(read_ktx2(bytes, out, error)) << error;
            EXPECT_EQ(out.format, f);
            EXPECT_EQ(out.width, w);
            EXPECT_EQ(out.height, h);
            EXPECT_EQ(out.levels, in.levels);
            ASSERT_NE(out.find("sherpa.settings"), nullptr);
            EXPECT_EQ(*out.find("sherpa.settings"), "bc7-srgb;q1");
            ASSERT_NE(out.find("KTXwriter"), nullptr);
        }
    }
}

TEST(Ktx2, StoresLevelsSmallestFirstAndAligned) {
    const auto bytes = write_ktx2(sample_texture(VkFormat::Bc7SrgbBlock, 64, 64, 7));
    auto offset_of = [&](int level) {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v |= std::uint64_t{bytes[80 + 24 * level + i]} << (8 * i);
        return v;
    };
    for (int l = 0; l < 6; ++l) EXPECT_GT(offset_of(l), offset_of(l + 1)) << "level " << l;
    for (int l = 0; l < 7; ++l) EXPECT_EQ(offset_of(l) % 16, 0u);
}

TEST(Ktx2, RejectsDamagedFiles) {
    const auto good = write_ktx2(sample_texture(VkFormat::Bc5UnormBlock, 32, 32, 6));
    Ktx2Texture out;
    std::string error;
    // Truncated anywhere: header, index, or inside the largest (last) level.
    for (std::size_t keep : {std::size_t{0}, std::size_t{40}, std::size_t{100}, good.size() - 1}) {
        const std::vector<std::uint8_t> cut(good.begin(), good.begin() + std::ptrdiff_t(keep));
        EXPECT_FALSE(read_ktx2(cut, out, error)) << "kept " << keep;
    }
    auto damaged = good;
    damaged[1] = 'X';
    EXPECT_FALSE(read_ktx2(damaged, out, error));
    EXPECT_NE(error.find("identifier"), std::string::npos);
    damaged = good;
    damaged[12] = 146; // claims BC7 sRGB, but the DFD says BC5
    EXPECT_FALSE(read_ktx2(damaged, out, error));
    EXPECT_NE(error.find("descriptor"), std::string::npos);
    damaged = good;
    damaged[80 + 8] ^= 0x10; // level 0 byteLength
    EXPECT_FALSE(read_ktx2(damaged, out, error));
}

TEST(Ktx2, WriterRejectsInconsistentInput) {
    Ktx2Texture t = sample_texture(VkFormat::Bc7SrgbBlock, 8, 8, 2);
    t.levels[1].pop_back();
    EXPECT_THROW(write_ktx2(t), std::invalid_argument);
    t = sample_texture(VkFormat::Bc7SrgbBlock, 8, 8, 4);
    t.levels.push_back(t.levels.back()); // a fifth level for an 8x8 texture
    EXPECT_THROW(write_ktx2(t), std::invalid_argument);
}

// Runs ktx-parse (installed on first use into a cache under the build tree) on
// files we wrote and checks what it reports.
TEST(Ktx2, AcceptedByKtxParse) {
    const std::filesystem::path cache = SHERPA_TEST_NPM_CACHE;
    const auto module = cache / "node_modules/ktx-parse/package.json";
    if (!std::filesystem::exists(module)) {
        std::filesystem::create_directories(cache);
        const std::string install = "npm install --prefix '" + cache.string() +
                                    "' --no-audit --no-fund --loglevel=error ktx-parse@2 >'" +
                                    (cache / "install.log").string() + "' 2>&1";
        ASSERT_EQ(std::system(install.c_str()), 0)
            << "could not install the npm package ktx-parse (offline? see "
            << (cache / "install.log") << ")";
    }
    const auto script = cache / "inspect.mjs";
    std::ofstream(script) << R"(import { read } from 'ktx-parse';
import { readFileSync } from 'node:fs';
const out = [];
for (const file of process.argv.slice(2)) {
  const c = read(new Uint8Array(readFileSync(file)));
  const d = c.dataFormatDescriptor[0];
  out.push({ vkFormat: c.vkFormat, width: c.pixelWidth, height: c.pixelHeight, levels: c.levels.length,
    levelBytes: c.levels.map(l => l.levelData.byteLength), colorModel: d.colorModel,
    transfer: d.transferFunction, block: d.texelBlockDimension, bytesPlane: d.bytesPlane,
    samples: d.samples.map(s => [s.bitOffset, s.bitLength, s.channelType]),
    keys: Object.keys(c.keyValue), writer: c.keyValue['KTXwriter'] });
}
console.log(JSON.stringify(out));
)";
    const auto dir = test::fresh_temp_dir("ktxparse");
    struct Case {
        VkFormat format;
        int model;
        int transfer;
    };
    const std::vector<Case> cases = {{VkFormat::Bc7SrgbBlock, 134, 2},
                                     {VkFormat::Bc7UnormBlock, 134, 1},
                                     {VkFormat::Bc5UnormBlock, 132, 1},
                                     {VkFormat::R8G8B8A8Srgb, 1, 2}};
    std::string files;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto path = dir / ("t" + std::to_string(i) + ".ktx2");
        std::string error;
        ASSERT_TRUE(core::write_file_atomic(
            path, write_ktx2(sample_texture(cases[i].format, 20, 12, 5)), error));
        files += " '" + path.string() + "'";
    }
    FILE* pipe = popen(("node '" + script.string() + "'" + files + " 2>&1").c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) output.append(buf, n);
    ASSERT_EQ(pclose(pipe), 0) << output;
    const auto report = nlohmann::json::parse(output);
    ASSERT_EQ(report.size(), cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& r = report[i];
        SCOPED_TRACE(vk_format_name(cases[i].format));
        EXPECT_EQ(r["vkFormat"], static_cast<std::uint32_t>(cases[i].format));
        EXPECT_EQ(r["width"], 20);
        EXPECT_EQ(r["height"], 12);
        EXPECT_EQ(r["levels"], 5);
        EXPECT_EQ(r["levelBytes"][0], level_size(cases[i].format, 20, 12));
        EXPECT_EQ(r["levelBytes"][4], level_size(cases[i].format, 1, 1));
        EXPECT_EQ(r["colorModel"], cases[i].model);
        EXPECT_EQ(r["transfer"], cases[i].transfer);
        EXPECT_EQ(r["writer"], "Sherpa texture pipeline");
        if (is_block_compressed(cases[i].format)) {
            EXPECT_EQ(r["block"], nlohmann::json::parse("[3,3,0,0]"));
            EXPECT_EQ(r["bytesPlane"][0], 16);
        }
    }
    EXPECT_EQ(report[0]["samples"], nlohmann::json::parse("[[0,127,0]]"));
    EXPECT_EQ(report[2]["samples"], nlohmann::json::parse("[[0,63,0],[64,63,1]]"));
    std::filesystem::remove_all(dir);
}
