// KHR_materials_variants under ray tracing on meshes that skin or morph, whose BLAS are
// posed copies refit or rebuilt per frame: a variant that masks the moving mesh away
// needs any-hit, which its BLAS, built opaque, skip; the switch forces it on their TLAS
// instances (VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR). Posed frames after the
// switch, and after the switch back, must show in the rays what the raster shows, under
// the validation layer (the fixture fails on any message).
#include "gpu_test_support.h"
#include "rt_agreement.h"

#include <sherpa/render/frame_request.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/animation.h>
#include <sherpa/scene/material_variants.h>

#include <cstdio>

namespace sherpa::test {
namespace {

class PosedVariantSwitch : public GpuTest {};

// `name` made opaque and double-sided (its BLAS geometries are built opaque), with a
// variant "Masked" that gives its first mesh a masked material whose alpha is 0.
std::unique_ptr<scene::Scene> with_masked_variant(const std::string& name) {
    scene::LoadResult r = scene::load_scene(gltf_asset(name));
    EXPECT_TRUE(r) << r.error;
    if (!r) return nullptr;
    scene::Scene& s = *r.scene;
    for (scene::MaterialInstance& m : s.materials) {
        m.alpha_mode = scene::AlphaMode::Opaque;
        m.double_sided = true;
    }
    const scene::MeshInstance& first = s.instances.front();
    scene::MaterialInstance masked = s.materials[first.material_id];
    masked.alpha_mode = scene::AlphaMode::Mask;
    masked.base_color_factor.a = 0.0f;
    s.materials.push_back(masked);
    s.variants.names = {"Masked"};
    s.variants.meshes = {scene::VariantMeshMapping{
        first.mesh_id, first.material_id, {std::int32_t(s.materials.size() - 1)}}};
    return std::move(r.scene);
}

TEST_F(PosedVariantSwitch, MaskedVariantOnASkinnedOrMorphedMeshForcesAnyHit) {
    if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    for (const std::string name : {"RiggedSimple", "SimpleMorph"}) {
        SCOPED_TRACE(name);
        std::unique_ptr<scene::Scene> scene = with_masked_variant(name);
        ASSERT_TRUE(scene);
        ASSERT_FALSE(scene->motions.empty());
        ASSERT_FALSE(scene->animations.empty());
        render::RendererOptions options;
        options.ray_tracing = true;
        options.textures = test_texture_settings();
        render::Renderer renderer(context(), options);
        renderer.load(*scene, streams_setup(render::StreamPolicy::AllPresent));
        render::FrameRequest s;
        s.width = 96;
        s.height = 72;
        s.shadows = false;
        s.view = render::DebugView::Normal;
        // Rays and raster of the pose at `t`; `masked`: the mesh is cut away in both.
        auto check = [&](double t, bool masked, const char* when) {
            SCOPED_TRACE(std::string(when) + " t=" + std::to_string(t));
            s.pose = std::make_shared<const scene::Pose>(scene::evaluate_pose(*scene, 0, t));
            const Agreement a = rays_against_raster(renderer, s, 2);
            std::printf("%-12s %-14s t=%.1f agree %7.3f%% of %5zu (covered %zu/%zu, holes "
                        "%zu/%zu)\n",
                        name.c_str(), when, t, 100.0 * a.fraction(), a.compared, a.covered_a,
                        a.covered_b, a.holes_a, a.holes_b);
            if (masked) {
                EXPECT_EQ(a.covered_a, 0u) << "the raster shows the masked mesh";
                EXPECT_EQ(a.covered_b, 0u) << "the rays hit the masked mesh (any-hit skipped)";
            } else {
                EXPECT_GT(a.compared, 100u);
                EXPECT_GE(a.fraction(), 0.995);
            }
            EXPECT_EQ(a.holes_a, 0u);
            EXPECT_EQ(a.holes_b, 0u);
        };
        check(0.3, false, "default");
        // Switched while posed: the TLAS is rebuilt with the loaded transforms, and the
        // next frame's pose goes in again.
        const render::VariantSwitch on = render::set_material_variant(renderer, 0);
        // The posed BLAS (SimpleMorph: its static BLAS of the same records too).
        EXPECT_GE(on.rt_forced_blas, 1u);
        EXPECT_TRUE(on.tlas_rebuilt);
        check(0.3, true, "masked");
        check(0.9, true, "masked");
        const render::VariantSwitch off = render::set_material_variant(renderer, -1);
        EXPECT_EQ(off.rt_forced_blas, 0u);
        EXPECT_TRUE(off.tlas_rebuilt);
        check(0.9, false, "back");
        check(0.3, false, "back");
    }
}

} // namespace
} // namespace sherpa::test
