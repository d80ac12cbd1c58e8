// tex::prepare_scene_textures for a TextureTarget: what a device without BC, a user
// forcing RGBA8 and a CPU device get, each against the blocks a BC device gets
// (decoded by the texture layer's block decoder, which the block-codec tests hold to
// the reference).
#include <gtest/gtest.h>

#include <algorithm>

#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/ktx2.h>
#include <sherpa/texture/texture_target.h>

#include "test_images.h"

using namespace sherpa;
using namespace sherpa::tex;

namespace {

// One instanced material with a base colour (BC7 sRGB) and a normal map (BC5).
scene::Scene colour_and_normal_scene() {
    scene::Scene s;
    const RgbaImage images[] = {test::synthetic_image(16, 12, true, 7),
                                test::synthetic_image(8, 8, false, 3)};
    for (int i = 0; i < 2; ++i) {
        scene::ImageRecord rec;
        rec.name = "image" + std::to_string(i);
        rec.uri = rec.name + ".png", rec.mime_type = "image/png";
        rec.encoded = test::png_bytes(images[i], rec.name);
        rec.byte_size = rec.encoded.size();
        s.images.push_back(std::move(rec));
    }
    s.textures = {{"colour", 0, -1, scene::kRoleColor}, {"normal", 1, -1, scene::kRoleNormal}};
    scene::MaterialInstance m;
    m.base_color.texture = 0, m.normal.texture = 1;
    s.materials = {m};
    s.instances.resize(1);
    s.instances[0].material_id = 0;
    return s;
}

PipelineOptions fast_options() {
    PipelineOptions o;
    o.bc7_level = 0; // no cache: every run prepares from the sources
    return o;
}

const PreparedTexture& in_role(const PreparedTextureSet& set, scene::TextureRole role) {
    const auto it = std::find_if(set.textures.begin(), set.textures.end(),
                                 [&](const PreparedTexture& t) { return t.role == role; });
    EXPECT_NE(it, set.textures.end());
    return *it;
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(text) != std::string::npos; });
}

} // namespace

TEST(TextureTarget, BcDeviceGetsBlocksAndNoMessage) {
    const auto set =
        prepare_scene_textures(colour_and_normal_scene(), {true, false, "GPU"}, fast_options());
    ASSERT_EQ(set->textures.size(), 2u);
    EXPECT_EQ(in_role(*set, scene::kRoleColor).format, VkFormat::Bc7SrgbBlock);
    EXPECT_EQ(in_role(*set, scene::kRoleNormal).format, VkFormat::Bc5UnormBlock);
    EXPECT_TRUE(set->warnings.empty());
    EXPECT_TRUE(set->notices.empty());
}

TEST(TextureTarget, DeviceWithoutBcGetsRgba8AndAWarningNamingIt) {
    const auto set =
        prepare_scene_textures(colour_and_normal_scene(), {false, false, "OldGPU"}, fast_options());
    EXPECT_EQ(in_role(*set, scene::kRoleColor).format, VkFormat::R8G8B8A8Srgb);
    EXPECT_EQ(in_role(*set, scene::kRoleNormal).format, VkFormat::R8G8B8A8Unorm);
    ASSERT_FALSE(set->warnings.empty());
    EXPECT_EQ(set->warnings.front().rfind("OldGPU cannot sample BC7/BC5", 0), 0u);
    // The pipeline's own device-less warning is replaced, not repeated.
    EXPECT_FALSE(mentions(set->warnings, "device cannot sample BC formats"));
    EXPECT_TRUE(set->notices.empty());
}

TEST(TextureTarget, ForcedRgba8IsANoticeNotAWarning) {
    PipelineOptions o = fast_options();
    o.device_supports_bc = false; // sherpa-cli --no-bc, the editor's source textures
    const auto set = prepare_scene_textures(colour_and_normal_scene(), {true, false, "GPU"}, o);
    EXPECT_EQ(in_role(*set, scene::kRoleColor).format, VkFormat::R8G8B8A8Srgb);
    EXPECT_TRUE(set->warnings.empty());
    EXPECT_TRUE(mentions(set->notices, "RGBA8 forced"));
    EXPECT_TRUE(mentions(set->notices, "although GPU samples BC7/BC5"));
}

TEST(TextureTarget, CpuDecodeGivesTheBlocksPixelsAndKeepsBc5) {
    const scene::Scene scene = colour_and_normal_scene();
    const auto blocks = prepare_scene_textures(scene, {true, false, "GPU"}, fast_options());
    const auto decoded = prepare_scene_textures(scene, {true, true, "lavapipe"}, fast_options());
    const PreparedTexture& b = in_role(*blocks, scene::kRoleColor);
    const PreparedTexture& d = in_role(*decoded, scene::kRoleColor);
    EXPECT_EQ(d.format, VkFormat::R8G8B8A8Srgb);
    ASSERT_EQ(d.levels.size(), b.levels.size());
    for (std::size_t l = 0; l < b.levels.size(); ++l) {
        const auto level = static_cast<std::uint32_t>(l);
        EXPECT_EQ(d.levels[l],
                  decode_image(BlockFormat::Bc7, b.levels[l], mip_extent(b.width, level),
                               mip_extent(b.height, level)))
            << "level " << l;
    }
    EXPECT_NE(d.note.find("decoded to RGBA8 for the CPU device"), std::string::npos);
    EXPECT_EQ(in_role(*decoded, scene::kRoleNormal).format, VkFormat::Bc5UnormBlock);
    EXPECT_TRUE(
        mentions(decoded->notices, "1 BC7 texture(s) decoded to RGBA8 at upload: lavapipe"));
    EXPECT_TRUE(decoded->warnings.empty());
}
