// KHR_materials_variants: the importer's variants and mappings (bad indices warned with
// their JSON pointer, the default material kept), everything a variant shows prepared
// at load, and the renderer's switch: a scene switched to a variant after loading draws
// the same bytes as the scene loaded with that variant, on every cull path, uploading
// only the instance records' material words. tests/data/material_sweeps/variants.gltf
// (tools/material_sweeps/make_sweeps.py): three unlit spheres, variants "Warm" (sphere 0
// red, sphere 2 a checker texture) and "Cool" (sphere 1 masked away, sphere 2 green).
#include "gpu/material_extension_support.h"
#include "gpu_test_support.h"

#include <sherpa/render/renderer.h>
#include <sherpa/scene/gltf_extensions.h>
#include <sherpa/scene/material_variants.h>
#include <sherpa/texture/texture_pipeline.h>

#include <algorithm>

namespace sherpa::test {
namespace {

constexpr std::uint32_t kWarm = 0, kCool = 1;
constexpr std::uint32_t kRed = 3, kChecker = 4, kMasked = 5, kGreen = 6;

std::string file(const char* name) {
    return (data_dir() / "material_sweeps" / name).string();
}

TEST(MaterialVariants, ImportReadsNamesAndMappings) {
    EXPECT_TRUE(is_supported_gltf_extension("KHR_materials_variants"));
    const LoadResult r = load_scene(file("variants.gltf"));
    ASSERT_TRUE(r) << r.error;
    const Scene& s = *r.scene;
    for (const std::string& w : s.warnings) ADD_FAILURE() << w;
    ASSERT_EQ(s.variants.names, (std::vector<std::string>{"Warm", "Cool"}));
    EXPECT_EQ(find_variant(s, "Cool"), 1);
    EXPECT_EQ(find_variant(s, "cool"), -1);
    ASSERT_EQ(s.variants.meshes.size(), 3u);
    EXPECT_EQ(variant_material(s, 0, kWarm), kRed);
    EXPECT_EQ(variant_material(s, 0, kCool), 0u); // unmapped: the default
    EXPECT_EQ(variant_material(s, 1, kCool), kMasked);
    EXPECT_EQ(variant_material(s, 2, -1), 2u);
    EXPECT_EQ(possible_materials(s, 2), (std::vector<std::uint32_t>{2, kChecker, kGreen}));
    const auto warm = variant_changes(s, kWarm);
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
    LoadResult r = load_scene(file("variants.gltf"));
    ASSERT_TRUE(r) << r.error;
    Scene& s = *r.scene;
    const auto vertices = s.meshes[2].vertices.size();
    EXPECT_EQ(apply_material_variant(s, kCool), 2u); // spheres 1 and 2
    EXPECT_EQ(s.meshes[1].material_id, kMasked);
    EXPECT_EQ(s.instances[2].material_id, kGreen);
    EXPECT_EQ(s.variants.active, int(kCool));
    EXPECT_EQ(s.meshes[2].vertices.size(), vertices);
    EXPECT_EQ(apply_material_variant(s, -1), 2u);
    EXPECT_EQ(s.meshes[1].material_id, 1u);
}

TEST(MaterialVariants, BadMappingsAreWarnedWithTheirPointerAndKeepTheDefault) {
    const LoadResult r = load_scene(file("variants_bad.gltf"));
    ASSERT_TRUE(r) << r.error;
    const Scene& s = *r.scene;
    const std::string base = "/meshes/0/primitives/0/extensions/KHR_materials_variants/mappings/";
    // The Khronos validator's codes and pointers (all errors there); the file loads.
    const std::pair<std::string, std::string> expected[] = {
        {base + "0/material", "UNRESOLVED_REFERENCE"},
        {base + "1/variants/0", "UNRESOLVED_REFERENCE"},
        {base + "2/variants/0", "KHR_MATERIALS_VARIANTS_NON_UNIQUE_VARIANT"},
        {base + "3", "UNDEFINED_PROPERTY"}};
    for (const auto& [p, code] : expected) {
        const ValidationMessage* m = test::message_at(s, p);
        ASSERT_NE(m, nullptr) << p;
        EXPECT_EQ(m->code, code) << p;
        EXPECT_EQ(m->severity, Severity::Error) << p;
    }
    EXPECT_EQ(variant_material(s, 0, kWarm), 0u);     // material 99: the default
    EXPECT_EQ(variant_material(s, 0, kCool), kRed);   // the first mapping of Cool is kept
    EXPECT_EQ(variant_material(s, 2, kCool), kGreen); // other primitives untouched
}

class VariantSwitch : public GpuTest {
protected:
    std::vector<std::uint8_t> frame(gpu::Renderer& r, gpu::CullPath cull) {
        gpu::FrameRequest s;
        s.width = 160;
        s.height = 120;
        std::string error;
        EXPECT_TRUE(gpu::parse_camera_spec("eye=0,0,5:target=0,0,0:fov=45", s.camera, error));
        s.cull = cull;
        std::vector<std::uint8_t> rgba;
        r.render(s, &rgba);
        return rgba;
    }
    // The frame of a scene loaded with `variant` already shown.
    std::vector<std::uint8_t> loaded_with(std::int32_t variant, gpu::CullPath cull) {
        std::unique_ptr<Scene> s = load(file("variants.gltf"));
        apply_material_variant(*s, variant);
        renderer().load(*s);
        return frame(renderer(), cull);
    }
};

TEST_F(VariantSwitch, SwitchedSceneDrawsAsTheSceneLoadedWithTheVariant) {
    for (const gpu::CullPath cull : {gpu::CullPath::Cpu, gpu::CullPath::Gpu}) {
        SCOPED_TRACE(std::string(gpu::to_string(cull)));
        const auto defaults = loaded_with(-1, cull);
        const auto warm = loaded_with(kWarm, cull);
        const auto cool = loaded_with(kCool, cull);
        EXPECT_GT(differing_pixels(defaults, warm, 8), 500u);
        EXPECT_GT(differing_pixels(defaults, cool, 8), 500u);

        std::unique_ptr<Scene> s = load(file("variants.gltf"));
        renderer().load(*s);
        EXPECT_EQ(frame(renderer(), cull), defaults);
        gpu::VariantSwitch w = gpu::set_material_variant(renderer(), kWarm);
        EXPECT_EQ(w.meshes, 2u);
        EXPECT_EQ(w.instances, 2u);
        EXPECT_EQ(w.gpu_bytes, 8u); // two material words
        EXPECT_FALSE(w.culling_rebuilt);
        EXPECT_EQ(frame(renderer(), cull), warm);
        gpu::VariantSwitch c = gpu::set_material_variant(renderer(), kCool);
        EXPECT_EQ(c.meshes, 3u);
        EXPECT_TRUE(c.culling_rebuilt); // sphere 1 became masked
        EXPECT_EQ(frame(renderer(), cull), cool);
        gpu::set_material_variant(renderer(), -1);
        EXPECT_EQ(frame(renderer(), cull), defaults);
        EXPECT_EQ(gpu::set_material_variant(renderer(), -1).gpu_bytes, 0u); // unchanged
        EXPECT_THROW(gpu::set_material_variant(renderer(), 2), std::out_of_range);
    }
}

} // namespace
} // namespace sherpa::test
