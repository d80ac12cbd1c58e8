// Missing and undecodable images are reported as what they are (state, file, the
// material slots that read them) and drawn so nobody takes them for intended white:
// a magenta/black checker in colour slots, or the glTF defaults when asked.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_run.h"
#include "reference/reference_images.h"
#include "test_support.h"

namespace {

using sherpa::test::CliRun;
using sherpa::test::run_cli;

const std::string kMissing = (sherpa::test::data_dir() / "missing_texture.gltf").string();
const std::string kCorrupt = (sherpa::test::data_dir() / "corrupt_texture.gltf").string();
const std::string kUses = "material 'Quad' baseColorTexture, occlusionTexture";

struct Counts {
    std::size_t magenta = 0, black = 0, white = 0, other = 0;
};

// Pixels of the central half of the image (the quad covers it), by colour.
Counts centre_colours(const sherpa::test::ReferenceImage& img) {
    Counts c;
    for (std::uint32_t y = img.height / 4; y < img.height * 3 / 4; ++y)
        for (std::uint32_t x = img.width / 4; x < img.width * 3 / 4; ++x) {
            const std::uint8_t* p = img.texel(x, y);
            if (p[0] > 200 && p[1] < 40 && p[2] > 200)
                ++c.magenta;
            else if (p[0] < 40 && p[1] < 40 && p[2] < 40)
                ++c.black;
            else if (p[0] > 245 && p[1] > 245 && p[2] > 245)
                ++c.white;
            else
                ++c.other;
        }
    return c;
}

// One texture or image problem record as the CLI's JSON writes it, in every report.
void expect_problem(const nlohmann::json& record, const std::string& state,
                    const std::string& file) {
    EXPECT_EQ(record["state"], state) << record;
    EXPECT_EQ(record["location"], file) << record;
    EXPECT_EQ(record["uses"], nlohmann::json::array({kUses})) << record;
}

class CliMissingTextures : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("sherpa-missing-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    // Renders the base-colour view of `scene` looking straight at its quad; the PNG
    // is read back by libpng.
    CliRun render(const std::string& scene, const std::string& options,
                  sherpa::test::ReferenceImage& image, nlohmann::json& report) {
        const std::string png = (dir_ / "out.png").string(), json = (dir_ / "out.json").string();
        const CliRun r = run_cli("render '" + scene + "' -o '" + png +
                                 "' --width 64 --height 64 --view base-color --no-cache"
                                 " --camera eye=0,0,2:target=0,0,0 --validation --report '" +
                                 json + "' " + options);
        EXPECT_EQ(r.exit_code, 0) << r.out;
        if (r.exit_code != 0) return r;
        std::string error;
        EXPECT_TRUE(sherpa::test::read_png_reference(png, image, error)) << error;
        report = sherpa::test::read_json(json);
        return r;
    }

    std::filesystem::path dir_;
};

TEST_F(CliMissingTextures, RenderDrawsAMagentaBlackCheckerAndSaysWhatIsMissing) {
    sherpa::test::ReferenceImage image;
    nlohmann::json report;
    const CliRun r = render(kMissing, "", image, report);
    ASSERT_EQ(r.exit_code, 0);
    const Counts c = centre_colours(image);
    const std::size_t total = c.magenta + c.black + c.white + c.other;
    // Half the checks each; filtering at check edges leaves a few in between.
    EXPECT_GT(c.magenta, total / 3) << c.black << " black, " << c.other << " other";
    EXPECT_GT(c.black, total / 3) << c.magenta << " magenta, " << c.other << " other";
    EXPECT_EQ(c.white, 0u);
    // The warning names the state, the file and every slot that reads it.
    const std::string file = (sherpa::test::data_dir() / "does_not_exist.png").string();
    EXPECT_NE(r.out.find("warning: texture missing: " + file + " (used by " + kUses + ")"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("neither encoded bytes"), std::string::npos) << r.out;
    ASSERT_FALSE(report["textures"]["textures"].empty());
    for (const auto& t : report["textures"]["textures"]) expect_problem(t, "missing", file);
    EXPECT_EQ(report["validation_messages"], 0);
}

TEST_F(CliMissingTextures, NeutralDrawsTheGltfDefaultWhite) {
    sherpa::test::ReferenceImage image;
    nlohmann::json report;
    ASSERT_EQ(render(kMissing, "--missing-textures neutral", image, report).exit_code, 0);
    const Counts c = centre_colours(image);
    EXPECT_EQ(c.magenta + c.black + c.other, 0u)
        << c.magenta << " magenta, " << c.black << " black, " << c.other << " other";
    EXPECT_GT(c.white, 0u);
}

TEST_F(CliMissingTextures, UndecodableImageIsCheckeredWithTheDecodersReason) {
    sherpa::test::ReferenceImage image;
    nlohmann::json report;
    const CliRun r = render(kCorrupt, "", image, report);
    ASSERT_EQ(r.exit_code, 0);
    const Counts c = centre_colours(image);
    EXPECT_GT(c.magenta, 0u);
    EXPECT_GT(c.black, 0u);
    EXPECT_NE(r.out.find("warning: texture undecodable: " +
                         (sherpa::test::data_dir() / "corrupt_texture.png").string() +
                         " (used by " + kUses + "): cannot decode: PNG"),
              std::string::npos)
        << r.out;
    for (const auto& t : report["textures"]["textures"]) EXPECT_EQ(t["state"], "undecodable");
}

TEST_F(CliMissingTextures, TexturesAndInfoReportStatePathAndSlots) {
    const std::string file = (sherpa::test::data_dir() / "does_not_exist.png").string();
    const CliRun textures = run_cli("textures '" + kMissing + "' --no-cache --json", "2>/dev/null");
    ASSERT_EQ(textures.exit_code, 0) << textures.out;
    const nlohmann::json tj = nlohmann::json::parse(textures.out);
    ASSERT_EQ(tj["textures"].size(), 2u); // colour and linear role
    for (const auto& t : tj["textures"]) {
        expect_problem(t, "missing", file);
        EXPECT_EQ(t["failed"], true);
    }
    const CliRun info = run_cli("info '" + kMissing + "' --json", "2>/dev/null");
    ASSERT_EQ(info.exit_code, 0) << info.out;
    const nlohmann::json ij = nlohmann::json::parse(info.out);
    ASSERT_EQ(ij["image_problems"].size(), 1u);
    expect_problem(ij["image_problems"][0], "missing", file);
    const CliRun text = run_cli("info '" + kMissing + "'");
    EXPECT_NE(text.out.find("warning: texture missing: " + file + " (used by " + kUses + ")"),
              std::string::npos)
        << text.out;

    const CliRun corrupt = run_cli("info '" + kCorrupt + "' --json", "2>/dev/null");
    const nlohmann::json cj = nlohmann::json::parse(corrupt.out);
    ASSERT_EQ(cj["image_problems"].size(), 1u);
    EXPECT_EQ(cj["image_problems"][0]["state"], "undecodable");
    EXPECT_NE(cj["image_problems"][0]["reason"].get<std::string>().find("PNG"), std::string::npos);
    // A model whose images are all there reports none.
    const CliRun box =
        run_cli("info '" + sherpa::test::gltf_asset("BoxTextured") + "' --json", "2>/dev/null");
    EXPECT_TRUE(nlohmann::json::parse(box.out)["image_problems"].empty());
}

TEST_F(CliMissingTextures, BadModeIsAUsageError) {
    const CliRun r = run_cli("render '" + kMissing + "' -o '" + (dir_ / "x.png").string() +
                             "' --missing-textures pink");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find("--missing-textures needs checker or neutral"), std::string::npos);
}

} // namespace
