// Emissive triangles as lights in the path tracer (docs/path_tracer.md): the light list
// on the CPU (sherpa/render/emissive_lights.h) against hand computation, and on lavapipe
// under the validation layer a small emissive quad lighting a diffuse floor: with light
// sampling the mean agrees with BSDF sampling alone (the unbiased reference, 4x the
// samples) and the estimated error at the same sample count is far lower. Hostile
// emission (infinite factor, 1e30 strength) gives a named warning and a finite image.
#include "gpu_test_support.h"
#include "path_trace_renderer.h"
#include "sphere_scenes.h"

#include <sherpa/render/emissive_lights.h>
#include <sherpa/render/path_trace.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace sherpa::test {
namespace {

// A white double-sided floor 4 x 4 at y = 0 and, 1 above it, a 0.5 x 0.5 quad facing
// down (single-sided, black) that emits `emissive` x `strength`; with `point_light` also
// a KHR_lights_punctual point light 0.6 above the floor's corner quadrant.
std::string lit_floor_gltf(const std::string& emissive, const std::string& strength,
                           bool point_light = false) {
    const float pos[] = {-2,     0, -2,     2,     0, -2,     2,     0, 2,     -2,     0, 2,
                         -0.25f, 1, -0.25f, 0.25f, 1, -0.25f, 0.25f, 1, 0.25f, -0.25f, 1, 0.25f};
    const float nrm[] = {0, 1,  0, 0, 1,  0, 0, 1,  0, 0, 1,  0,
                         0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0};
    const std::uint16_t idx[] = {0, 2, 1, 0, 3, 2, 0, 1, 2, 0, 2, 3};
    std::vector<std::uint8_t> bytes(sizeof(pos) + sizeof(nrm) + sizeof(idx));
    std::memcpy(bytes.data(), pos, sizeof(pos));
    std::memcpy(bytes.data() + sizeof(pos), nrm, sizeof(nrm));
    std::memcpy(bytes.data() + sizeof(pos) + sizeof(nrm), idx, sizeof(idx));
    std::ostringstream j;
    j << R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_emissive_strength")"
      << (point_light
              ? R"(,"KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":)"
                R"([{"type":"point","color":[1,0.8,0.6],"intensity":3}]}},)"
                R"("scene":0,"scenes":[{"nodes":[0,1,2]}],"nodes":[{"mesh":0},{"mesh":1},)"
                R"({"translation":[1,0.6,1],"extensions":{"KHR_lights_punctual":{"light":0}}}],)"
              : R"(],"scene":0,"scenes":[{"nodes":[0,1]}],"nodes":[{"mesh":0},{"mesh":1}],)")
      << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1},"indices":2,"material":0}]},)"
      << R"({"primitives":[{"attributes":{"POSITION":3,"NORMAL":4},"indices":5,"material":1}]}],)"
      << R"("materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],"metallicFactor":0},"doubleSided":true},)"
      << R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0},"emissiveFactor":)"
      << emissive << R"(,"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":)"
      << strength << "}}}],"
      << R"("accessors":[)"
      << R"({"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-2,0,-2],"max":[2,0,2]},)"
      << R"({"bufferView":2,"componentType":5126,"count":4,"type":"VEC3"},)"
      << R"({"bufferView":4,"componentType":5123,"count":6,"type":"SCALAR"},)"
      << R"({"bufferView":1,"componentType":5126,"count":4,"type":"VEC3","min":[-0.25,1,-0.25],"max":[0.25,1,0.25]},)"
      << R"({"bufferView":3,"componentType":5126,"count":4,"type":"VEC3"},)"
      << R"({"bufferView":5,"componentType":5123,"count":6,"type":"SCALAR"}],"bufferViews":[)"
      << R"({"buffer":0,"byteOffset":0,"byteLength":48,"target":34962},)"
      << R"({"buffer":0,"byteOffset":48,"byteLength":48,"target":34962},)"
      << R"({"buffer":0,"byteOffset":96,"byteLength":48,"target":34962},)"
      << R"({"buffer":0,"byteOffset":144,"byteLength":48,"target":34962},)"
      << R"({"buffer":0,"byteOffset":192,"byteLength":12,"target":34963},)"
      << R"({"buffer":0,"byteOffset":204,"byteLength":12,"target":34963}],)"
      << R"("buffers":[{"byteLength":)" << bytes.size()
      << R"(,"uri":"data:application/octet-stream;base64,)" << base64(bytes) << "\"}]}";
    return j.str();
}

std::unique_ptr<scene::Scene> load_file(const std::filesystem::path& p) {
    scene::LoadResult r = scene::load_scene(p.string());
    EXPECT_TRUE(r) << p << ": " << r.error;
    return std::move(r.scene);
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.find(text) != std::string::npos; });
}

// Two triangles of 0.125 each emitting luminance 10: equal shares, density per area
// luminance / power = 10 / (10 x 0.25) = 4.
TEST(EmissiveLightsCpu, ListFollowsPowerAndSkipsWhatCannotBeSampled) {
    auto scene = load_file(write_temp("pt_lights.gltf", lit_floor_gltf("[1,1,1]", "10")));
    ASSERT_TRUE(scene);
    const render::EmissiveLights lights = render::emissive_lights(*scene);
    ASSERT_EQ(lights.triangles.size(), 2u);
    EXPECT_NEAR(lights.triangles[0].p0_cdf.w, 0.5f, 1e-6f);
    EXPECT_EQ(lights.triangles[1].p0_cdf.w, 1.0f);
    EXPECT_NEAR(lights.triangles[0].e1_density.w, 4.0f, 1e-5f);
    EXPECT_NEAR(lights.power, 2.5, 1e-6);
    EXPECT_NEAR(lights.inv_power, 0.4f, 1e-7f);
    EXPECT_TRUE(lights.warnings.empty());
    // The cap: none sampled past it.
    EXPECT_TRUE(render::emissive_lights(*scene, 1).triangles.empty());
    EXPECT_TRUE(mentions(render::emissive_lights(*scene, 1).warnings, "more than 1 emissive"));

    // 1e30 strength: a warning at load naming the property, none in the light list.
    auto huge = load_file(write_temp("pt_lights_huge.gltf", lit_floor_gltf("[1,1,1]", "1e30")));
    ASSERT_TRUE(huge);
    EXPECT_TRUE(mentions(huge->warnings, "KHR_materials_emissive_strength.emissiveStrength"));
    const render::EmissiveLights none = render::emissive_lights(*huge);
    EXPECT_TRUE(none.triangles.empty());
    EXPECT_TRUE(mentions(none.warnings, "beyond 1e20"));
    // An infinite factor (1e39 in JSON) is reset at load with a warning: nothing emits.
    auto inf = load_file(write_temp("pt_lights_inf.gltf", lit_floor_gltf("[1e39,0,0]", "1")));
    ASSERT_TRUE(inf);
    EXPECT_TRUE(mentions(inf->warnings, "emissiveFactor: not finite"));
    EXPECT_TRUE(render::emissive_lights(*inf).triangles.empty());
}

// The emissive texture's mean over a triangle (at load, on the CPU): a 4 x 2 image, white
// in its left half (u < 0.5) and black in its right, in linear luminance from sRGB.
TEST(EmissiveLightsCpu, TextureMeanOverATriangle) {
    std::vector<std::uint8_t> rgba(4 * 2 * 4, 255);
    for (int y = 0; y < 2; ++y)
        for (int x = 2; x < 4; ++x)
            for (int c = 0; c < 3; ++c) rgba[std::size_t((y * 4 + x) * 4 + c)] = 0;
    const render::LuminanceGrid g = render::luminance_grid(4, 2, rgba);
    ASSERT_EQ(g.width, 4u);
    EXPECT_NEAR(g.mean, 0.5, 1e-6);
    const glm::vec2 left[3] = {{0.0f, 0.0f}, {0.45f, 0.0f}, {0.0f, 1.0f}};
    const glm::vec2 right[3] = {{0.55f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}};
    EXPECT_NEAR(render::mean_over_triangle(g, left), 1.0, 1e-6);
    EXPECT_NEAR(render::mean_over_triangle(g, right), 0.0, 1e-6);
    // Repeat wraps a whole period away onto the same texels; clamp holds the edge.
    const glm::vec2 shifted[3] = {{2.0f, -3.0f}, {2.45f, -3.0f}, {2.0f, -2.0f}};
    EXPECT_NEAR(render::mean_over_triangle(g, shifted), 1.0, 1e-6);
    const glm::vec2 beyond[3] = {{1.5f, 0.0f}, {2.0f, 0.0f}, {2.0f, 1.0f}};
    EXPECT_NEAR(render::mean_over_triangle(g, beyond, scene::AddressMode::ClampToEdge), 0.0, 1e-6);
    // Mirrored repeat: u in [1, 2) reads the image reversed (white at its right end).
    const glm::vec2 mirrored[3] = {{1.55f, 0.0f}, {2.0f, 0.0f}, {2.0f, 1.0f}};
    EXPECT_NEAR(render::mean_over_triangle(g, mirrored, scene::AddressMode::MirroredRepeat), 1.0,
                1e-6);
    // Non-finite coordinates read a texel, never out of bounds.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const glm::vec2 broken[3] = {{nan, 0.0f}, {1e30f, -1e30f}, {0.0f, nan}};
    EXPECT_TRUE(std::isfinite(render::mean_over_triangle(g, broken)));
    // The grid is box-filtered down to kEmissiveGridSize a side, keeping the mean.
    std::vector<std::uint8_t> big(std::size_t(1024) * 4 * 4, 255);
    for (std::size_t i = 0; i < big.size(); i += 8) big[i] = big[i + 1] = big[i + 2] = 0;
    const render::LuminanceGrid small = render::luminance_grid(1024, 4, big);
    EXPECT_EQ(small.width, render::kEmissiveGridSize);
    EXPECT_NEAR(small.mean, 0.5, 1e-6);
    EXPECT_NEAR(small.texels[0], 0.5f, 1e-6f);
}

// DamagedHelmet emits through a mostly black texture with emissive factor 1 on every
// triangle: the list weighs each triangle by the texture's mean over it, with a floor
// that keeps every probability above 0; the densities per area integrate to 1.
TEST(EmissiveLightsCpu, DamagedHelmetWeighsTrianglesByItsEmissiveTexture) {
    auto scene = load_file(gltf_asset("DamagedHelmet"));
    ASSERT_TRUE(scene);
    const auto start = std::chrono::steady_clock::now();
    const render::EmissiveLights lights = render::emissive_lights(*scene);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ASSERT_FALSE(lights.triangles.empty());
    EXPECT_EQ(lights.textures_read, 1u);
    EXPECT_LT(lights.sampled_power, 0.5 * lights.power) << "the texture is mostly black";
    double integral = 0.0;
    float least = 1e30f, most = 0.0f;
    for (const render::EmissiveTriangle& t : lights.triangles) {
        const double area = 0.5 * glm::length(glm::cross(glm::vec3(t.e1_density), glm::vec3(t.e2)));
        integral += double(t.e1_density.w) * area;
        least = std::min(least, t.emission.y);
        most = std::max(most, t.emission.y);
        EXPECT_EQ(t.emission.x, 1.0f); // the material's luminance (MIS weights)
    }
    EXPECT_NEAR(integral, 1.0, 1e-3);
    EXPECT_GT(least, 0.0f);
    EXPECT_GT(most, 100.0f * least) << "glowing triangles outweigh black ones";
    std::printf(
        "DamagedHelmet: %zu emissive triangles, sampled power %.4f of material power "
        "%.4f, estimated luminance %.3g to %.3g; made in %.1f ms (its 2048x2048 texture decoded)\n",
        lights.triangles.size(), lights.sampled_power, lights.power, least, most, ms);
}

// Material variants that change what emits: no list (one made for the loaded variant
// would bias the others after a switch); variants that keep every emitter's luminance
// keep it.
TEST(EmissiveLightsCpu, VariantsThatChangeEmissionGetNoList) {
    auto scene = load_file(write_temp("pt_lights_variants.gltf", lit_floor_gltf("[1,1,1]", "10")));
    ASSERT_TRUE(scene);
    const auto emitter = std::find_if(
        scene->instances.begin(), scene->instances.end(), [&](const scene::MeshInstance& i) {
            return render::emitted_luminance(scene->materials[i.material_id]) > 0.0f;
        });
    ASSERT_NE(emitter, scene->instances.end());
    scene::MaterialInstance same = scene->materials[emitter->material_id];
    scene::MaterialInstance dark = same;
    dark.emissive_factor = glm::vec3(0.0f);
    scene->materials.push_back(same);
    scene->materials.push_back(dark);
    const auto n = static_cast<std::int32_t>(scene->materials.size());
    scene->variants.names = {"same", "dark"};
    scene->variants.meshes = {
        scene::VariantMeshMapping{emitter->mesh_id, emitter->material_id, {n - 2, -1}}};
    EXPECT_EQ(render::emissive_lights(*scene).triangles.size(), 2u);
    scene->variants.meshes[0].materials[1] = n - 1;
    const render::EmissiveLights none = render::emissive_lights(*scene);
    EXPECT_TRUE(none.triangles.empty());
    EXPECT_TRUE(mentions(none.warnings, "changes which surfaces emit"));
}

class PathTraceLights : public GpuTest {
protected:
    static render::Renderer& rt() { return path_trace_renderer(); }
    static void TearDownTestSuite() { rt().unload(); }

    // The floor from above the light (its single-sided back is invisible from there), in
    // a black environment, no sun.
    static render::FrameRequest view() {
        render::FrameRequest s;
        s.width = s.height = 64;
        std::string error;
        EXPECT_TRUE(render::parse_camera_spec("eye=0,4,2.5:target=0,0,0:fov=60", s.camera, error));
        s.sun = false;
        s.shadows = false;
        s.tone_map = render::ToneMap::Linear;
        s.background = render::Background::Color;
        s.clear_color = glm::vec4(0, 0, 0, 1);
        s.renderer = render::RendererKind::RayTraced;
        s.path.max_bounces = 2;
        return s;
    }
};

struct BlackEnvironment {
    render::Renderer& r;
    explicit BlackEnvironment(render::Renderer& renderer) : r(renderer) {
        const render::EnvironmentImage black = render::uniform_environment(glm::vec3(0.0f));
        r.set_environment(&black);
    }
    ~BlackEnvironment() { r.set_environment(nullptr); }
};

// The mean over the pixels of a path-traced image's mean radiance (rgb averaged).
double mean_radiance(const render::PathTraceImage& img) {
    double sum = 0.0;
    for (std::size_t i = 0; i < img.sums.size(); i += 4)
        sum += (img.sums[i] + img.sums[i + 1] + img.sums[i + 2]) / 3.0;
    return sum / double(img.samples) / double(img.width * img.height);
}

// The loaded scene at 64 spp with light sampling, then with BSDF sampling alone at 64
// spp (its error) continued to 256 (the unbiased reference's mean).
struct LightAgainstBsdf {
    double light_mean = 0.0, bsdf_mean = 0.0;
    double light_error = 0.0, bsdf_error = 0.0; // relative, at 64 spp each
};

LightAgainstBsdf light_against_bsdf_sampling(render::Renderer& r, render::FrameRequest s,
                                             const char* what) {
    s.path.samples = 64;
    s.path.restart = true;
    r.render(s);
    const render::PathTraceImage light = render::read_path_trace(r);
    LightAgainstBsdf out;
    out.light_error = render::estimate_error(light).relative_error;
    s.path.light_sampling = false;
    r.render(s);
    out.bsdf_error = render::path_trace_error(r).relative_error;
    s.path.restart = false;
    s.path.samples = 192;
    r.render(s);
    const render::PathTraceImage bsdf = render::read_path_trace(r);
    EXPECT_EQ(bsdf.samples, 256u);
    out.light_mean = mean_radiance(light);
    out.bsdf_mean = mean_radiance(bsdf);
    std::printf("%s, 64x64: mean radiance %.5f with light sampling (64 spp), %.5f BSDF "
                "sampling alone (256 spp); relative error at 64 spp %.4f vs %.4f\n",
                what, out.light_mean, out.bsdf_mean, out.light_error, out.bsdf_error);
    return out;
}

TEST_F(PathTraceLights, LightSamplingAgreesWithBsdfSamplingAndLowersTheError) {
    BlackEnvironment black(rt());
    auto scene = load(write_temp("pt_lights.gltf", lit_floor_gltf("[1,1,1]", "10")).string());
    rt().load(*scene);
    const LightAgainstBsdf r =
        light_against_bsdf_sampling(rt(), view(), "emissive quad over a floor");
    EXPECT_GT(r.bsdf_mean, 0.01);
    EXPECT_NEAR(r.light_mean / r.bsdf_mean, 1.0, 0.03);
    EXPECT_LT(r.light_error, 0.5 * r.bsdf_error);
}

// An emitter lit through its texture (tests/data/textured_emitter.gltf: a 1 x 1 quad
// facing down 1 above a grey floor, emissive strength 20 through an 8 x 8 texture whose
// first column is white and the rest black, nearest filtering): its triangles are drawn
// by the texture's mean over them, while the multiple-importance weights keep the
// material's density. The two weights still sum to 1, so the mean agrees with BSDF
// sampling alone (the unbiased reference, 256 spp).
TEST_F(PathTraceLights, TextureWeightedEmitterAgreesWithBsdfSampling) {
    BlackEnvironment black(rt());
    auto scene = load(std::string(SHERPA_TEST_DATA_DIR) + "/textured_emitter.gltf");
    ASSERT_TRUE(scene);
    EXPECT_EQ(render::emissive_lights(*scene).textures_read, 1u);
    rt().load(*scene);
    const LightAgainstBsdf r =
        light_against_bsdf_sampling(rt(), view(), "textured emitter over a floor");
    EXPECT_GT(r.bsdf_mean, 0.005);
    EXPECT_NEAR(r.light_mean / r.bsdf_mean, 1.0, 0.03);
    EXPECT_LT(r.light_error, r.bsdf_error);
}

// 1e30 strength: a finite image (samples capped), no validation message.
TEST_F(PathTraceLights, AbsurdEmissionGivesAFiniteImage) {
    BlackEnvironment black(rt());
    for (const char* strength : {"1e30", "3e38"}) {
        auto scene =
            load(write_temp("pt_lights_huge.gltf", lit_floor_gltf("[1,1,1]", strength)).string());
        rt().load(*scene);
        render::FrameRequest s = view();
        s.path.samples = 8;
        s.path.restart = true;
        std::vector<std::uint8_t> rgba;
        rt().render(s, &rgba);
        const render::PathTraceImage img = render::read_path_trace(rt());
        ASSERT_EQ(img.samples, 8u);
        std::size_t lit = 0;
        for (float v : img.sums) {
            ASSERT_TRUE(std::isfinite(v)) << strength;
            lit += v > 0.0f ? 1 : 0;
        }
        EXPECT_GT(lit, 0u) << strength << ": the floor is lit";
        EXPECT_EQ(rgba.size(), std::size_t(64 * 64 * 4));
    }
}

// Per block of 16 x 16 pixels: the mean luminance and the variance of that mean (the
// pixels' sample variances over n, summed, over the block's pixel count squared).
struct BlockMeans {
    std::vector<double> mean, variance;
};

BlockMeans block_means(const render::PathTraceImage& img, std::uint32_t block) {
    const std::uint32_t bx = img.width / block, by = img.height / block;
    BlockMeans out{std::vector<double>(std::size_t(bx) * by, 0.0),
                   std::vector<double>(std::size_t(bx) * by, 0.0)};
    const double n = img.samples, pixels = double(block) * block;
    for (std::uint32_t y = 0; y < by * block; ++y)
        for (std::uint32_t x = 0; x < bx * block; ++x) {
            const std::size_t i = std::size_t(y) * img.width + x, b = (y / block) * bx + x / block;
            const double lum = 0.2126 * img.sums[4 * i] + 0.7152 * img.sums[4 * i + 1] +
                               0.0722 * img.sums[4 * i + 2];
            const double m = lum / n, var = std::max(0.0, double(img.moments[i]) / n - m * m);
            out.mean[b] += m / pixels;
            out.variance[b] += var / n / (pixels * pixels);
        }
    return out;
}

// Direct light from one shadow ray per surface, its light chosen in proportion to what
// each would bring, converges to one ray per light (the reference): the sun (which the
// quad shadows), a point light, the room environment and the emissive quad, two
// bounces; every 16 x 16 block's mean luminance within 4.5 standard errors of the
// difference. A choice that dropped a light, or weighted it wrongly, fails in the
// blocks where that light matters.
TEST_F(PathTraceLights, OneLightRayConvergesToOneRayPerLight) {
    const render::EnvironmentImage room = render::room_environment(256);
    rt().set_environment(&room);
    auto scene =
        load(write_temp("pt_choice.gltf", lit_floor_gltf("[1,0.9,0.8]", "4", true)).string());
    rt().load(*scene);
    render::FrameRequest s = view();
    s.sun = true;
    s.sun_direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    s.path.samples = 256;
    s.path.restart = true;
    rt().render(s);
    const render::PathTraceImage one = render::read_path_trace(rt());
    const render::PathTraceError one_error = render::estimate_error(one);
    s.path.one_light_ray = false;
    rt().render(s);
    const render::PathTraceImage all = render::read_path_trace(rt());
    const render::PathTraceError all_error = render::estimate_error(all);
    rt().set_environment(nullptr);
    ASSERT_EQ(one.samples, 256u);
    ASSERT_EQ(all.samples, 256u);

    const BlockMeans a = block_means(one, 16), b = block_means(all, 16);
    double worst = 0.0;
    for (std::size_t i = 0; i < a.mean.size(); ++i) {
        const double sigma = std::sqrt(a.variance[i] + b.variance[i]);
        ASSERT_GT(b.mean[i], 0.0);
        const double z = std::abs(a.mean[i] - b.mean[i]) / sigma;
        worst = std::max(worst, z);
        EXPECT_LT(z, 4.5) << "block " << i << ": " << a.mean[i] << " one ray, " << b.mean[i]
                          << " one per light";
    }
    std::printf("sun, point light, room, emissive quad, 64x64, 256 spp: mean luminance %.5f one "
                "light ray, %.5f one ray per light (largest block difference %.2f standard "
                "errors); relative error %.4f vs %.4f\n",
                one_error.mean_luminance, all_error.mean_luminance, worst, one_error.relative_error,
                all_error.relative_error);
    EXPECT_NEAR(one_error.mean_luminance / all_error.mean_luminance, 1.0, 0.01);
}

} // namespace
} // namespace sherpa::test
