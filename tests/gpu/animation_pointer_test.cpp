// KHR_animation_pointer on the ratified material extensions:
// tests/data/animation_pointer/extensions.gltf (tools/animation_pointer/make_pointer.py):
// material 0 uses every extension Sherpa draws with a texture in every slot; its
// channels animate each factor the glTF Object Model lists and the
// KHR_texture_transform of each extension texture, then come channels to refuse. The
// importer resolves each pointer (or warns naming the channel), the pose samples them,
// and the frame's GPU extension blocks, read back from the device, hold the values the
// specification's interpolation gives at chosen times (written out here, independently
// of Sherpa's sampler).
#include "gpu_test_support.h"

#include <sherpa/render/frame_request.h>
#include <sherpa/render/gpu_material_ext_structs.h>
#include <sherpa/render/material_readback.h>
#include <sherpa/render/renderer.h>
#include <sherpa/scene/animation.h>
#include <sherpa/scene/animation_pointer.h>

#include <cmath>
#include <cstring>

namespace sherpa::test {
namespace {

constexpr std::size_t kSlots = 14;              // extension texture slots animated
constexpr std::size_t kValid = 18 + kSlots + 2; // the file's valid channels
constexpr float kPi = 3.14159265358979f;

std::unique_ptr<scene::Scene> extensions_file() {
    const std::string path = (data_dir() / "animation_pointer" / "extensions.gltf").string();
    scene::LoadResult r = scene::load_scene(path);
    EXPECT_TRUE(r) << path << ": " << r.error;
    return std::move(r.scene);
}

float lerp(float a, float b, float t) { // LINEAR over keys at 0 and 2 s, clamped
    const float u = std::clamp(t / 2.0f, 0.0f, 1.0f);
    return a + (b - a) * u;
}

float step(float a, float b, float t) {
    return t < 1.0f ? a : b;
} // STEP, keys at 0 and 1 s

// attenuationDistance: CUBICSPLINE, keys 0 s (value 1, out-tangent 0.5) and 2 s (value
// 3, in-tangent 0): the Hermite spline with tangents times the key interval (Appendix C).
float attenuation_distance(float t) {
    const float d = 2.0f, u = std::clamp(t / d, 0.0f, 1.0f);
    const float u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * 1.0f + d * (u3 - 2 * u2 + u) * 0.5f + (-2 * u3 + 3 * u2) * 3.0f;
}

TEST(AnimationPointerExtensions, EveryObjectModelPointerResolvesAndTheRestAreWarned) {
    std::unique_ptr<scene::Scene> s = extensions_file();
    ASSERT_TRUE(s);
    ASSERT_EQ(s->animations.size(), 1u);
    const scene::Animation& a = s->animations[0];
    ASSERT_EQ(a.pointers.size(), kValid);
    for (const scene::PointerChannel& c : a.pointers) {
        EXPECT_EQ(scene::pointer_of(c.target), c.pointer) << "resolved to another property";
        EXPECT_EQ(c.target.object, 0u);
    }
    // Each refused channel: a warning naming its channel's pointer and the reason.
    const std::pair<std::size_t, const char*> refused[] = {
        {kValid + 0, "materials[1] does not use KHR_materials_clearcoat"},
        {kValid + 1, "materials[2] uses KHR_materials_clearcoat but does not draw it (unlit)"},
        {kValid + 2, "materials[1] does not use KHR_materials_sheen"},
        {kValid + 3,
         "materials[3] has no extensions/KHR_materials_clearcoat/clearcoatNormalTexture"},
        {kValid + 4, "materials[3] has no extensions/KHR_materials_clearcoat/clearcoatTexture"},
        {kValid + 5, "not an animatable material property"},
    };
    for (const auto& [channel, why] : refused) {
        const std::string where = "animations[0].channels[" + std::to_string(channel) +
                                  "].target.extensions.KHR_animation_pointer.pointer";
        const bool found = std::any_of(s->warnings.begin(), s->warnings.end(), [&](const auto& w) {
            return w.find(where) != std::string::npos && w.find(why) != std::string::npos;
        });
        EXPECT_TRUE(found) << where << ": " << why;
    }
}

TEST(AnimationPointerExtensions, PoseSamplesAndAppliesEveryExtensionValue) {
    std::unique_ptr<scene::Scene> s = extensions_file();
    ASSERT_TRUE(s);
    for (const float t : {0.5f, 1.5f}) {
        SCOPED_TRACE("t = " + std::to_string(t));
        const scene::Pose pose = scene::evaluate_pose(*s, 0, t);
        ASSERT_EQ(pose.properties.size(), kValid);
        std::vector<scene::MaterialInstance> materials = s->materials;
        const auto changed =
            scene::apply_animated_properties(pose.properties, materials, {}, {}, nullptr);
        EXPECT_EQ(changed, std::vector<std::uint32_t>{0});
        const scene::MaterialInstance& m = materials[0];
        EXPECT_FLOAT_EQ(m.clearcoat->factor, lerp(0, 1, t));
        EXPECT_FLOAT_EQ(m.clearcoat->roughness_factor, step(0.2f, 0.6f, t));
        EXPECT_FLOAT_EQ(m.clearcoat->normal_scale, lerp(1, 0.5f, t));
        EXPECT_FLOAT_EQ(m.transmission->factor, lerp(0, 1, t));
        EXPECT_FLOAT_EQ(m.volume->thickness_factor, lerp(0, 2, t));
        EXPECT_NEAR(m.volume->attenuation_distance, attenuation_distance(t), 1e-5);
        EXPECT_FLOAT_EQ(m.volume->attenuation_color.y, lerp(1, 0.5f, t));
        EXPECT_FLOAT_EQ(m.sheen->color_factor.x, lerp(0, 1, t));
        EXPECT_FLOAT_EQ(m.sheen->roughness_factor, step(0.3f, 0.7f, t));
        EXPECT_FLOAT_EQ(m.iridescence->factor, lerp(0, 1, t));
        EXPECT_FLOAT_EQ(m.iridescence->ior, lerp(1.3f, 2.0f, t));
        EXPECT_FLOAT_EQ(m.iridescence->thickness_minimum, lerp(100, 200, t));
        EXPECT_FLOAT_EQ(m.iridescence->thickness_maximum, lerp(400, 800, t));
        EXPECT_FLOAT_EQ(m.anisotropy->strength, lerp(0, 1, t));
        EXPECT_NEAR(m.anisotropy->rotation, lerp(0, kPi, t), 1e-6);
        EXPECT_FLOAT_EQ(*m.dispersion, lerp(0, 1, t));
        EXPECT_FLOAT_EQ(m.diffuse_transmission->factor, lerp(0, 1, t));
        EXPECT_FLOAT_EQ(m.diffuse_transmission->color_factor.x, lerp(1, 0, t));
        EXPECT_FLOAT_EQ(m.sheen->color.transform.offset.x, lerp(0, 0.05f * 6, t));
        EXPECT_FLOAT_EQ(m.sheen->color.transform.scale.y, lerp(1, 4, t));
        EXPECT_FLOAT_EQ(m.clearcoat->normal.transform.rotation, step(0, kPi / 2, t));
        EXPECT_FLOAT_EQ(m.iridescence->thickness.transform.offset.y, lerp(0, 0.5f, t));
        // The other materials keep their values.
        EXPECT_FLOAT_EQ(materials[3].clearcoat->factor, 1.0f);
    }
}

// The block of type B at word `at` (from the buffer's start) of a read-back material.
template <class B> B block(const render::MaterialReadback& r, std::uint32_t at) {
    B out{};
    EXPECT_NE(at, render::kNoExtension);
    const std::size_t first = at - r.extension_first;
    EXPECT_LE((first * 16 + sizeof(B)), r.extension_words.size() * 16);
    if (at != render::kNoExtension && first * 16 + sizeof(B) <= r.extension_words.size() * 16)
        std::memcpy(&out, &r.extension_words[first], sizeof(B));
    return out;
}

// A texture transform without rotation: scale on the diagonal, offset in the third column.
void expect_uv(const render::GPUTextureTransform& uv, glm::vec2 offset, glm::vec2 scale,
               const char* what) {
    SCOPED_TRACE(what);
    EXPECT_NEAR(uv.row0.x, scale.x, 1e-5);
    EXPECT_NEAR(uv.row0.y, 0.0f, 1e-5);
    EXPECT_NEAR(uv.row0.z, offset.x, 1e-5);
    EXPECT_NEAR(uv.row1.x, 0.0f, 1e-5);
    EXPECT_NEAR(uv.row1.y, scale.y, 1e-5);
    EXPECT_NEAR(uv.row1.z, offset.y, 1e-5);
}

class AnimationPointerGpu : public GpuTest {};

// Frames at chosen times; after each, the material's GPU extension blocks are read back
// from the device and must hold the specification's values (the GPU record the shaders
// read), while the material without extensions still has no block.
TEST_F(AnimationPointerGpu, AnimatedExtensionValuesReachTheGpuRecords) {
    std::unique_ptr<scene::Scene> s = extensions_file();
    ASSERT_TRUE(s);
    render::RendererOptions options;
    options.textures = test_texture_settings();
    render::Renderer r(context(), options);
    r.load(*s);
    const std::uint64_t words = r.scene()->materials().extensions().words.size();
    render::FrameRequest f;
    f.width = 64;
    f.height = 48;
    for (const float t : {0.5f, 1.5f, 0.25f}) {
        SCOPED_TRACE("t = " + std::to_string(t));
        f.pose = std::make_shared<const scene::Pose>(scene::evaluate_pose(*s, 0, t));
        r.render(f);
        const auto back = render::read_material(r, *s, 0);
        ASSERT_TRUE(back);
        ASSERT_FALSE(back->extension_words.empty());
        const auto index = block<render::GPUExtensionIndex>(*back, back->extension_first);
        const auto cc = block<render::GPUClearcoatBlock>(*back, index.clearcoat);
        EXPECT_NEAR(cc.factors.x, lerp(0, 1, t), 1e-6);
        EXPECT_NEAR(cc.factors.y, step(0.2f, 0.6f, t), 1e-6);
        EXPECT_NEAR(cc.factors.z, lerp(1, 0.5f, t), 1e-6);
        expect_uv(cc.clearcoat_uv, {lerp(0, 0.15f, t), lerp(0, 0.5f, t)}, {1, 1}, "clearcoat");
        expect_uv(cc.roughness_uv, {lerp(0, 0.20f, t), lerp(0, 0.5f, t)}, {1, 1}, "cc roughness");
        // clearcoatNormalTexture's rotation steps to pi/2 at 1 s: the linear part turns.
        const float rotation = step(0, kPi / 2, t);
        EXPECT_NEAR(cc.normal_uv.row0.x, std::cos(rotation), 1e-5);
        EXPECT_NEAR(std::abs(cc.normal_uv.row0.y), std::sin(rotation), 1e-5);
        const auto tr = block<render::GPUTransmissionBlock>(*back, index.transmission);
        EXPECT_NEAR(tr.factor, lerp(0, 1, t), 1e-6);
        expect_uv(tr.uv, {lerp(0, 0.40f, t), lerp(0, 0.5f, t)}, {1, 1}, "transmission");
        const auto vol = block<render::GPUVolumeBlock>(*back, index.volume);
        EXPECT_NEAR(vol.thickness_factor, lerp(0, 2, t), 1e-6);
        EXPECT_NEAR(vol.attenuation.w, attenuation_distance(t), 1e-5);
        EXPECT_NEAR(vol.attenuation.x, lerp(1, 0.2f, t), 1e-6);
        EXPECT_NEAR(vol.attenuation.z, lerp(1, 0.8f, t), 1e-6);
        expect_uv(vol.thickness_uv, {lerp(0, 0.45f, t), lerp(0, 0.5f, t)}, {1, 1}, "thickness");
        const auto sh = block<render::GPUSheenBlock>(*back, index.sheen);
        EXPECT_NEAR(sh.factors.x, lerp(0, 1, t), 1e-6);
        EXPECT_NEAR(sh.factors.y, lerp(0, 0.5f, t), 1e-6);
        EXPECT_NEAR(sh.factors.w, step(0.3f, 0.7f, t), 1e-6);
        expect_uv(sh.color_uv, {lerp(0, 0.30f, t), lerp(0, 0.5f, t)},
                  {lerp(1, 2, t), lerp(1, 4, t)}, "sheen colour");
        expect_uv(sh.roughness_uv, {lerp(0, 0.35f, t), lerp(0, 0.5f, t)}, {1, 1}, "sheen rough");
        const auto ir = block<render::GPUIridescenceBlock>(*back, index.iridescence);
        EXPECT_NEAR(ir.factors.x, lerp(0, 1, t), 1e-6);
        EXPECT_NEAR(ir.factors.y, lerp(1.3f, 2.0f, t), 1e-6);
        EXPECT_NEAR(ir.factors.z, lerp(100, 200, t), 1e-4);
        EXPECT_NEAR(ir.factors.w, lerp(400, 800, t), 1e-4);
        expect_uv(ir.uv, {lerp(0, 0.65f, t), lerp(0, 0.5f, t)}, {1, 1}, "iridescence");
        expect_uv(ir.thickness_uv, {lerp(0, 0.70f, t), lerp(0, 0.5f, t)}, {1, 1}, "film");
        const auto an = block<render::GPUAnisotropyBlock>(*back, index.anisotropy);
        EXPECT_NEAR(an.factors.x, lerp(0, 1, t), 1e-6);
        EXPECT_NEAR(an.factors.y, std::cos(lerp(0, kPi, t)), 1e-5);
        EXPECT_NEAR(an.factors.z, std::sin(lerp(0, kPi, t)), 1e-5);
        expect_uv(an.uv, {lerp(0, 0.60f, t), lerp(0, 0.5f, t)}, {1, 1}, "anisotropy");
        EXPECT_NEAR(block<render::GPUDispersionBlock>(*back, index.dispersion).dispersion,
                    lerp(0, 1, t), 1e-6);
        const auto dt =
            block<render::GPUDiffuseTransmissionBlock>(*back, index.diffuse_transmission);
        EXPECT_NEAR(dt.color_factor.w, lerp(0, 1, t), 1e-6);
        EXPECT_NEAR(dt.color_factor.x, lerp(1, 0, t), 1e-6);
        EXPECT_NEAR(dt.color_factor.y, 1.0f, 1e-6);
        expect_uv(dt.uv, {lerp(0, 0.50f, t), lerp(0, 0.5f, t)}, {1, 1}, "diffuse transmission");
        expect_uv(dt.color_uv, {lerp(0, 0.55f, t), lerp(0, 0.5f, t)}, {1, 1}, "dt colour");
        const auto sp = block<render::GPUSpecularBlock>(*back, index.specular);
        expect_uv(sp.specular_uv, {lerp(0, 0.05f, t), lerp(0, 0.5f, t)}, {1, 1}, "specular");
        expect_uv(sp.color_uv, {lerp(0, 0.10f, t), lerp(0, 0.5f, t)}, {1, 1}, "specular colour");
        // Only materials that use an extension have blocks, and animation adds none.
        const auto plain = render::read_material(r, *s, 1);
        ASSERT_TRUE(plain);
        EXPECT_TRUE(plain->extension_words.empty());
        EXPECT_EQ(r.scene()->materials().extensions().words.size(), words);
    }
}

} // namespace
} // namespace sherpa::test
