// The lighting family's invariants on small scenes: rows of white spheres (furnace
// scenes, tests/gpu/sphere_scenes.h) under a uniform or a linear environment, and the
// transmission sweep. Tiny images and few samples: what is checked is which of two
// approximations is nearer the path tracer, never a time.
#include "gpu/sphere_scenes.h"

#include <sherpa/lab/families.h>
#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

#include "lab/lab_figures.h"
#include <cmath>
#include <cstdio>

namespace {

using namespace sherpa;
using sherpa::test::figure;

std::unique_ptr<scene::Scene> sphere_row(float metallic) {
    const auto path =
        test::write_temp(metallic > 0 ? "lab_lighting_metal.gltf" : "lab_lighting_dielectric.gltf",
                         test::sphere_row_gltf(3, metallic, 16));
    scene::LoadResult r = scene::load_scene(path.string(), lab::lab_load_options());
    EXPECT_TRUE(r) << r.error;
    return r ? std::move(r.scene) : nullptr;
}

// Radiance 1 + b.w: smooth, its irradiance known in closed form (environment_sh_test).
render::EnvironmentImage linear_environment() {
    return test::environment_of(128, [](glm::vec3 d) {
        return glm::vec3(1.0f + 0.5f * d.y, 1.0f + 0.5f * d.x, 1.0f - 0.5f * d.z);
    });
}

// 48x16 (three spheres), 64 reference samples, one size of prefilter, no shadow maps
// beyond "off", linear tone mapping at -1 EV on black: the furnace's display.
lab::LightingFamilyOptions tiny(std::shared_ptr<const render::EnvironmentImage> environment) {
    lab::LightingFamilyOptions o;
    o.width = 48;
    o.height = 16;
    o.reference_spp = 64;
    o.convergence_spp = {1, 4, 16};
    o.specular_sizes = {32};
    o.specular_samples = {8};
    o.shadows = {{512, 1, 1}};
    o.frames = 1;
    o.supersample = 2;
    o.validation = true;
    o.lighting.environment = std::move(environment);
    o.lighting.settings = test::furnace_view(3, 16); // only its lighting fields are read
    return o;
}

const lab::MethodResult& method(const lab::FamilyReport& r, const std::string& name) {
    for (const lab::MethodResult& m : r.methods)
        if (m.method.name == name) return m;
    ADD_FAILURE() << "no method " << name;
    return r.methods.front();
}

// Skips where the device does not ray trace; fails on validation messages.
bool ran_cleanly(const lab::FamilyReport& r) {
    for (const lab::MethodResult& m : r.methods) {
        if (m.note.find("does not ray trace") != std::string::npos) return false;
        for (const lab::Failure& f : m.failures)
            ADD_FAILURE() << m.method.name << ": " << f.cause << " at " << f.where;
    }
    return true;
}

void print(const lab::FamilyReport& r) {
    for (const std::string& n : r.notes) std::printf("note: %s\n", n.c_str());
    for (const lab::MethodResult& m : r.methods)
        if (m.ran)
            std::printf("%-22s mean_diff %.3f psnr %.2f\n", m.method.name.c_str(),
                        figure(m, "mean_diff"), figure(m, "psnr_db"));
        else
            std::printf("%-22s %s\n", m.method.name.c_str(), m.note.c_str());
}

TEST(LabLighting, FurnaceMetalAndThePathTracersConvergence) {
    auto scene = sphere_row(1.0f);
    ASSERT_TRUE(scene);
    auto uniform = std::make_shared<const render::EnvironmentImage>(
        render::uniform_environment(glm::vec3(1.0f)));
    const lab::FamilyReport r = lab::make_lighting_family(tiny(uniform))->run(*scene, {});
    if (!ran_cleanly(r)) GTEST_SKIP() << r.methods.front().note;
    print(r);
    std::printf("compensation on/off, roughest sphere: %.2f / %.2f\n",
                figure(method(r, "compensation on"), "material_2_mean_diff"),
                figure(method(r, "compensation off"), "material_2_mean_diff"));
    EXPECT_EQ(r.chart_error, "mean_diff");
    EXPECT_NE(r.reference.find("64 spp"), std::string::npos) << r.reference;
    // The path tracer follows glTF's single-scattering BRDF, as the raster does without
    // compensation: the roughest sphere (material 2) loses the same energy in both, and
    // compensation adds back what the reference does not have.
    const lab::MethodResult& on = method(r, "compensation on");
    const lab::MethodResult& off = method(r, "compensation off");
    ASSERT_TRUE(on.ran && off.ran) << on.note << off.note;
    // Measured: 6.0 8-bit steps off (the split-sum's and the path tracer's 0.015 gap at
    // roughness 1, docs/path_tracer.md), 61 on.
    EXPECT_LT(figure(off, "material_2_mean_diff"), 9.0);
    EXPECT_GT(figure(on, "material_2_mean_diff"), 3.0 * figure(off, "material_2_mean_diff"));
    EXPECT_LT(figure(off, "mean_diff"), figure(on, "mean_diff"));
    // A uniform environment is held exactly by both irradiance forms.
    EXPECT_NEAR(figure(method(r, "irradiance cube"), "mean_diff"),
                figure(method(r, "irradiance sh9"), "mean_diff"), 0.3);
    // Its error falls as the samples rise (1, 4, 16 against 64 of another seed).
    const double e1 = figure(method(r, "path tracer 1 spp"), "mean_diff");
    const double e4 = figure(method(r, "path tracer 4 spp"), "mean_diff");
    const double e16 = figure(method(r, "path tracer 16 spp"), "mean_diff");
    EXPECT_GT(e1, e4);
    EXPECT_GT(e4, e16);
    EXPECT_EQ(method(r, "path tracer 1 spp").error("estimated_error_percent"), nullptr)
        << "one sample has no variance";
    EXPECT_GT(figure(method(r, "path tracer 4 spp"), "ms_per_sample"), 0.0);
    // No sun (off, no lights) and no transmissive material: not applicable, by cause.
    for (const char* name : {"shadows off", "shadows 512x1 pcf1"}) {
        EXPECT_FALSE(method(r, name).ran);
        EXPECT_NE(method(r, name).note.find("not applicable: no directional light"),
                  std::string::npos)
            << method(r, name).note;
    }
    for (const char* name : {"transmission on", "transmission off"}) {
        EXPECT_FALSE(method(r, name).ran);
        EXPECT_NE(method(r, name).note.find("not applicable: no material has "
                                            "KHR_materials_transmission"),
                  std::string::npos)
            << method(r, name).note;
    }
    EXPECT_NE(method(r, "anisotropy albedo")
                  .note.find("not applicable: no material has "
                             "KHR_materials_anisotropy"),
              std::string::npos)
        << method(r, "anisotropy albedo").note;
}

// The anisotropy sweep (strength 0 .. 1 and rotations of strength 0.8, a metal of F0 0.9
// and roughness 0.3) in a uniform environment, compensation off (the path tracer is
// glTF's single-scattering BRDF): the anisotropic lobe's own albedo is nearer the path
// tracer than the isotropic table's, over the image and on the strength-1 sphere.
TEST(LabLighting, AnisotropicAlbedoIsNearerThePathTracerThanTheIsotropicTable) {
    scene::LoadResult loaded = scene::load_scene(std::string(SHERPA_TEST_DATA_DIR) +
                                                     "/material_sweeps/anisotropy_sweep.gltf",
                                                 lab::lab_load_options());
    ASSERT_TRUE(loaded) << loaded.error;
    lab::LightingFamilyOptions o = tiny(std::make_shared<const render::EnvironmentImage>(
        render::uniform_environment(glm::vec3(1.0f))));
    o.lighting.settings.energy_compensation = false;
    o.width = 80;
    o.height = 40;
    o.reference_spp = 32;
    o.convergence_spp = {4};
    const lab::FamilyReport r = lab::make_lighting_family(o)->run(*loaded.scene, {});
    if (!ran_cleanly(r)) GTEST_SKIP() << r.methods.front().note;
    print(r);
    const lab::MethodResult& iso = method(r, "anisotropy isotropic");
    const lab::MethodResult& albedo = method(r, "anisotropy albedo");
    ASSERT_TRUE(iso.ran && albedo.ran) << iso.note << albedo.note;
    std::printf("anisotropy isotropic / albedo / lobe, strength-1 sphere: %.2f / %.2f / %.2f\n",
                figure(iso, "material_4_mean_diff"), figure(albedo, "material_4_mean_diff"),
                figure(method(r, "anisotropy lobe"), "material_4_mean_diff"));
    EXPECT_LT(figure(albedo, "material_4_mean_diff"), 0.5 * figure(iso, "material_4_mean_diff"));
    EXPECT_LT(figure(albedo, "mean_diff"), figure(iso, "mean_diff"));
}

TEST(LabLighting, Sh9AndCubeIrradianceAreBothNearThePathTracerOnASmoothEnvironment) {
    auto scene = sphere_row(0.0f);
    ASSERT_TRUE(scene);
    auto linear = std::make_shared<const render::EnvironmentImage>(linear_environment());
    lab::LightingFamilyOptions o = tiny(linear);
    const lab::FamilyReport r = lab::make_lighting_family(o)->run(*scene, {});
    if (!ran_cleanly(r)) GTEST_SKIP() << r.methods.front().note;
    print(r);
    const double cube = figure(method(r, "irradiance cube"), "mean_diff");
    const double sh9 = figure(method(r, "irradiance sh9"), "mean_diff");
    // Stated tolerance: within 3 8-bit steps of the path tracer on average (the white
    // dielectric's own gap to glTF's BRDF, which the split-sum keeps at 1, is in both).
    EXPECT_LT(cube, 3.0);
    EXPECT_LT(sh9, 3.0);
    EXPECT_NEAR(cube, sh9, 1.0);
    // Per material figures for the three spheres, none for the background.
    for (int m = 0; m < 3; ++m)
        EXPECT_NE(method(r, "irradiance sh9").error("material_" + std::to_string(m) + "_mean_diff"),
                  nullptr);
}

TEST(LabLighting, TransmissionIsNearerThePathTracerThanWithoutIt) {
    scene::LoadResult loaded = scene::load_scene(std::string(SHERPA_TEST_DATA_DIR) +
                                                     "/material_sweeps/transmission_sweep.gltf",
                                                 lab::lab_load_options());
    ASSERT_TRUE(loaded) << loaded.error;
    lab::LightingFamilyOptions o =
        tiny(std::make_shared<const render::EnvironmentImage>(render::room_environment(256)));
    o.lighting.settings = render::FrameRequest{};
    o.width = 64;
    o.height = 48;
    o.reference_spp = 32;
    o.convergence_spp = {4};
    const lab::FamilyReport r = lab::make_lighting_family(o)->run(*loaded.scene, {});
    if (!ran_cleanly(r)) GTEST_SKIP() << r.methods.front().note;
    print(r);
    const lab::MethodResult& on = method(r, "transmission on");
    const lab::MethodResult& off = method(r, "transmission off");
    ASSERT_TRUE(on.ran && off.ran) << on.note << off.note;
    // Material 0 transmits fully: without the extension it is an opaque white dielectric.
    EXPECT_LT(figure(on, "material_0_mean_diff"), 0.5 * figure(off, "material_0_mean_diff"));
    EXPECT_LT(figure(on, "mean_diff"), figure(off, "mean_diff"));
}

TEST(LabLighting, WithoutAnEnvironmentItsGroupsAreNotApplicable) {
    auto scene = sphere_row(1.0f);
    ASSERT_TRUE(scene);
    lab::LightingFamilyOptions o = tiny(nullptr);
    o.reference_spp = 8;
    o.convergence_spp = {2};
    const lab::FamilyReport r = lab::make_lighting_family(o)->run(*scene, {});
    if (!ran_cleanly(r)) GTEST_SKIP() << r.methods.front().note;
    for (const lab::MethodResult& m : r.methods) {
        if (m.method.group == "irradiance" || m.method.group == "specular prefilter" ||
            m.method.group == "energy compensation" || m.method.group == "anisotropy") {
            EXPECT_FALSE(m.ran) << m.method.name;
            EXPECT_NE(m.note.find("not applicable: no environment"), std::string::npos) << m.note;
            EXPECT_TRUE(m.errors.empty()) << m.method.name << " has a number";
        }
    }
    EXPECT_TRUE(method(r, "path tracer 2 spp").ran);
}

TEST(LabLighting, WithoutRayTracingNothingRunsAndEachSaysWhy) {
    auto scene = sphere_row(1.0f);
    ASSERT_TRUE(scene);
    lab::LightingFamilyOptions o = tiny(nullptr);
    o.ray_tracing = false;
    const lab::FamilyReport r = lab::make_lighting_family(o)->run(*scene, {});
    ASSERT_FALSE(r.methods.empty());
    for (const lab::MethodResult& m : r.methods) {
        EXPECT_FALSE(m.ran) << m.method.name;
        EXPECT_NE(m.note.find("does not ray trace"), std::string::npos) << m.note;
    }
}

TEST(LabLighting, MethodListAndConvergenceSeries) {
    lab::LightingFamilyOptions o;
    EXPECT_EQ(lab::lighting_convergence_spp(o), (std::vector<std::uint32_t>{1, 4, 16, 64}));
    o.reference_spp = 10;
    EXPECT_EQ(lab::lighting_convergence_spp(o), (std::vector<std::uint32_t>{1}));
    o.convergence_spp = {8, 2, 2, 0, 10, 12};
    EXPECT_EQ(lab::lighting_convergence_spp(o), (std::vector<std::uint32_t>{2, 8}));
    const auto family = lab::make_family("lighting");
    ASSERT_TRUE(family);
    const auto methods = family->methods();
    // irradiance 2, prefilter 1 + 4 x 3, compensation 2, anisotropy 3, shadows 1 + 3,
    // transmission 2, path tracer 4.
    EXPECT_EQ(methods.size(), 2u + 13u + 2u + 3u + 4u + 2u + 4u);
    EXPECT_TRUE(lab::family_draws_lit_frames("lighting"));
}

TEST(LabLighting, CancelledBeforeItStartsReturnsNoMethods) {
    auto scene = sphere_row(1.0f);
    ASSERT_TRUE(scene);
    core::CancelToken cancel;
    cancel.cancel();
    lab::RunControl control;
    control.cancel = &cancel;
    const lab::FamilyReport r = lab::make_lighting_family(tiny(nullptr))->run(*scene, control);
    EXPECT_TRUE(r.cancelled);
    EXPECT_TRUE(r.methods.empty());
}

// A cancel during the reference stops it at the next launch of the path tracer.
TEST(LabLighting, CancelDuringTheReferenceStopsAtTheNextLaunch) {
    auto scene = sphere_row(1.0f);
    ASSERT_TRUE(scene);
    lab::LightingFamilyOptions o = tiny(nullptr);
    o.reference_spp = 256; // 64 launches: far more than the few it may take to stop
    core::CancelToken cancel;
    std::size_t calls_after_cancel = 0;
    lab::RunControl control;
    control.cancel = &cancel;
    control.progress = [&](std::size_t done, std::size_t) {
        if (cancel.cancelled()) ++calls_after_cancel;
        if (done >= 2) cancel.cancel();
    };
    const lab::FamilyReport r = lab::make_lighting_family(o)->run(*scene, control);
    EXPECT_TRUE(r.cancelled);
    EXPECT_TRUE(r.methods.empty());
    EXPECT_LE(calls_after_cancel, 1u);
}

} // namespace
