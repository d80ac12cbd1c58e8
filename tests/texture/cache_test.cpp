// Texture cache and pipeline: hits on the second load, recovery from damaged
// files, stale entries, concurrent writers, keys that follow the settings, LRU
// eviction, the RGBA8 fallback and (image, role) collection over a scene.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include <sherpa/core/file_io.h>
#include <sherpa/texture/texture_pipeline.h>

#include "test_images.h"

using namespace sherpa;
using namespace sherpa::tex;

namespace {

// A scene with two materials on one instance each: material 0 uses image 0 as
// base colour (through two textures sharing the image) and image 1 as normal
// map; material 1 (alpha-masked) uses image 0 again as base colour; material 2
// is not instanced, so its image 2 must not be touched.
scene::Scene small_scene() {
    scene::Scene s;
    auto add_image = [&](RgbaImage img, const std::string& name) {
        scene::ImageRecord rec;
        rec.name = name, rec.uri = name + ".png", rec.mime_type = "image/png";
        rec.encoded = test::png_bytes(img, name);
        rec.byte_size = rec.encoded.size();
        s.images.push_back(std::move(rec));
    };
    add_image(test::load_crop(test::assets_dir() / "textures/sponza/16275776544635328252.png", 480,
                              470, 24, 20),
              "albedo");
    add_image(test::load_crop(test::assets_dir() / "gltf/DamagedHelmet/glTF/Default_normal.jpg",
                              900, 900, 32, 32),
              "normal");
    add_image(test::synthetic_image(8, 8, false, 2), "unused");
    s.textures = {{"t0", 0, -1, scene::kRoleColor},
                  {"t1", 0, -1, scene::kRoleColor},
                  {"t2", 1, -1, scene::kRoleNormal},
                  {"t3", 2, -1, scene::kRoleColor}};
    scene::MaterialInstance m0, m1, m2;
    m0.base_color.texture = 0, m0.normal.texture = 2;
    m1.base_color.texture = 1, m1.alpha_mode = scene::AlphaMode::Mask, m1.alpha_cutoff = 0.4f;
    m2.base_color.texture = 3;
    s.materials = {m0, m1, m2};
    s.instances.resize(2);
    s.instances[0].material_id = 0, s.instances[1].material_id = 1;
    return s;
}

} // namespace

TEST(TextureUses, DedupeByImageAndSkipUnusedMaterials) {
    const auto uses = collect_texture_uses(small_scene());
    ASSERT_EQ(uses.size(), 2u);
    EXPECT_EQ(uses[0].image, 0);
    EXPECT_EQ(uses[0].role, scene::kRoleColor);
    EXPECT_EQ(uses[0].textures, (std::vector<std::int32_t>{0, 1}));
    ASSERT_TRUE(uses[0].alpha_cutoff.has_value());
    EXPECT_FLOAT_EQ(*uses[0].alpha_cutoff, 0.4f);
    EXPECT_EQ(uses[1].image, 1);
    EXPECT_EQ(uses[1].role, scene::kRoleNormal);
}

TEST(TextureUses, DifferentCutoffsOnOneImageGetPlainMips) {
    scene::Scene s = small_scene();
    // Texture 0 shares image 0 with masked texture 1 (cutoff 0.4); mask it at 0.7 too.
    s.materials[0].alpha_mode = scene::AlphaMode::Mask, s.materials[0].alpha_cutoff = 0.7f;
    auto uses = collect_texture_uses(s);
    ASSERT_EQ(uses[0].image, 0);
    EXPECT_FALSE(uses[0].alpha_cutoff.has_value()); // no one scale keeps both coverages
    s.materials[0].alpha_cutoff = 0.4f;             // the same cutoff twice: kept
    uses = collect_texture_uses(s);
    ASSERT_TRUE(uses[0].alpha_cutoff.has_value());
    EXPECT_FLOAT_EQ(*uses[0].alpha_cutoff, 0.4f);
}

TEST(TexturePipeline, MissThenHitWithSameLevels) {
    const auto dir = test::fresh_temp_dir("cache-hit");
    const scene::Scene scene = small_scene();
    const auto first = prepare_textures(scene, test::cache_test_options(dir));
    ASSERT_EQ(first.textures.size(), 2u);
    for (const auto& t : first.textures) {
        EXPECT_EQ(t.state, CacheState::Miss);
        EXPECT_TRUE(std::filesystem::exists(t.cache_file));
        EXPECT_GT(t.bytes_on_disk, t.bytes_gpu); // header + metadata on top of the levels
        ASSERT_TRUE(t.psnr.has_value());
        EXPECT_GT(*t.psnr, 30.0);
    }
    EXPECT_EQ(first.textures[0].format, VkFormat::Bc7SrgbBlock);
    EXPECT_EQ(first.textures[1].format, VkFormat::Bc5UnormBlock);
    EXPECT_EQ(first.textures[0].levels.size(), 5u); // 24x20 -> 1x1
    EXPECT_EQ(first.find(1, scene::kRoleColor), 0);
    EXPECT_EQ(first.find(2, scene::kRoleNormal), 1);
    EXPECT_EQ(first.find(3, scene::kRoleColor), -1);

    const auto second = prepare_textures(scene, test::cache_test_options(dir));
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(second.textures[i].state, CacheState::Hit);
        EXPECT_EQ(second.textures[i].levels, first.textures[i].levels);
        EXPECT_EQ(second.textures[i].decode_ms, 0.0); // a hit never decodes
        ASSERT_TRUE(second.textures[i].psnr.has_value()) << "texture " << i;
        if (std::isinf(*first.textures[i].psnr)) // lossless (flat) normal crop
            EXPECT_EQ(*second.textures[i].psnr, *first.textures[i].psnr);
        else
            EXPECT_NEAR(*second.textures[i].psnr, *first.textures[i].psnr, 1e-3);
    }
    std::filesystem::remove_all(dir);
}

TEST(TexturePipeline, DamagedFilesAreReportedAndReplaced) {
    const auto dir = test::fresh_temp_dir("cache-corrupt");
    const scene::Scene scene = small_scene();
    const auto first = prepare_textures(scene, test::cache_test_options(dir));
    const auto file = first.textures[0].cache_file;
    std::vector<std::uint8_t> bytes;
    std::string error;
    ASSERT_TRUE(core::read_file(file, bytes, error));
    const std::vector<std::vector<std::uint8_t>> damage = {
        std::vector<std::uint8_t>(bytes.begin(),
                                  bytes.begin() + std::ptrdiff_t(bytes.size() / 2)), // truncated
        [&] {
            auto b = bytes;
            b[b.size() - 5] ^= 0xFF;
            return b;
        }(), // level data flipped
        [&] {
            auto b = bytes;
            b[0] = 0;
            return b;
        }(), // header
    };
    for (const auto& damaged : damage) {
        ASSERT_TRUE(core::write_file_atomic(file, damaged, error));
        const auto again = prepare_textures(scene, test::cache_test_options(dir));
        EXPECT_EQ(again.textures[0].state, CacheState::Recompressed);
        EXPECT_FALSE(again.textures[0].note.empty());
        EXPECT_FALSE(again.warnings.empty());
        EXPECT_EQ(again.textures[0].levels, first.textures[0].levels);
        EXPECT_EQ(prepare_textures(scene, test::cache_test_options(dir)).textures[0].state,
                  CacheState::Hit);
    }
    std::filesystem::remove_all(dir);
}

TEST(TexturePipeline, ResolvesMaterialTexturesToBindlessSlots) {
    const scene::Scene scene = small_scene();
    PipelineOptions o;
    o.bc7_level = 0;
    const auto set = prepare_textures(scene, o);
    const std::vector<std::uint32_t> slots = {7, 9}; // where the GPU layer put set.textures[0], [1]
    const scene::GPUMaterialData m0 = resolve_material(scene.materials[0], set, slots);
    EXPECT_EQ(m0.base_color_tex, 7u);
    EXPECT_EQ(m0.normal_tex, 9u);
    EXPECT_EQ(m0.emissive_tex, scene::kTextureSentinel);
    EXPECT_EQ(resolve_material(scene.materials[1], set, slots).base_color_tex, 7u); // shared image
    EXPECT_EQ(resolve_material(scene.materials[2], set, slots).base_color_tex,
              scene::kTextureSentinel); // not displayed
}

TEST(TexturePipeline, FileForAnotherRecipeIsStale) {
    const auto dir = test::fresh_temp_dir("cache-stale");
    const scene::Scene scene = small_scene();
    const auto first = prepare_textures(scene, test::cache_test_options(dir));
    // Put texture 1's valid file where texture 0's key points.
    std::filesystem::copy_file(first.textures[1].cache_file, first.textures[0].cache_file,
                               std::filesystem::copy_options::overwrite_existing);
    const auto again = prepare_textures(scene, test::cache_test_options(dir));
    EXPECT_EQ(again.textures[0].state, CacheState::Stale);
    EXPECT_EQ(again.textures[0].levels, first.textures[0].levels);
    std::filesystem::remove_all(dir);
}

TEST(TexturePipeline, ConcurrentWritersLeaveOneValidFile) {
    const auto dir = test::fresh_temp_dir("cache-concurrent");
    const scene::Scene scene = small_scene();
    std::vector<PreparedTextureSet> results(4);
    std::vector<std::thread> writers;
    for (auto& r : results)
        writers.emplace_back([&] { r = prepare_textures(scene, test::cache_test_options(dir)); });
    for (auto& w : writers) w.join();
    for (const auto& r : results) {
        EXPECT_TRUE(r.warnings.empty());
        EXPECT_EQ(r.textures[0].levels, results[0].textures[0].levels);
    }
    const auto after = prepare_textures(scene, test::cache_test_options(dir));
    EXPECT_EQ(after.textures[0].state, CacheState::Hit);
    EXPECT_EQ(after.textures[1].state, CacheState::Hit);
    // Each entry was compressed once: the others waited on its lock and reused it.
    for (std::size_t t = 0; t < 2; ++t) {
        int compressed = 0;
        for (const auto& r : results) compressed += r.textures[t].state == CacheState::Miss;
        EXPECT_EQ(compressed, 1) << "texture " << t;
    }
    std::size_t entries = 0, temps = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        entries += e.path().extension() == ".ktx2";
        temps += e.path().filename().string().find(".tmp.") != std::string::npos;
    }
    EXPECT_EQ(entries, 2u);
    EXPECT_EQ(temps, 0u); // no temp files left behind
    std::filesystem::remove_all(dir);
}

TEST(TexturePipeline, KeyFollowsEverySetting) {
    const auto uses = collect_texture_uses(small_scene());
    PipelineOptions base;
    const std::string recipe = texture_recipe(uses[0], base);
    EXPECT_NE(recipe.find("sherpa-texture/" + std::to_string(kTextureEncoderVersion)),
              std::string::npos);
    PipelineOptions other_level = base;
    other_level.bc7_level = base.bc7_level + 1;
    PipelineOptions fallback = base;
    fallback.device_supports_bc = false;
    TextureUse no_mask = uses[0];
    no_mask.alpha_cutoff.reset();
    const Hash128 source = hash_bytes(small_scene().images[0].encoded);
    const Hash128 key = cache_key(source, recipe);
    EXPECT_NE(key, cache_key(source, texture_recipe(uses[0], other_level)));
    EXPECT_NE(key, cache_key(source, texture_recipe(uses[0], fallback)));
    EXPECT_NE(key, cache_key(source, texture_recipe(no_mask, base)));
    EXPECT_NE(key, cache_key(hash_bytes(small_scene().images[1].encoded), recipe));
    // The BC5 level only matters for normal maps.
    PipelineOptions bc5 = base;
    bc5.bc5_level = base.bc5_level == kBc5MaxLevel ? kBc5MinLevel : kBc5MaxLevel;
    EXPECT_EQ(recipe, texture_recipe(uses[0], bc5));
    EXPECT_NE(texture_recipe(uses[1], base), texture_recipe(uses[1], bc5));
}

TEST(TextureCache, EvictsLeastRecentlyUsedBeyondCap) {
    const auto dir = test::fresh_temp_dir("cache-lru");
    Ktx2Texture t{VkFormat::R8G8B8A8Unorm, 16, 16, {std::vector<std::uint8_t>(16 * 16 * 4, 7)}, {}};
    std::string error;
    const Hash128 src{1, 2};
    const Hash128 a{0, 1}, b{0, 2}, c{0, 3};
    ASSERT_TRUE(TextureCache(dir).store(a, src, "r", t, error)) << error;
    const std::uint64_t one_file = std::filesystem::file_size(TextureCache(dir).file_for(a));
    const TextureCache cache(dir, 2 * one_file + one_file / 2); // room for two files
    ASSERT_TRUE(cache.store(b, src, "r", t, error)) << error;
    // Age both, then use `a`: `b` becomes the least recently used.
    const auto old = std::filesystem::file_time_type::clock::now() - std::chrono::hours(2);
    std::filesystem::last_write_time(cache.file_for(a), old);
    std::filesystem::last_write_time(cache.file_for(b), old + std::chrono::minutes(1));
    EXPECT_EQ(cache.load(a, src, "r").state, LookupState::Hit);
    ASSERT_TRUE(cache.store(c, src, "r", t, error)) << error;
    EXPECT_TRUE(std::filesystem::exists(cache.file_for(a)));
    EXPECT_FALSE(std::filesystem::exists(cache.file_for(b)));
    EXPECT_TRUE(std::filesystem::exists(cache.file_for(c)));
    std::filesystem::remove_all(dir);
}

TEST(TexturePipeline, FallsBackToRgba8WithoutBcSupport) {
    const auto dir = test::fresh_temp_dir("cache-fallback");
    PipelineOptions o = test::cache_test_options(dir);
    o.device_supports_bc = false;
    const auto set = prepare_textures(small_scene(), o);
    EXPECT_FALSE(set.warnings.empty());
    EXPECT_EQ(set.textures[0].format, VkFormat::R8G8B8A8Srgb);
    EXPECT_EQ(set.textures[1].format, VkFormat::R8G8B8A8Unorm);
    for (const auto& t : set.textures) {
        EXPECT_EQ(t.state, CacheState::Fallback);
        EXPECT_EQ(t.levels[0].size(), std::size_t{t.width} * t.height * 4);
    }
    std::filesystem::remove_all(dir);
}

TEST(TexturePipeline, WorksWithoutCache) {
    PipelineOptions o;
    o.bc7_level = 0;
    const auto set = prepare_textures(small_scene(), o);
    ASSERT_EQ(set.textures.size(), 2u);
    EXPECT_TRUE(set.textures[0].cache_file.empty());
    EXPECT_EQ(set.textures[0].bytes_on_disk, 0u);
    EXPECT_EQ(set.textures[0].state, CacheState::Miss);
}

TEST(TextureCache, DefaultDirectoryFollowsXdg) {
    EXPECT_EQ(default_cache_dir(std::string("/x/cache"), std::string("/home/u")),
              "/x/cache/sherpa/textures");
    EXPECT_EQ(default_cache_dir(std::nullopt, std::string("/home/u")),
              "/home/u/.cache/sherpa/textures");
    EXPECT_EQ(default_cache_dir(std::string("relative"), std::string("/home/u")),
              "/home/u/.cache/sherpa/textures");
    EXPECT_EQ(default_cache_dir(std::string(""), std::string("/home/u")),
              "/home/u/.cache/sherpa/textures");
}

namespace {

TEST(TexturePipeline, ProgressCountsEveryTexture) {
    const auto dir = test::fresh_temp_dir("cache-progress");
    const scene::Scene scene = small_scene();
    std::vector<std::pair<std::size_t, std::size_t>> reports;
    PipelineOptions options = test::cache_test_options(dir);
    options.progress = [&](std::size_t done, std::size_t total) {
        reports.emplace_back(done, total);
    };
    const auto set = prepare_textures(scene, options);
    ASSERT_EQ(set.textures.size(), 2u);
    EXPECT_FALSE(set.cancelled);
    // 0 of 2 before the misses, then one report per texture made.
    const std::vector<std::pair<std::size_t, std::size_t>> expected = {{0, 2}, {1, 2}, {2, 2}};
    EXPECT_EQ(reports, expected);
    reports.clear();
    prepare_textures(scene, options); // all hits: ready at once
    ASSERT_FALSE(reports.empty());
    EXPECT_EQ(reports.front(), (std::pair<std::size_t, std::size_t>{2, 2}));
}

TEST(TexturePipeline, CancelStopsAndReturnsNothing) {
    const auto dir = test::fresh_temp_dir("cache-cancel");
    const scene::Scene scene = small_scene();
    core::CancelToken token;
    PipelineOptions options = test::cache_test_options(dir);
    options.cancel = &token;
    // Cancelled after the first texture is made: the second is never compressed.
    options.progress = [&](std::size_t done, std::size_t) {
        if (done == 1) token.cancel();
    };
    const auto set = prepare_textures(scene, options);
    EXPECT_TRUE(set.cancelled);
    EXPECT_TRUE(set.textures.empty());
    // A later run without cancel completes (the first texture's cache file is a hit).
    options.cancel = nullptr;
    options.progress = nullptr;
    const auto again = prepare_textures(scene, options);
    ASSERT_EQ(again.textures.size(), 2u);
    EXPECT_EQ(again.textures[0].state, CacheState::Hit);
    EXPECT_EQ(again.textures[1].state, CacheState::Miss);
}

} // namespace
