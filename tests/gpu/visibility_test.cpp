// Node visibility (SceneSetup::hidden_nodes, Renderer::set_hidden_nodes): a hidden node's
// instances are drawn by no pass on every cull path, cast no shadow (cached cascades
// are redrawn), are left out of the ray tracer's TLAS, and are counted as hidden; showing
// them again restores the identical image. Scene: tests/data/double_sided_shadow.gltf
// (node 0 a 2x2 plane at z = 0, node 1 a caster quad at z = -0.5 that shadows it).
#include "gpu_test_support.h"

#include <sherpa/render/renderer.h>
#include <sherpa/scene/animation.h>
#include <sherpa/scene/visibility.h>

namespace sherpa::test {
namespace visibility_test {

constexpr std::uint32_t kSize = 96;
constexpr const char* kCamera = "eye=0,0,-3:target=0,0,0:fov=50:aspect=1";
constexpr std::uint32_t kCaster = 1;

class Visibility : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        scene_ = load(std::string(SHERPA_TEST_DATA_DIR) + "/double_sided_shadow.gltf");
        ASSERT_TRUE(scene_);
        ASSERT_EQ(scene_->nodes.size(), 2u);
        ASSERT_EQ(scene_->nodes[kCaster].name, "caster");
        std::string error;
        ASSERT_TRUE(render::parse_camera_spec(kCamera, settings_.camera, error)) << error;
        settings_.width = settings_.height = kSize;
        settings_.sun_direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));
        settings_.view = render::DebugView::Shadow; // lit 255, shadowed 0
        hidden_ = std::make_shared<std::vector<bool>>(2, false);
        (*hidden_)[kCaster] = true;
    }

    std::vector<std::uint8_t> render(render::Renderer& r, const render::FrameRequest& s,
                                     render::FrameStats* stats = nullptr) {
        std::vector<std::uint8_t> rgba;
        const render::FrameStats st = r.render(s, &rgba);
        if (stats) *stats = st;
        EXPECT_EQ(rgba.size(), std::size_t{kSize} * kSize * 4);
        return rgba;
    }

    // Pixels of the shadow view: shadowed (dark) and lit (bright) ones.
    static std::pair<std::size_t, std::size_t> dark_bright(const std::vector<std::uint8_t>& rgba) {
        std::size_t dark = 0, bright = 0;
        for (std::size_t p = 0; p < rgba.size(); p += 4) {
            const bool grey = rgba[p] == rgba[p + 1] && rgba[p] == rgba[p + 2];
            dark += grey && rgba[p] < 64;
            bright += grey && rgba[p] > 192;
        }
        return {dark, bright};
    }

    std::unique_ptr<scene::Scene> scene_;
    render::FrameRequest settings_;
    std::shared_ptr<std::vector<bool>> hidden_;
};

TEST(VisibilityRule, AHiddenNodeHidesItsSubtreeAndHostileParentsEndTheWalk) {
    std::vector<scene::Node> nodes(4);
    nodes[1].parent = 0;
    nodes[2].parent = 1;
    nodes[3].parent = 3; // a cycle onto itself
    EXPECT_EQ(scene::hidden_subtrees(nodes, {}), std::vector<bool>(4, false));
    EXPECT_EQ(scene::hidden_subtrees(nodes, {false, true}),
              (std::vector<bool>{false, true, true, false}));
    EXPECT_EQ(scene::hidden_subtrees(nodes, {true}), (std::vector<bool>{true, true, true, false}));
    nodes[0].parent = 57; // out of range
    EXPECT_EQ(scene::hidden_subtrees(nodes, {false, false, false, true}),
              (std::vector<bool>{false, false, false, true}));
}

TEST_F(Visibility, HiddenCasterLeavesNoPixelsNorShadowOnEveryCullPath) {
    render::Renderer r(context());
    r.load(*scene_);
    std::vector<std::uint8_t> hidden_image;
    for (const render::CullPath path :
         {render::CullPath::None, render::CullPath::Cpu, render::CullPath::Gpu}) {
        SCOPED_TRACE(std::string(to_string(path)));
        render::FrameRequest s = settings_;
        s.cull = path;
        const auto shown = render(r, s); // cascades cached from here on
        const auto [shown_dark, shown_bright] = dark_bright(shown);
        EXPECT_GT(shown_dark, 150u) << "the caster's shadow on the plane";

        r.set_hidden_nodes(hidden_);
        render::FrameStats st;
        const auto hidden = render(r, s, &st);
        EXPECT_TRUE(st.shadows_rendered) << "cached cascades redrawn when visibility changes";
        const auto [dark, bright] = dark_bright(hidden);
        EXPECT_EQ(dark, 0u) << "no shadow of the hidden caster";
        EXPECT_GT(bright, shown_bright + shown_dark / 2)
            << "the plane where caster and shadow were";
        ASSERT_FALSE(st.culling.empty());
        for (const scene::CullStats& c : st.culling) {
            SCOPED_TRACE(c.pass);
            EXPECT_EQ(c.hidden, 1u);
            // Hidden instances are neither tested, visible nor culled.
            if (path == render::CullPath::None) {
                EXPECT_EQ(c.visible, c.total - c.hidden);
            } else {
                EXPECT_EQ(c.tested, c.total - c.hidden);
                EXPECT_EQ(c.visible + c.culled, c.tested);
            }
        }
        EXPECT_EQ(st.culling[0].visible, 1u) << "only the plane";
        if (path == render::CullPath::Gpu) { // check mode: the CPU test leaves them out too
            render::FrameRequest k = s;
            k.cull_check = true;
            k.cache_shadows = false;
            render::FrameStats checked;
            EXPECT_EQ(render(r, k, &checked), hidden);
            for (const scene::CullStats& c : checked.culling)
                EXPECT_EQ(c.cpu_gpu_differences, 0) << c.pass;
        }
        if (hidden_image.empty())
            hidden_image = hidden;
        else
            EXPECT_EQ(hidden, hidden_image) << "every cull path draws the same";

        r.set_hidden_nodes(nullptr);
        EXPECT_EQ(render(r, s), shown) << "shown again: the identical image";
    }
}

TEST_F(Visibility, HidingTheRootOfASubtreeHidesItsDescendantsInTheRenderer) {
    // The caster made a child of the plane: hiding the plane hides both.
    scene::Scene scene = *scene_;
    scene.nodes[kCaster].parent = 0;
    scene.nodes[0].children = {kCaster};
    render::Renderer r(context());
    auto root = std::make_shared<std::vector<bool>>(std::vector<bool>{true});
    r.load(scene, {.hidden_nodes = root}); // hidden from the load on
    render::FrameRequest s = settings_;
    s.view = render::DebugView::Lit;
    render::FrameStats st;
    const auto image = render(r, s, &st);
    EXPECT_EQ(st.culling[0].hidden, 2u);
    EXPECT_EQ(st.culling[0].visible, 0u);
    for (std::size_t p = 0; p < image.size(); p += 4)
        ASSERT_EQ(image[p], image[0]) << "only the clear colour";
}

TEST_F(Visibility, RayTracedImageAndTlasLeaveTheHiddenNodeOut) {
    if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    render::RendererOptions options;
    options.ray_tracing = true;
    render::Renderer r(context(), options);
    r.load(*scene_);
    render::FrameRequest s = settings_;
    s.renderer = render::RendererKind::RayTraced;
    const auto shown = render(r, s);
    ASSERT_NE(r.resident().acceleration, nullptr);
    EXPECT_EQ(r.resident().acceleration->tlas.hidden, 0u);
    EXPECT_EQ(r.resident().acceleration->tlas.instances, 2u);
    EXPECT_GT(dark_bright(shown).first, 150u);

    r.set_hidden_nodes(hidden_);
    const auto hidden = render(r, s);
    EXPECT_EQ(r.resident().acceleration->tlas.hidden, 1u);
    EXPECT_EQ(r.resident().acceleration->tlas.instances, 1u);
    EXPECT_EQ(dark_bright(hidden).first, 0u) << "rays do not see the hidden caster";

    r.set_hidden_nodes(nullptr);
    EXPECT_EQ(render(r, s), shown);
    EXPECT_EQ(r.resident().acceleration->tlas.hidden, 0u);
}

TEST_F(Visibility, HiddenSkinnedMeshLeavesPosedFramesOnEveryPathAndTheRays) {
    const auto scene = load(gltf_asset("RiggedSimple"));
    ASSERT_TRUE(scene);
    ASSERT_FALSE(scene->animations.empty());
    auto mask = std::make_shared<std::vector<bool>>(scene->nodes.size(), false);
    for (std::size_t n = 0; n < scene->nodes.size(); ++n)
        if (scene->nodes[n].mesh >= 0) (*mask)[n] = true; // every mesh node
    const auto pose = std::make_shared<const scene::Pose>(
        scene::evaluate_pose(*scene, 0, 0.37 * scene->animations[0].end));
    render::FrameRequest s;
    s.width = s.height = kSize;
    const core::Aabb b = scene->bounds;
    const glm::vec3 eye = b.center() + glm::vec3(0.0f, 0.0f, 2.5f * glm::length(b.extent()));
    std::string error;
    ASSERT_TRUE(render::parse_camera_spec(
        "eye=" + std::to_string(eye.x) + "," + std::to_string(eye.y) + "," + std::to_string(eye.z) +
            ":target=" + std::to_string(b.center().x) + "," + std::to_string(b.center().y) + "," +
            std::to_string(b.center().z),
        s.camera, error))
        << error;
    s.pose = pose;
    s.view = render::DebugView::Shadow; // drawn by both renderers
    const bool rays = context().info().ray_tracing_enabled;
    render::RendererOptions options;
    options.ray_tracing = rays;
    render::Renderer r(context(), options);
    r.load(*scene);
    auto only_clear = [](const std::vector<std::uint8_t>& rgba) {
        for (std::size_t p = 4; p < rgba.size(); ++p)
            if (rgba[p] != rgba[p % 4]) return false;
        return true;
    };
    for (const render::CullPath path :
         {render::CullPath::None, render::CullPath::Cpu, render::CullPath::Gpu}) {
        SCOPED_TRACE(std::string(to_string(path)));
        s.cull = path;
        r.set_hidden_nodes(nullptr);
        const auto shown = render(r, s);
        EXPECT_FALSE(only_clear(shown)) << "the posed mesh is in view";
        r.set_hidden_nodes(mask);
        EXPECT_TRUE(only_clear(render(r, s)));
        r.set_hidden_nodes(nullptr);
        EXPECT_EQ(render(r, s), shown);
    }
    if (!rays) return;
    s.renderer = render::RendererKind::RayTraced;
    const auto shown = render(r, s);
    EXPECT_FALSE(only_clear(shown));
    r.set_hidden_nodes(mask);
    EXPECT_TRUE(only_clear(render(r, s))) << "the posed BLAS is out of the TLAS";
    EXPECT_GE(r.resident().acceleration->tlas.hidden, 1u);
    r.set_hidden_nodes(nullptr);
    EXPECT_EQ(render(r, s), shown) << "shown again in the same pose";
}

} // namespace visibility_test
} // namespace sherpa::test
