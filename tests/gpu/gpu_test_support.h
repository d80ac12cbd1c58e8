#pragma once
// One validated Vulkan context and renderer for the whole test binary (creating a
// device per test would dominate the run time), and a fixture that fails any test
// during which the validation layer said anything.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <sherpa/core/heap_tuning.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/renderer.h>
#include <sherpa/render/scene_textures.h>
#include <sherpa/scene/scene_loader.h>

#include "rhi_test_support.h"
#include "test_support.h"

namespace sherpa::test {

// Texture preparation for GPU tests: a cache in the build tree (never the user's),
// shared by the tests so that the DamagedHelmet textures are compressed once.
inline render::TextureSettings test_texture_settings() {
    render::TextureSettings s;
    s.cache_dir = std::filesystem::path(SHERPA_TEST_TEXTURE_CACHE);
    return s;
}

// A scene setup with `streams` uploaded, the rest as by default.
inline render::SceneSetup streams_setup(render::StreamPolicy streams) {
    render::SceneSetup setup;
    setup.streams = streams;
    return setup;
}

// `scene`'s textures prepared for `device` with `settings`, as sherpa-cli render does.
inline std::shared_ptr<const tex::PreparedTextureSet>
prepare_for_device(const scene::Scene& scene, const gpu::DeviceInfo& device,
                   const render::TextureSettings& settings) {
    return tex::prepare_scene_textures(scene, render::texture_target(device, settings),
                                       render::texture_pipeline_options(settings));
}

// RGBA8 pixels where one of the first `channels` channels differs by more than
// `tolerance` (the sizes must match).
inline std::size_t differing_pixels(const std::vector<std::uint8_t>& a,
                                    const std::vector<std::uint8_t>& b, int tolerance,
                                    int channels = 4) {
    EXPECT_EQ(a.size(), b.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4)
        for (int ch = 0; ch < channels; ++ch)
            if (std::abs(int(a[i + ch]) - int(b[i + ch])) > tolerance) {
                ++n;
                break;
            }
    return n;
}

struct GpuEnvironment {
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<render::Renderer> renderer;
    GpuEnvironment() {
        core::keep_freed_memory_mapped(); // as every application does, before any device exists
        gpu::ContextOptions options;
        options.validation = true; // every GPU test runs under the Khronos layer
        context = std::make_unique<gpu::Context>(options);
        render::RendererOptions renderer_options;
        renderer_options.textures = test_texture_settings();
        renderer = std::make_unique<render::Renderer>(*context, renderer_options);
    }
    static GpuEnvironment& get() {
        static GpuEnvironment env;
        return env;
    }
    ~GpuEnvironment() {
        renderer.reset(); // before the device it was made on
        context.reset();
    }
};

class GpuTest : public ::testing::Test {
protected:
    gpu::Context& context() { return *GpuEnvironment::get().context; }
    render::Renderer& renderer() { return *GpuEnvironment::get().renderer; }

    void SetUp() override { seen_ = context().validation().count(); }
    void TearDown() override { expect_no_validation_since(context(), seen_); }

    // The frame `s` asks for, as RGBA8 rows (top first).
    std::vector<std::uint8_t> draw(const render::FrameRequest& s) {
        std::vector<std::uint8_t> rgba;
        renderer().render(s, &rgba);
        return rgba;
    }

    static std::unique_ptr<scene::Scene> load(const std::string& spec) {
        scene::LoadResult r = scene::load_scene(spec);
        EXPECT_TRUE(r) << spec << ": " << r.error;
        return std::move(r.scene);
    }

private:
    std::size_t seen_ = 0;
};

} // namespace sherpa::test
