// Culling inside the renderer: per-pass statistics (camera and each shadow
// cascade), the GPU-driven path against the CPU path, check mode, and cascade
// culling that removes shadow draws without changing the image.
#include "gpu_test_support.h"

#include <sherpa/render/renderer.h>

#include <cstdlib>

namespace sherpa::test {
namespace {

class RendererCullingTest : public GpuTest {
protected:
    static render::FrameRequest settings(render::CullPath path, bool check = false) {
        render::FrameRequest s;
        s.width = 320;
        s.height = 180;
        std::string error;
        EXPECT_TRUE(render::parse_camera_spec("eye=2,3,6:target=0,0,0", s.camera, error)) << error;
        s.cull = path;
        s.cull_check = check;
        s.cache_shadows = false; // every frame culls and draws its cascades
        // The prepass statistics are checked: draw it even where Auto would skip it
        // (a CPU device at this size and density).
        s.depth_prepass = render::PrepassMode::On;
        return s;
    }
};

TEST_F(RendererCullingTest, GpuPathAgreesWithCpuPathPerPassAndComparesOnlyInCheckMode) {
    const auto scene = load("builtin:grid?n=2000");
    ASSERT_TRUE(scene);
    renderer().load(*scene);
    const render::FrameStats cpu = renderer().render(settings(render::CullPath::Cpu));
    const render::FrameStats gpu = renderer().render(settings(render::CullPath::Gpu));
    const render::FrameStats check = renderer().render(settings(render::CullPath::Gpu, true));
    ASSERT_EQ(cpu.culling.size(), 4u) << "camera and three cascades";
    ASSERT_EQ(gpu.culling.size(), cpu.culling.size());
    ASSERT_EQ(check.culling.size(), cpu.culling.size());
    for (std::size_t p = 0; p < cpu.culling.size(); ++p) {
        const scene::CullStats &c = cpu.culling[p], &g = gpu.culling[p], &k = check.culling[p];
        SCOPED_TRACE(c.pass);
        EXPECT_EQ(c.pass, p == 0 ? "camera" : "cascade" + std::to_string(p - 1));
        EXPECT_EQ(g.pass, c.pass);
        EXPECT_GT(c.visible, 0u);
        // The last cascade reaches the far end of the grid: it may keep everything.
        if (p < 3) {
            EXPECT_LT(c.visible, c.total) << "something is culled";
        }
        EXPECT_EQ(c.visible + c.culled, c.tested);
        EXPECT_FALSE(c.gpu);
        EXPECT_TRUE(g.gpu);
        for (const scene::CullStats* s : {&g, &k}) {
            EXPECT_EQ(s->total, c.total);
            EXPECT_EQ(s->visible, c.visible);
            EXPECT_EQ(s->triangles, c.triangles);
        }
        EXPECT_EQ(g.cpu_gpu_differences, -1) << "no CPU test outside check mode";
        EXPECT_EQ(g.false_positives, -1);
        EXPECT_EQ(k.cpu_gpu_differences, 0);
        EXPECT_GE(k.false_positives, 0);
        if (context().info().timestamps) {
            EXPECT_GE(g.gpu_ms, 0.0);
        }
    }
    // The depth prepass repeats the camera's (opaque) draws.
    EXPECT_EQ(cpu.prepass.triangles, cpu.culling[0].triangles);
    EXPECT_EQ(gpu.prepass.triangles, cpu.prepass.triangles);
    // History: the three frames, newest last.
    const auto& h = renderer().cull_history();
    ASSERT_GE(h.size(), 3u);
    EXPECT_EQ(h[h.size() - 1].path, render::CullPath::Gpu);
    EXPECT_EQ(h[h.size() - 3].path, render::CullPath::Cpu);
    EXPECT_EQ(h[h.size() - 1].passes.size(), 4u);
}

TEST_F(RendererCullingTest, CascadeCullingCutsShadowDrawsWithoutChangingTheImage) {
    const auto scene = load("builtin:grid?n=2000");
    ASSERT_TRUE(scene);
    renderer().load(*scene);
    std::vector<std::uint8_t> none_rgba, cpu_rgba, gpu_rgba;
    const render::FrameStats none = renderer().render(settings(render::CullPath::None), &none_rgba);
    const render::FrameStats cpu = renderer().render(settings(render::CullPath::Cpu), &cpu_rgba);
    const render::FrameStats gpu = renderer().render(settings(render::CullPath::Gpu), &gpu_rgba);
    ASSERT_EQ(none.culling.size(), 4u);
    ASSERT_EQ(cpu.culling.size(), 4u);
    for (std::size_t p = 1; p < 4; ++p) {
        SCOPED_TRACE(cpu.culling[p].pass);
        EXPECT_EQ(none.culling[p].visible, none.culling[p].total);
        EXPECT_EQ(gpu.culling[p].triangles, cpu.culling[p].triangles);
        // The near cascades cover a small part of the grid; the last one all of it.
        if (p < 3) {
            EXPECT_LT(cpu.culling[p].triangles, none.culling[p].triangles);
        }
    }
    for (const auto* rgba : {&cpu_rgba, &gpu_rgba}) {
        ASSERT_EQ(rgba->size(), none_rgba.size());
        EXPECT_EQ(differing_pixels(*rgba, none_rgba, 2, 3), 0u)
            << "culled shadows and views look the same as unculled ones";
    }
}

} // namespace
} // namespace sherpa::test
