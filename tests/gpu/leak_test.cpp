// Loading and unloading a scene gives every GPU object back; frames on a CPU device
// do not fault their working memory in again.
#include "gpu_test_support.h"

#include <sherpa/render/scene_textures.h>

#include <sys/resource.h>

namespace sherpa::test {
namespace {

class LeakTest : public GpuTest {};

TEST_F(LeakTest, TwentyLoadUnloadCyclesOfDamagedHelmetLeaveNothingBehind) {
    auto scene = load(gltf_asset("DamagedHelmet"));
    ASSERT_TRUE(scene);
    // Prepare the textures once (decode, mips, BC7/BC5): the cycles are about GPU
    // objects. Image creation, upload of every level, bindless registration and
    // destruction all still run per cycle.
    const auto textures = prepare_for_device(*scene, context().info(), test_texture_settings());
    ASSERT_EQ(textures->textures.size(), 5u);
    render::FrameRequest s;
    s.width = 32;
    s.height = 32;
    // Baseline after one cycle: pipelines and render targets exist from then on.
    renderer().load(*scene, textures);
    renderer().render(s);
    renderer().unload();
    renderer().resources().flush();
    const std::int64_t objects = gpu::live_vulkan_objects();
    const gpu::ResourceCounts counts = renderer().resources().counts();
    // The counts are exact, so one leaked handle fails the cycle that leaks it; twenty
    // cycles (each uploading 5 textures with every level) also cover reuse of freed
    // slots, at a fifth of the CI time a hundred took.
    for (int i = 0; i < 20; ++i) {
        renderer().load(*scene, textures);
        if (i % 5 == 0) renderer().render(s); // some cycles also draw with the scene
        renderer().unload();
        ASSERT_EQ(renderer().resources().counts().buffers, counts.buffers) << "cycle " << i;
        ASSERT_EQ(renderer().resources().counts().images, counts.images) << "cycle " << i;
    }
    renderer().resources().flush();
    EXPECT_EQ(gpu::live_vulkan_objects(), objects);
    EXPECT_EQ(renderer().resources().counts().total(), counts.total());
    EXPECT_EQ(renderer().resources().stale_handle_uses(), 0u);
}

long minor_page_faults() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_minflt;
}

// On a CPU device the rasterizer's per-frame memory comes from this process's heap;
// the applications keep it mapped (sherpa::core::keep_freed_memory_mapped(), called first
// thing in sherpa-cli, the editor and sherpa-bench-render, and by GpuEnvironment
// before it makes the device: called after that it does not help) instead of
// letting every frame fault it in again. Without that, 2CylinderEngine (many draws)
// took about 5,400 page faults per 720p frame; with it, about 300.
TEST_F(LeakTest, CpuDeviceFramesDoNotFaultTheirWorkingMemoryInAgain) {
    if (!context().info().is_cpu()) GTEST_SKIP() << "the heap setting is for CPU devices";
    auto scene = load(gltf_asset("2CylinderEngine"));
    ASSERT_TRUE(scene);
    renderer().load(*scene); // textures prepared with the renderer's test_texture_settings()
    render::FrameRequest s;  // 1280x720, lit
    for (int i = 0; i < 3; ++i) renderer().render(s); // pipelines, shadow map, first frames
    const long before = minor_page_faults();
    constexpr int kFrames = 10;
    for (int i = 0; i < kFrames; ++i) renderer().render(s);
    const long per_frame = (minor_page_faults() - before) / kFrames;
    renderer().unload();
    EXPECT_LT(per_frame, 2000) << "page faults per frame";
}

} // namespace
} // namespace sherpa::test
