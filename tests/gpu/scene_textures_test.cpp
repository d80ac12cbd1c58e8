// The GPU layer's textures: the texture pipeline's levels uploaded as they are
// (BC7/BC5 where the device samples them, RGBA8 otherwise), prepared off the
// thread that owns the device, registered in the bindless table and resolved into
// the material records.
#include "gpu_test_support.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/scene_textures.h>
#include <sherpa/texture/block_codecs.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <thread>

namespace sherpa::test {
namespace {

class SceneTexturesTest : public GpuTest {
protected:
    std::vector<std::uint8_t> render_helmet(std::shared_ptr<const tex::PreparedTextureSet> set) {
        render::FrameRequest s;
        s.width = 128;
        s.height = 128;
        std::string error;
        EXPECT_TRUE(render::parse_camera_spec("eye=1.6,0.5,2.6:target=0,0,0", s.camera, error));
        renderer().load(*helmet_, std::move(set));
        return draw(s);
    }
    void SetUp() override {
        GpuTest::SetUp();
        helmet_ = load(gltf_asset("DamagedHelmet"));
        ASSERT_TRUE(helmet_);
    }
    void TearDown() override {
        renderer().unload();
        GpuTest::TearDown();
    }
    std::unique_ptr<scene::Scene> helmet_;
};

// Blocks as they are, also on CPU devices (which decode BC7 at upload by default).
render::TextureSettings block_settings() {
    render::TextureSettings s = test_texture_settings();
    s.decode_bc7_on_cpu = false;
    return s;
}

TEST_F(SceneTexturesTest, DeviceSamplesBcOnLavapipe) {
    // Lavapipe decodes BC formats; a device without them takes the RGBA8 path (below).
    if (context().info().is_cpu()) {
        EXPECT_TRUE(context().info().bc_textures);
    }
}

TEST_F(SceneTexturesTest, PreparedOnAnotherThreadUploadsBlocksWithFullMipChains) {
    if (!context().info().bc_textures) GTEST_SKIP() << "device cannot sample BC";
    // Preparation makes no Vulkan calls: run it where the editor's loader runs it.
    std::shared_ptr<const tex::PreparedTextureSet> set;
    std::thread worker(
        [&] { set = prepare_for_device(*helmet_, context().info(), block_settings()); });
    worker.join();
    ASSERT_TRUE(set);
    renderer().load(*helmet_, set);
    const render::GpuScene& scene = *renderer().scene();
    const render::SceneTextures& textures = scene.materials().textures();
    ASSERT_EQ(textures.records().size(), 5u);
    ASSERT_EQ(textures.gpu().size(), 5u);
    std::multiset<tex::VkFormat> formats;
    std::set<std::uint32_t> slots;
    std::uint64_t bytes = 0;
    for (std::size_t i = 0; i < textures.records().size(); ++i) {
        const tex::PreparedTexture& t = textures.records()[i];
        const render::GpuTexture& g = textures.gpu()[i];
        formats.insert(t.format);
        EXPECT_EQ(g.mip_levels, 12u) << t.source; // 2048 .. 1
        EXPECT_NE(g.slot, scene::kTextureSentinel);
        slots.insert(g.slot);
        // Block data: 1 byte per texel at level 0 (BC7 and BC5 alike), 4/3 over the chain.
        EXPECT_GE(g.bytes, t.bytes_gpu);
        EXPECT_LT(g.bytes, 2048ull * 2048 * 2);
        bytes += g.bytes;
    }
    EXPECT_EQ(formats, (std::multiset<tex::VkFormat>{
                           tex::VkFormat::Bc7SrgbBlock, tex::VkFormat::Bc7SrgbBlock,
                           tex::VkFormat::Bc7UnormBlock, tex::VkFormat::Bc7UnormBlock,
                           tex::VkFormat::Bc5UnormBlock}));
    EXPECT_EQ(slots.size(), 5u);
    EXPECT_EQ(scene.memory().textures, bytes);
    EXPECT_EQ(textures.gpu_bytes(), bytes);

    // The material record names exactly those slots.
    const scene::MaterialInstance& m = helmet_->materials.at(0);
    const scene::GPUMaterialData g = textures.material(m);
    EXPECT_EQ(g.base_color_tex, textures.slot(m.base_color.texture, scene::kRoleColor));
    EXPECT_EQ(g.normal_tex, textures.slot(m.normal.texture, scene::kRoleNormal));
    EXPECT_EQ(g.emissive_tex, textures.slot(m.emissive.texture, scene::kRoleColor));
    EXPECT_EQ(g.occlusion_tex, textures.slot(m.occlusion.texture, scene::kRoleLinear));
    EXPECT_EQ(g.metallic_roughness_tex,
              textures.slot(m.metallic_roughness.texture, scene::kRoleLinear));
    for (std::uint32_t s : {g.base_color_tex, g.normal_tex, g.emissive_tex, g.occlusion_tex,
                            g.metallic_roughness_tex})
        EXPECT_TRUE(slots.count(s)) << s;

    // Without its textures the same material reads the default textures.
    scene::MaterialInstance bare = m;
    bare.base_color = bare.normal = bare.emissive = bare.occlusion = bare.metallic_roughness = {};
    bare.emissive_factor = glm::vec3(0.0f);
    const scene::GPUMaterialData d = textures.material(bare);
    EXPECT_EQ(d.base_color_tex, gpu::kWhiteTexture);
    EXPECT_EQ(d.normal_tex, gpu::kFlatNormalTexture);
    EXPECT_EQ(d.emissive_tex, gpu::kBlackTexture);
    EXPECT_EQ(d.occlusion_tex, gpu::kWhiteTexture);
    EXPECT_EQ(d.metallic_roughness_tex, gpu::kWhiteTexture);
}

TEST_F(SceneTexturesTest, CpuDevicesDecodeBc7AtUploadAndSaySo) {
    if (!context().info().is_cpu() || !context().info().bc_textures)
        GTEST_SKIP() << "BC7 is decoded at upload on CPU devices only";
    const auto decoded = prepare_for_device(*helmet_, context().info(), test_texture_settings());
    const auto blocks = prepare_for_device(*helmet_, context().info(), block_settings());
    ASSERT_EQ(decoded->textures.size(), blocks->textures.size());
    for (std::size_t i = 0; i < blocks->textures.size(); ++i) {
        const tex::PreparedTexture& b = blocks->textures[i];
        const tex::PreparedTexture& d = decoded->textures[i];
        if (b.format == tex::VkFormat::Bc5UnormBlock) {
            EXPECT_EQ(d.format, b.format) << "BC5 samples as fast as RGBA8: kept";
            continue;
        }
        ASSERT_TRUE(b.format == tex::VkFormat::Bc7SrgbBlock ||
                    b.format == tex::VkFormat::Bc7UnormBlock);
        EXPECT_EQ(tex::is_srgb(d.format), tex::is_srgb(b.format)) << b.source;
        EXPECT_FALSE(tex::is_block_compressed(d.format)) << b.source;
        ASSERT_EQ(d.levels.size(), b.levels.size());
        // Every level is exactly the decoding of the cached blocks.
        for (std::size_t l = 0; l < b.levels.size(); ++l)
            EXPECT_EQ(d.levels[l], tex::decode_image(tex::BlockFormat::Bc7, b.levels[l],
                                                     tex::mip_extent(b.width, std::uint32_t(l)),
                                                     tex::mip_extent(b.height, std::uint32_t(l))))
                << b.source << " level " << l;
        EXPECT_EQ(d.state, b.state);
        EXPECT_EQ(d.psnr, b.psnr);
        EXPECT_NE(d.note.find("decoded to RGBA8"), std::string::npos);
    }
    // Nothing to act on: a notice for the report, not a warning.
    ASSERT_FALSE(decoded->notices.empty());
    EXPECT_NE(decoded->notices.back().find("CPU device"), std::string::npos);
    for (const std::string& w : decoded->warnings)
        EXPECT_EQ(w.find("decoded to RGBA8"), std::string::npos) << w;
}

TEST_F(SceneTexturesTest, RefusesSetsWithoutLevelsOrForAnotherScene) {
    const auto good = prepare_for_device(*helmet_, context().info(), test_texture_settings());
    auto stripped = std::make_shared<tex::PreparedTextureSet>(*good);
    stripped->textures[2].levels.clear(); // as after GpuScene released them
    EXPECT_THROW(renderer().load(*helmet_, stripped), gpu::GpuError);
    auto truncated = std::make_shared<tex::PreparedTextureSet>(*good);
    truncated->textures[1].levels[3].pop_back();
    EXPECT_THROW(renderer().load(*helmet_, truncated), gpu::GpuError);
    scene::Scene other = *helmet_;
    other.textures.resize(2); // the set names textures 2..4 too
    EXPECT_THROW(renderer().load(other, good), gpu::GpuError);
    // Nothing half-made stays behind; the good set still loads.
    renderer().load(*helmet_, good);
    EXPECT_EQ(renderer().scene()->materials().textures().image_count(), 5u);
}

TEST_F(SceneTexturesTest, ForcedRgba8FallbackLooksLikeTheBlocksAndCostsFourTimesTheMemory) {
    render::TextureSettings rgba8 = test_texture_settings();
    rgba8.force_rgba8 = true;
    const auto fallback = prepare_for_device(*helmet_, context().info(), rgba8);
    ASSERT_FALSE(fallback->notices.empty());
    EXPECT_NE(fallback->notices.front().find("RGBA8 forced"), std::string::npos);
    for (const tex::PreparedTexture& t : fallback->textures) {
        EXPECT_EQ(t.state, tex::CacheState::Fallback) << t.source;
        EXPECT_FALSE(tex::is_block_compressed(t.format)) << t.source;
    }
    const std::vector<std::uint8_t> plain = render_helmet(fallback);
    const std::uint64_t plain_bytes = renderer().scene()->memory().textures;
    EXPECT_EQ(renderer().scene()->materials().textures().warnings(), fallback->warnings);

    if (!context().info().bc_textures) GTEST_SKIP() << "device cannot sample BC";
    const auto blocks = prepare_for_device(*helmet_, context().info(), block_settings());
    const std::vector<std::uint8_t> compressed = render_helmet(blocks);
    const std::uint64_t block_bytes = renderer().scene()->memory().textures;
    // 1 byte per texel against 4 (tiny mip levels round up to whole 4x4 blocks).
    EXPECT_NEAR(double(plain_bytes) / double(block_bytes), 4.0, 0.01);

    // BC7/BC5 are lossy but close: the same picture within a few levels on average.
    ASSERT_EQ(plain.size(), compressed.size());
    double sum = 0;
    std::size_t far = 0;
    for (std::size_t i = 0; i < plain.size(); i += 4)
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(plain[i + c]) - int(compressed[i + c]));
            sum += d;
            far += d > 24;
        }
    const double mean = sum / double(plain.size() / 4 * 3);
    EXPECT_LT(mean, 2.0);
    EXPECT_LT(double(far) / double(plain.size() / 4 * 3), 0.01);
}

} // namespace
} // namespace sherpa::test
