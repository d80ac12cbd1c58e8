// The path tracer's light list takes the emissive images' luminance grids from the
// texture pipeline (texture_pipeline.h: made while it decodes an emissive image, kept in
// its cache entry) instead of decoding the images again: on DamagedHelmet the list made
// that way is byte for byte the list made by decoding, after a cache miss and a hit.
#include "gpu_test_support.h"

#include <sherpa/render/emissive_lights.h>
#include <sherpa/scene/scene_loader.h>
#include <sherpa/texture/texture_pipeline.h>

#include <chrono>
#include <cstdio>
#include <cstring>

namespace sherpa::test {
namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

bool same_list(const render::EmissiveLights& a, const render::EmissiveLights& b) {
    return a.triangles.size() == b.triangles.size() && a.power == b.power &&
           a.sampled_power == b.sampled_power && a.inv_power == b.inv_power &&
           std::memcmp(a.triangles.data(), b.triangles.data(),
                       a.triangles.size() * sizeof(render::EmissiveTriangle)) == 0;
}

TEST(EmissiveLightsCpu, TexturePipelineGridGivesTheSameListWithoutDecoding) {
    scene::LoadResult loaded = scene::load_scene(gltf_asset("DamagedHelmet"));
    ASSERT_TRUE(loaded) << loaded.error;
    const scene::Scene& scene = *loaded.scene;
    auto start = std::chrono::steady_clock::now();
    const render::EmissiveLights decoded = render::emissive_lights(scene);
    const double decoded_ms = ms_since(start);
    ASSERT_FALSE(decoded.triangles.empty());
    ASSERT_EQ(decoded.textures_read, 1u);

    const std::filesystem::path cache = std::filesystem::temp_directory_path() /
                                        ("sherpa_emissive_reuse_" + std::to_string(::getpid()));
    std::filesystem::remove_all(cache);
    tex::PipelineOptions options;
    options.cache_dir = cache;
    options.device_supports_bc = false; // RGBA8 levels: no block encoding to wait for
    for (const char* pass : {"miss", "hit"}) {
        SCOPED_TRACE(pass);
        const tex::PreparedTextureSet set = tex::prepare_textures(scene, options);
        std::size_t grids = 0;
        for (const tex::PreparedTexture& t : set.textures) grids += t.luminance != nullptr;
        EXPECT_EQ(grids, 1u) << "only the emissive image gets a grid";
        start = std::chrono::steady_clock::now();
        const render::EmissiveLights reused =
            render::emissive_lights(scene, render::kMaxEmissiveTriangles, &set);
        const double reused_ms = ms_since(start);
        EXPECT_EQ(reused.textures_read, 0u);
        EXPECT_EQ(reused.textures_reused, 1u);
        EXPECT_TRUE(same_list(decoded, reused));
        EXPECT_TRUE(reused.warnings.empty());
        std::printf("DamagedHelmet light list (cache %s): %.1f ms decoding the emissive image, "
                    "%.1f ms with the texture pipeline's grid\n",
                    pass, decoded_ms, reused_ms);
    }
    std::filesystem::remove_all(cache);
}

// The grid's cache bytes read back as the same grid; other bytes are refused.
TEST(EmissiveLightsCpu, LuminanceGridBytesRoundTrip) {
    std::vector<std::uint8_t> rgba(300 * 7 * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::uint8_t(i * 37);
    const tex::LuminanceGrid g = tex::luminance_grid(300, 7, rgba);
    const std::string bytes = tex::encode_luminance_grid(g);
    tex::LuminanceGrid back;
    ASSERT_TRUE(tex::decode_luminance_grid(bytes, back));
    EXPECT_EQ(back.width, g.width);
    EXPECT_EQ(back.height, g.height);
    EXPECT_EQ(back.mean, g.mean);
    EXPECT_EQ(back.texels, g.texels);
    EXPECT_FALSE(tex::decode_luminance_grid(bytes.substr(0, bytes.size() - 1), back));
    EXPECT_FALSE(tex::decode_luminance_grid("sherpa", back));
}

} // namespace
} // namespace sherpa::test
