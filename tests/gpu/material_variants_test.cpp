// KHR_materials_variants: the importer's variants and mappings (bad indices warned with
// their JSON pointer, the default material kept), everything a variant shows prepared
// at load, and the renderer's switch: a scene switched to a variant after loading draws
// the same bytes as the scene loaded with that variant, on every cull path, uploading
// only the instance records' material words. tests/data/material_sweeps/variants.gltf
// (tools/material_sweeps/make_sweeps.py): three unlit spheres, variants "Warm" (sphere 0
// red, sphere 2 a checker texture) and "Cool" (sphere 1 masked away, sphere 2 green).
#include "gpu/material_extension_support.h"
#include "gpu_test_support.h"
#include "rt_agreement.h"

#include <sherpa/render/frame_request.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/scene/material_variants.h>
#include <sherpa/texture/texture_pipeline.h>

#include <algorithm>
#include <cstdio>

namespace sherpa::test {
namespace {

constexpr std::uint32_t kWarm = 0, kCool = 1;
constexpr std::uint32_t kRed = 3, kChecker = 4, kMasked = 5, kGreen = 6;

std::string file(const char* name) {
    return (data_dir() / "material_sweeps" / name).string();
}

TEST(MaterialVariants, ImportReadsNamesAndMappings) {
    EXPECT_TRUE(scene::is_supported_gltf_extension("KHR_materials_variants"));
    const scene::LoadResult r = scene::load_scene(file("variants.gltf"));
    ASSERT_TRUE(r) << r.error;
    const scene::Scene& s = *r.scene;
    for (const std::string& w : s.warnings) ADD_FAILURE() << w;
    ASSERT_EQ(s.variants.names, (std::vector<std::string>{"Warm", "Cool"}));
    EXPECT_EQ(scene::find_variant(s, "Cool"), 1);
    EXPECT_EQ(scene::find_variant(s, "cool"), -1);
    ASSERT_EQ(s.variants.meshes.size(), 3u);
    EXPECT_EQ(scene::variant_material(s, 0, kWarm), kRed);
    EXPECT_EQ(scene::variant_material(s, 0, kCool), 0u); // unmapped: the default
    EXPECT_EQ(scene::variant_material(s, 1, kCool), kMasked);
    EXPECT_EQ(scene::variant_material(s, 2, -1), 2u);
    EXPECT_EQ(scene::possible_materials(s, 2), (std::vector<std::uint32_t>{2, kChecker, kGreen}));
    const auto warm = scene::variant_changes(s, kWarm);
    ASSERT_EQ(warm.size(), 2u);
    EXPECT_EQ(warm[0].gltf_mesh, 0u);
    EXPECT_EQ(warm[0].to, kRed);
    EXPECT_EQ(warm[1].gltf_mesh, 2u);
    EXPECT_EQ(warm[1].to, kChecker);
    // The checker is read by no default material, yet prepared: a switch uploads nothing.
    const auto uses = tex::collect_texture_uses(s);
    ASSERT_EQ(uses.size(), 1u);
    EXPECT_EQ(uses[0].image, 0);
}

TEST(MaterialVariants, ApplyChangesOnlyMaterialIds) {
    scene::LoadResult r = scene::load_scene(file("variants.gltf"));
    ASSERT_TRUE(r) << r.error;
    scene::Scene& s = *r.scene;
    const auto vertices = s.meshes[2].vertices.size();
    EXPECT_EQ(scene::apply_material_variant(s, kCool), 2u); // spheres 1 and 2
    EXPECT_EQ(s.meshes[1].material_id, kMasked);
    EXPECT_EQ(s.instances[2].material_id, kGreen);
    EXPECT_EQ(s.variants.active, int(kCool));
    EXPECT_EQ(s.meshes[2].vertices.size(), vertices);
    EXPECT_EQ(scene::apply_material_variant(s, -1), 2u);
    EXPECT_EQ(s.meshes[1].material_id, 1u);
}

TEST(MaterialVariants, BadMappingsAreWarnedWithTheirPointerAndKeepTheDefault) {
    const scene::LoadResult r = scene::load_scene(file("variants_bad.gltf"));
    ASSERT_TRUE(r) << r.error;
    const scene::Scene& s = *r.scene;
    const std::string base = "/meshes/0/primitives/0/extensions/KHR_materials_variants/mappings/";
    // The Khronos validator's codes and pointers (all errors there); the file loads.
    const std::pair<std::string, std::string> expected[] = {
        {base + "0/material", "UNRESOLVED_REFERENCE"},
        {base + "1/variants/0", "UNRESOLVED_REFERENCE"},
        {base + "2/variants/0", "KHR_MATERIALS_VARIANTS_NON_UNIQUE_VARIANT"},
        {base + "3", "UNDEFINED_PROPERTY"}};
    for (const auto& [p, code] : expected) {
        const scene::ValidationMessage* m = test::message_at(s, p);
        ASSERT_NE(m, nullptr) << p;
        EXPECT_EQ(m->code, code) << p;
        EXPECT_EQ(m->severity, scene::Severity::Error) << p;
    }
    EXPECT_EQ(scene::variant_material(s, 0, kWarm), 0u);     // material 99: the default
    EXPECT_EQ(scene::variant_material(s, 0, kCool), kRed);   // the first mapping of Cool is kept
    EXPECT_EQ(scene::variant_material(s, 2, kCool), kGreen); // other primitives untouched
}

class VariantSwitch : public GpuTest {
protected:
    std::vector<std::uint8_t> frame(render::Renderer& r, render::CullPath cull) {
        render::FrameRequest s;
        s.width = 160;
        s.height = 120;
        std::string error;
        EXPECT_TRUE(render::parse_camera_spec("eye=0,0,5:target=0,0,0:fov=45", s.camera, error));
        s.cull = cull;
        std::vector<std::uint8_t> rgba;
        r.render(s, &rgba);
        return rgba;
    }
    // The frame of a scene loaded with `variant` already shown.
    std::vector<std::uint8_t> loaded_with(std::int32_t variant, render::CullPath cull) {
        std::unique_ptr<scene::Scene> s = load(file("variants.gltf"));
        scene::apply_material_variant(*s, variant);
        renderer().load(*s);
        return frame(renderer(), cull);
    }
};

TEST_F(VariantSwitch, SwitchedSceneDrawsAsTheSceneLoadedWithTheVariant) {
    for (const render::CullPath cull : {render::CullPath::Cpu, render::CullPath::Gpu}) {
        SCOPED_TRACE(std::string(to_string(cull)));
        const auto defaults = loaded_with(-1, cull);
        const auto warm = loaded_with(kWarm, cull);
        const auto cool = loaded_with(kCool, cull);
        EXPECT_GT(differing_pixels(defaults, warm, 8), 500u);
        EXPECT_GT(differing_pixels(defaults, cool, 8), 500u);

        std::unique_ptr<scene::Scene> s = load(file("variants.gltf"));
        renderer().load(*s);
        EXPECT_EQ(frame(renderer(), cull), defaults);
        render::VariantSwitch w = render::set_material_variant(renderer(), kWarm);
        EXPECT_EQ(w.meshes, 2u);
        EXPECT_EQ(w.instances, 2u);
        EXPECT_EQ(w.gpu_bytes, 8u); // two material words
        EXPECT_FALSE(w.culling_rebuilt);
        EXPECT_EQ(frame(renderer(), cull), warm);
        render::VariantSwitch c = render::set_material_variant(renderer(), kCool);
        EXPECT_EQ(c.meshes, 3u);
        EXPECT_TRUE(c.culling_rebuilt); // sphere 1 became masked
        EXPECT_EQ(frame(renderer(), cull), cool);
        render::set_material_variant(renderer(), -1);
        EXPECT_EQ(frame(renderer(), cull), defaults);
        EXPECT_EQ(render::set_material_variant(renderer(), -1).gpu_bytes, 0u); // unchanged
        EXPECT_THROW(render::set_material_variant(renderer(), 2), std::out_of_range);
    }
}

// The ray tracer after a switch: its geometry records follow the switched materials,
// so rays and raster agree on every surface view (the exactness tests' measure), and
// the path tracer's lit frame equals that of the file loaded with the variant. The
// spheres are made opaque and double-sided, so their BLAS geometries are built
// VK_GEOMETRY_OPAQUE_BIT; "Cool" masks sphere 1 away, which needs any-hit: its
// instance is forced non-opaque (TLAS rebuilt, no BLAS rebuilt), and the flag goes
// with the switch back.
TEST_F(VariantSwitch, RaysFollowTheSwitchedVariant) {
    if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    auto opaque_spheres = [&](std::int32_t variant) {
        std::unique_ptr<scene::Scene> s = load(file("variants.gltf"));
        for (scene::MaterialInstance& m : s->materials)
            m.double_sided = m.alpha_mode == scene::AlphaMode::Opaque;
        scene::apply_material_variant(*s, variant);
        return s;
    };
    auto traced = [&](const scene::Scene& scene) {
        render::RendererOptions options;
        options.ray_tracing = true;
        options.textures = test_texture_settings();
        auto r = std::make_unique<render::Renderer>(context(), options);
        r->load(scene, streams_setup(render::StreamPolicy::AllPresent));
        return r;
    };
    render::FrameRequest s;
    s.width = 160;
    s.height = 120;
    s.shadows = false;
    s.path.samples = 4;
    s.path.restart = true; // each lit frame is 4 samples from the same seed
    std::string error;
    ASSERT_TRUE(render::parse_camera_spec("eye=0,0,5:target=0,0,0:fov=45", s.camera, error));
    auto image = [&](render::Renderer& r, render::DebugView view, render::RendererKind kind) {
        s.view = view;
        s.renderer = kind;
        std::vector<std::uint8_t> rgba;
        r.render(s, &rgba);
        return rgba;
    };
    std::unique_ptr<scene::Scene> scene = opaque_spheres(-1);
    auto switched = traced(*scene);
    const std::vector<std::uint8_t> defaults_lit =
        image(*switched, render::DebugView::Lit, render::RendererKind::RayTraced);
    struct Step {
        std::int32_t variant;
        std::uint32_t forced_blas;
        bool tlas_rebuilt;
    };
    for (const Step step : {Step{kWarm, 0, false}, Step{kCool, 1, true}, Step{-1, 0, true}}) {
        SCOPED_TRACE("variant " + std::to_string(step.variant));
        const render::VariantSwitch v = render::set_material_variant(*switched, step.variant);
        EXPECT_GT(v.rt_records, 0u);
        EXPECT_EQ(v.rt_gpu_bytes, 4u * v.rt_records); // material words only
        EXPECT_EQ(v.rt_forced_blas, step.forced_blas);
        EXPECT_EQ(v.tlas_rebuilt, step.tlas_rebuilt);
        int views = 0;
        for (const render::DebugViewInfo& info : render::kDebugViews) {
            if (!render::ray_traced_view(info.id) || !render::raster_view(info.id) ||
                info.id == render::DebugView::Shadow || info.id == render::DebugView::Lit)
                continue;
            const auto raster = image(*switched, info.id, render::RendererKind::Raster);
            const auto rays = image(*switched, info.id, render::RendererKind::RayTraced);
            const Agreement a = compare(raster, rays, s.width, s.height, 2);
            std::printf("variant %2d %-15s agree %7.3f%% of %5zu (max diff %3d)\n", step.variant,
                        std::string(info.name).c_str(), 100.0 * a.fraction(), a.compared,
                        a.max_difference);
            EXPECT_GT(a.compared, 100u) << info.name;
            EXPECT_GE(a.fraction(), 0.995) << info.name << " max diff " << a.max_difference;
            EXPECT_EQ(a.holes_a, 0u) << info.name << ": holes in the raster";
            EXPECT_EQ(a.holes_b, 0u) << info.name << ": holes in the rays";
            ++views;
        }
        EXPECT_GE(views, 12);
        // The path tracer: as the file loaded with the variant (same seeds, same bytes).
        const auto lit = image(*switched, render::DebugView::Lit, render::RendererKind::RayTraced);
        std::unique_ptr<scene::Scene> loaded_scene = opaque_spheres(step.variant);
        auto loaded = traced(*loaded_scene);
        EXPECT_EQ(lit, image(*loaded, render::DebugView::Lit, render::RendererKind::RayTraced));
        if (step.variant >= 0) {
            EXPECT_GT(differing_pixels(lit, defaults_lit, 8), 300u);
        }
    }
}

// A variant that brings a double-sided material into a mesh whose materials were all
// single-sided: the traversal culled that mesh's back faces, and its instances stop
// culling (TLAS rebuilt, no BLAS rebuilt). Seen from inside sphere 0, its inside shows
// only while its material is double-sided ("Warm": red), so rays that still culled would
// show the spheres behind it where the raster draws red.
TEST_F(VariantSwitch, ADoubleSidedVariantStopsTheTraversalCullingItsMesh) {
    if (!context().info().ray_tracing_enabled) GTEST_SKIP() << "device without ray tracing";
    auto red_double_sided = [&](std::int32_t variant) {
        std::unique_ptr<scene::Scene> s = load(file("variants.gltf"));
        s->materials[kRed].double_sided = true; // the others single-sided, as in the file
        scene::apply_material_variant(*s, variant);
        return s;
    };
    render::RendererOptions options;
    options.ray_tracing = true;
    options.textures = test_texture_settings();
    auto traced = [&](const scene::Scene& scene) {
        auto r = std::make_unique<render::Renderer>(context(), options);
        r->load(scene, streams_setup(render::StreamPolicy::AllPresent));
        return r;
    };
    std::unique_ptr<scene::Scene> scene = red_double_sided(-1);
    auto switched = traced(*scene);
    render::FrameRequest s;
    s.width = 160;
    s.height = 120;
    s.shadows = false;
    s.path.samples = 4;
    s.path.restart = true;
    std::string error;
    ASSERT_TRUE(render::parse_camera_spec("eye=-1,0,0:target=1,0,0:fov=60", s.camera, error));
    s.view = render::DebugView::BaseColor;
    std::vector<std::uint8_t> inside_default;
    s.renderer = render::RendererKind::Raster;
    switched->render(s, &inside_default);
    struct Step {
        std::int32_t variant;
        std::uint32_t forced_blas, unculled_blas;
    };
    for (const Step step : {Step{kWarm, 0, 1}, Step{kCool, 1, 0}, Step{-1, 0, 0}}) {
        SCOPED_TRACE("variant " + std::to_string(step.variant));
        const render::VariantSwitch v = render::set_material_variant(*switched, step.variant);
        EXPECT_EQ(v.rt_forced_blas, step.forced_blas);
        EXPECT_EQ(v.rt_unculled_blas, step.unculled_blas);
        EXPECT_TRUE(v.tlas_rebuilt);
        // Every pixel (from inside a double-sided sphere nothing shows the clear colour,
        // so compare()'s coverage does not apply): within 2 of 255 but along silhouettes.
        s.view = render::DebugView::BaseColor;
        std::vector<std::uint8_t> raster, rays;
        s.renderer = render::RendererKind::Raster;
        switched->render(s, &raster);
        s.renderer = render::RendererKind::RayTraced;
        switched->render(s, &rays);
        const std::size_t differ = differing_pixels(raster, rays, 2, 3);
        std::printf("variant %2d base colour from inside sphere 0: %zu of %u pixels differ\n",
                    step.variant, differ, s.width * s.height);
        EXPECT_LE(differ, s.width * s.height / 100u);
        if (step.variant == kWarm) {
            EXPECT_GT(differing_pixels(raster, inside_default, 8), 5000u);
        }
        // The path tracer: as the file loaded with the variant, whose BLAS were planned
        // with that material from the start.
        s.view = render::DebugView::Lit;
        s.renderer = render::RendererKind::RayTraced;
        std::vector<std::uint8_t> lit, loaded_lit;
        switched->render(s, &lit);
        std::unique_ptr<scene::Scene> loaded_scene = red_double_sided(step.variant);
        traced(*loaded_scene)->render(s, &loaded_lit);
        EXPECT_EQ(lit, loaded_lit);
    }
}

} // namespace
} // namespace sherpa::test
