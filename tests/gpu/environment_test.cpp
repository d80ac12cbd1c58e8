// Environment lighting: the furnace test (a white sphere in a uniform environment of
// radiance 1 reflects exactly 1 at every roughness with energy compensation on), the
// equirectangular convention and rotation (docs/environment.md), the blender-data
// EXRs, bad input (unreadable, corrupt, NaN, 0-size) and what no environment costs.
#include "gpu_test_support.h"
#include "sphere_scenes.h"

#include <sherpa/render/environment.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace sherpa::test {
namespace {

namespace fs = std::filesystem;

// Removes the environment when a test ends: the renderer is shared by the binary.
struct EnvironmentGuard {
    render::Renderer& r;
    ~EnvironmentGuard() { r.set_environment(nullptr); }
};

float srgb_to_linear(std::uint8_t v) {
    const float c = float(v) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

struct FurnaceResult {
    float worst = 0.0f;            // largest |radiance - 1| over covered pixels
    std::vector<float> per_sphere; // mean radiance of each sphere
};

class EnvironmentTest : public GpuTest {
protected:
    FurnaceResult furnace(float metallic, bool compensation, int count);
};

// Renders the row of spheres in a uniform environment of radiance 1, linear tone
// mapping at -1 EV (so 1 reads 0.5, clear of the 8-bit ceiling), on a black background.
FurnaceResult EnvironmentTest::furnace(float metallic, bool compensation, int count) {
    auto scene = load(write_temp(metallic > 0 ? "metal.gltf" : "dielectric.gltf",
                                 sphere_row_gltf(count, metallic))
                          .string());
    renderer().load(*scene);
    render::FrameRequest s = furnace_view(count, 64); // every sphere ~50 px across
    s.energy_compensation = compensation;
    const auto rgba = draw(s);
    FurnaceResult out;
    out.per_sphere.assign(count, 0.0f);
    std::vector<int> covered(count, 0);
    for (std::uint32_t y = 0; y < s.height; ++y)
        for (std::uint32_t x = 0; x < s.width; ++x) {
            const std::uint8_t* p = &rgba[(std::size_t{y} * s.width + x) * 4];
            if (p[0] == 0 && p[1] == 0 && p[2] == 0) continue; // background
            const int sphere = int(x) / 64;
            for (int c = 0; c < 3; ++c) {
                const float v = 2.0f * srgb_to_linear(p[c]);
                out.worst = std::max(out.worst, std::abs(v - 1.0f));
                if (c == 0) out.per_sphere[sphere] += v, ++covered[sphere];
            }
        }
    for (int i = 0; i < count; ++i) {
        EXPECT_GT(covered[i], 1000) << "sphere " << i << " barely visible";
        out.per_sphere[i] /= float(std::max(covered[i], 1));
    }
    return out;
}

TEST_F(EnvironmentTest, FurnaceWhiteSpheresReflectOneAtEveryRoughness) {
    EnvironmentGuard guard{renderer()};
    const render::EnvironmentImage uniform = render::uniform_environment(glm::vec3(1.0f));
    renderer().set_environment(&uniform);
    constexpr int kCount = 11; // roughness 0, 0.1, .., 1
    for (const float metallic : {0.0f, 1.0f}) {
        const FurnaceResult on = furnace(metallic, true, kCount);
        const FurnaceResult off = furnace(metallic, false, kCount);
        std::string means_on, means_off;
        for (int i = 0; i < kCount; ++i) {
            means_on += " " + std::to_string(on.per_sphere[i]).substr(0, 5);
            means_off += " " + std::to_string(off.per_sphere[i]).substr(0, 5);
        }
        std::printf("furnace %s: compensation on: worst |L-1| %.4f, means%s\n"
                    "furnace %s: compensation off: worst |L-1| %.4f, means%s\n",
                    metallic > 0 ? "metal" : "dielectric", on.worst, means_on.c_str(),
                    metallic > 0 ? "metal" : "dielectric", off.worst, means_off.c_str());
        // Within 2% at every pixel of every roughness (8-bit steps are 0.5% here).
        EXPECT_LT(on.worst, 0.02f) << (metallic > 0 ? "metal" : "dielectric");
        if (metallic > 0) {
            // Without compensation a rough metal loses what single scattering misses.
            EXPECT_LT(off.per_sphere[kCount - 1], 0.9f);
            EXPECT_GT(off.worst, 0.1f);
        }
    }
    renderer().unload();
}

TEST_F(EnvironmentTest, Sh9IrradianceKeepsTheFurnaceAndMakesNoCube) {
    EnvironmentGuard guard{renderer()};
    const render::EnvironmentImage uniform = render::uniform_environment(glm::vec3(1.0f));
    render::EnvironmentOptions options;
    options.irradiance = render::IrradianceMode::Cube;
    renderer().set_environment(&uniform, options);
    const render::EnvironmentStats cube = renderer().resident().environment;
    EXPECT_EQ(cube.irradiance_size, 32u);
    // SH9 is the default.
    renderer().set_environment(&uniform);
    const render::EnvironmentStats sh = renderer().resident().environment;
    EXPECT_EQ(sh.irradiance, render::IrradianceMode::Sh9);
    EXPECT_EQ(sh.irradiance_size, 0u);
    // The 32x32 irradiance cube (6 faces of RGBA16F) is not made.
    EXPECT_EQ(cube.bytes - sh.bytes, 32u * 32u * 6u * 8u);
    const FurnaceResult dielectric = furnace(0.0f, true, 5);
    const FurnaceResult metal = furnace(1.0f, true, 5);
    std::printf("furnace SH9: dielectric worst |L-1| %.4f, metal %.4f\n", dielectric.worst,
                metal.worst);
    EXPECT_LT(dielectric.worst, 0.02f);
    EXPECT_LT(metal.worst, 0.02f);
    renderer().unload();
}

// A rough white dielectric row lit by radiance 1 + b.w: SH9 holds it exactly (bands 0
// and 1; the closed form is checked on the CPU in environment_sh_test.cpp), the cube by
// 48 filtered samples a texel, whose wide lobes read coarse levels and flatten the
// gradient a little: measured 1.95 8-bit steps apart on average, 6 at worst, the cube
// brighter where b.n < 0 (blue, whose gradient faces the camera: 2.9 steps).
TEST_F(EnvironmentTest, Sh9AndCubeIrradianceAgreeOnALinearEnvironment) {
    EnvironmentGuard guard{renderer()};
    const render::EnvironmentImage linear = environment_of(256, [](glm::vec3 d) {
        return glm::vec3(1.0f + 0.8f * d.x, 1.0f + 0.6f * d.y, 1.0f - 0.7f * d.z);
    });
    auto scene = load(write_temp("rough.gltf", sphere_row_gltf(3, 0.0f)).string());
    renderer().load(*scene);
    render::FrameRequest s = furnace_view(3, 64);
    render::EnvironmentOptions options;
    options.irradiance = render::IrradianceMode::Cube;
    renderer().set_environment(&linear, options);
    const auto cube = draw(s);
    options.irradiance = render::IrradianceMode::Sh9;
    renderer().set_environment(&linear, options);
    const auto sh = draw(s);
    ASSERT_EQ(cube.size(), sh.size());
    double sum = 0.0, signed_sum[3] = {};
    int worst = 0;
    std::size_t covered = 0;
    for (std::size_t i = 0; i < cube.size(); i += 4) {
        if ((cube[i] | cube[i + 1] | cube[i + 2]) == 0) continue; // background
        ++covered;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(cube[i + c]) - int(sh[i + c]));
            sum += d, worst = std::max(worst, d);
            signed_sum[c] += int(sh[i + c]) - int(cube[i + c]);
        }
    }
    const double mean = sum / double(3 * std::max<std::size_t>(covered, 1));
    std::printf("SH9 vs cube, linear environment: mean %.3f, worst %d 8-bit steps over %zu "
                "pixels; SH9 - cube per channel %.3f %.3f %.3f\n",
                mean, worst, covered, signed_sum[0] / covered, signed_sum[1] / covered,
                signed_sum[2] / covered);
    EXPECT_GT(covered, 3000u);
    EXPECT_LT(mean, 2.5);
    EXPECT_LE(worst, 8);
    renderer().unload();
}

// An environment whose colour says which axis a direction is nearest.
render::EnvironmentImage axis_environment() {
    render::EnvironmentImage img;
    img.width = 256;
    img.height = 128;
    img.name = "axes";
    img.rgba.resize(std::size_t{img.width} * img.height * 4);
    for (std::uint32_t y = 0; y < img.height; ++y)
        for (std::uint32_t x = 0; x < img.width; ++x) {
            // environment.h: u = atan2(z, x) / 2pi + 0.5, v = asin(y) / pi + 0.5, top row v = 1.
            const float u = (x + 0.5f) / img.width, v = 1.0f - (y + 0.5f) / img.height;
            const float ph = (u - 0.5f) * 2.0f * float(M_PI), th = (v - 0.5f) * float(M_PI);
            const glm::vec3 d{std::cos(th) * std::cos(ph), std::sin(th),
                              std::cos(th) * std::sin(ph)};
            glm::vec3 c{0.0f};
            const glm::vec3 a = glm::abs(d);
            if (a.x >= a.y && a.x >= a.z)
                c = d.x > 0 ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 1);
            else if (a.y >= a.z)
                c = d.y > 0 ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 1);
            else
                c = d.z > 0 ? glm::vec3(0, 0, 1) : glm::vec3(1, 1, 0);
            float* t = &img.rgba[(std::size_t{y} * img.width + x) * 4];
            t[0] = c.r, t[1] = c.g, t[2] = c.b, t[3] = 1.0f;
        }
    return img;
}

TEST_F(EnvironmentTest, BackgroundFollowsTheEquirectangularConventionAndRotation) {
    EnvironmentGuard guard{renderer()};
    const render::EnvironmentImage axes = axis_environment();
    renderer().set_environment(&axes);
    renderer().unload();
    struct Case {
        const char* camera;
        float rotation;
        glm::u8vec3 expected;
    } cases[] = {
        {"eye=0,0,0:target=1,0,0", 0.0f, {255, 0, 0}},    // +X red
        {"eye=0,0,0:target=-1,0,0", 0.0f, {0, 255, 255}}, // -X cyan
        {"eye=0,0,0:target=0,0,1", 0.0f, {0, 0, 255}},    // +Z blue
        {"eye=0,0,0:target=0,0,-1", 0.0f, {255, 255, 0}}, // -Z yellow
        {"eye=0,0,0:target=0,1,0:up=0,0,1", 0.0f, {0, 255, 0}},
        // Turned 90 degrees about +Y: what was at +Z now shows at R_y(90)(+Z) = +X.
        {"eye=0,0,0:target=1,0,0", 90.0f, {0, 0, 255}},
    };
    for (const Case& c : cases) {
        render::FrameRequest s;
        s.width = s.height = 32;
        std::string error;
        ASSERT_TRUE(render::parse_camera_spec(c.camera, s.camera, error)) << error;
        s.tone_map = render::ToneMap::Linear;
        s.environment_rotation = c.rotation;
        const auto rgba = draw(s);
        const std::uint8_t* p = &rgba[(16 * 32 + 16) * 4];
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(p[ch], c.expected[ch], 8) << c.camera << " rotation " << c.rotation;
    }
}

// A source read at level 0 (at most four cube faces wide) is uploaded in 32-bit floats
// where the device filters them; a wider one in half floats, with mips. Both read the
// same axis colours behind the camera.
TEST_F(EnvironmentTest, NarrowAndWideSourcesShowTheSameEnvironment) {
    EnvironmentGuard guard{renderer()};
    const render::EnvironmentImage axes = axis_environment();
    renderer().unload();
    render::FrameRequest s;
    s.width = s.height = 32;
    std::string error;
    ASSERT_TRUE(render::parse_camera_spec("eye=0,0,0:target=0,0,1", s.camera, error)) << error;
    s.tone_map = render::ToneMap::Linear;
    std::vector<std::vector<std::uint8_t>> frames;
    for (std::uint32_t face : {axes.width / 4, 16u}) { // level 0; the source's level 2+
        render::EnvironmentOptions options;
        options.specular_size = face;
        renderer().set_environment(&axes, options);
        EXPECT_EQ(renderer().resident().environment.cube_size, face);
        frames.push_back(draw(s));
    }
    const std::uint8_t* narrow = &frames[0][(16 * 32 + 16) * 4];
    const std::uint8_t* wide = &frames[1][(16 * 32 + 16) * 4];
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(narrow[ch], (glm::u8vec3{0, 0, 255})[ch], 8); // +Z blue
        EXPECT_NEAR(wide[ch], narrow[ch], 8);
    }
}

TEST_F(EnvironmentTest, NoEnvironmentHoldsNothing) {
    renderer().set_environment(nullptr);
    const render::EnvironmentStats none = renderer().resident().environment;
    EXPECT_FALSE(none.present);
    EXPECT_EQ(none.bytes, 0u);
    EnvironmentGuard guard{renderer()};
    const render::EnvironmentImage room = render::room_environment(512);
    renderer().set_environment(&room);
    const render::EnvironmentStats made = renderer().resident().environment;
    EXPECT_TRUE(made.present);
    EXPECT_EQ(made.cube_size, 128u); // a quarter of the width
    EXPECT_GT(made.bytes, 0u);
}

// The split-sum lookup table is the BRDF's: made with the first environment, reused by
// the next (no LUT pass: its GPU time is 0), freed with the last and made again after.
// A frame lit through the reused table is the frame lit through a fresh one.
TEST_F(EnvironmentTest, LookupTableIsMadeOnceWhileEnvironmentsFollowEachOther) {
    renderer().set_environment(nullptr);
    EnvironmentGuard guard{renderer()};
    auto scene = load(write_temp("lut.gltf", sphere_row_gltf(3, 1.0f)).string());
    renderer().load(*scene);
    const render::FrameRequest s = furnace_view(3, 48);
    const render::EnvironmentImage room = render::room_environment(256);
    const render::EnvironmentImage linear = environment_of(
        64, [](glm::vec3 d) { return glm::vec3(1.0f + 0.5f * d.x, 1.0f, 1.0f - 0.5f * d.z); });
    renderer().set_environment(&room);
    const render::EnvironmentStats first = renderer().resident().environment;
    renderer().set_environment(&linear);
    renderer().set_environment(&room);
    const render::EnvironmentStats reused = renderer().resident().environment;
    const auto lit_reused = draw(s);
    renderer().set_environment(nullptr);
    EXPECT_EQ(renderer().resident().environment.bytes, 0u);
    renderer().set_environment(&room);
    const render::EnvironmentStats fresh = renderer().resident().environment;
    const auto lit_fresh = draw(s);
    EXPECT_EQ(first.bytes, reused.bytes); // the table's bytes are counted while it is kept
    EXPECT_EQ(reused.pass_ms[4], 0.0);
    if (first.gpu_ms > 0.0) { // timestamps on this device
        EXPECT_GT(first.pass_ms[4], 0.0);
        EXPECT_GT(fresh.pass_ms[4], 0.0);
    }
    EXPECT_EQ(lit_reused, lit_fresh);
    renderer().unload();
}

TEST_F(EnvironmentTest, BlenderStudioLightsLoadAndLight) {
    const auto files = render::installed_studio_lights();
    if (files.empty())
        GTEST_SKIP() << "blender-data is not installed (" << render::kStudioLightsDir << ")";
    EXPECT_EQ(files.size(), 8u);
    EnvironmentGuard guard{renderer()};
    for (const std::string& f : files) {
        const render::EnvironmentLoad load = render::load_environment(f);
        EXPECT_FALSE(load.fallback) << f;
        EXPECT_TRUE(load.warnings.empty()) << f << ": " << load.warnings.front();
        EXPECT_EQ(load.image.width, 1024u) << f;
        EXPECT_EQ(load.image.height, 512u) << f;
    }
    const render::EnvironmentLoad studio = render::load_environment(files.front());
    renderer().set_environment(&studio.image);
    EXPECT_EQ(renderer().resident().environment.cube_size, 256u);
    EXPECT_EQ(renderer().resident().environment.specular_levels, 6u);
}

TEST_F(EnvironmentTest, BadFilesWarnAndFallBackToTheRoom) {
    const fs::path dir = fs::temp_directory_path();
    const fs::path missing = dir / "sherpa_env_test_missing.exr";
    fs::remove(missing);
    const fs::path corrupt =
        write_temp("corrupt.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\nxx");
    const fs::path empty =
        write_temp("empty.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 0\n");
    const fs::path text = write_temp("text.exr", "not an image");
    for (const fs::path& p : {missing, corrupt, empty, text}) {
        const render::EnvironmentLoad load = render::load_environment(p.string());
        EXPECT_TRUE(load.fallback) << p;
        ASSERT_FALSE(load.warnings.empty()) << p;
        EXPECT_NE(load.warnings.front().find(p.string()), std::string::npos)
            << load.warnings.front();
        EXPECT_NE(load.warnings.front().find("room"), std::string::npos) << load.warnings.front();
        EXPECT_EQ(load.image.name, "room");
        EXPECT_TRUE(load.image.valid());
    }
}

// A w x h RGB float image of one value, written by OpenImageIO (.exr or .hdr).
void write_image(const fs::path& p, int w, int h, float value) {
    std::vector<float> px(std::size_t(w) * h * 3, value);
    auto out = OIIO::ImageOutput::create(p.string());
    ASSERT_TRUE(out) << p;
    const OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(p.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data())) << out->geterror();
    out->close();
}

// Every failure names the file and falls back to the room.
void expect_room_fallback(const render::EnvironmentLoad& load, const fs::path& p) {
    EXPECT_TRUE(load.fallback) << p;
    ASSERT_FALSE(load.warnings.empty()) << p;
    EXPECT_NE(load.warnings.front().find(p.string()), std::string::npos) << load.warnings.front();
    EXPECT_NE(load.warnings.front().find("using the built-in room environment instead"),
              std::string::npos)
        << load.warnings.front();
    EXPECT_EQ(load.image.name, "room");
    EXPECT_TRUE(load.image.valid());
}

TEST_F(EnvironmentTest, TruncatedAndUnreadableFilesWarnAndFallBackToTheRoom) {
    // Real EXR and HDR files cut short: the header reads, the texels do not.
    for (const char* ext : {".exr", ".hdr"}) {
        const fs::path whole = fs::temp_directory_path() / (std::string("sherpa_env_whole") + ext);
        write_image(whole, 256, 128, 0.5f);
        const auto size = fs::file_size(whole);
        const fs::path cut = fs::temp_directory_path() / (std::string("sherpa_env_cut") + ext);
        fs::copy_file(whole, cut, fs::copy_options::overwrite_existing);
        fs::resize_file(cut, size / 3);
        const render::EnvironmentLoad ok = render::load_environment(whole.string());
        EXPECT_FALSE(ok.fallback) << whole;
        expect_room_fallback(render::load_environment(cut.string()), cut);
    }
    // A directory is not an image.
    const fs::path dir = fs::temp_directory_path() / "sherpa_env_dir.exr";
    fs::create_directories(dir);
    expect_room_fallback(render::load_environment(dir.string()), dir);
}

TEST_F(EnvironmentTest, OneTexelImageIsAUniformEnvironmentWithAWarning) {
    const fs::path p = fs::temp_directory_path() / "sherpa_env_test_1x1.exr";
    write_image(p, 1, 1, 0.25f);
    const render::EnvironmentLoad load = render::load_environment(p.string());
    EXPECT_FALSE(load.fallback);
    ASSERT_EQ(load.warnings.size(), 1u);
    EXPECT_NE(load.warnings.front().find(p.string()), std::string::npos);
    EXPECT_NE(load.warnings.front().find("1x1 is not 2:1"), std::string::npos)
        << load.warnings.front();
    ASSERT_TRUE(load.image.valid());
    EXPECT_EQ(load.image.rgba[0], 0.25f);
    // The smallest cube, built without a validation message, lights like a uniform one.
    EnvironmentGuard guard{renderer()};
    renderer().set_environment(&load.image);
    EXPECT_EQ(renderer().resident().environment.cube_size, 16u); // the smallest cube made
}

TEST_F(EnvironmentTest, NonFiniteTexelsAreCountedAndReadAsBlack) {
    const fs::path p = fs::temp_directory_path() / "sherpa_env_test_nan.exr";
    {
        const int w = 16, h = 8;
        std::vector<float> px(std::size_t(w) * h * 3, 0.5f);
        px[0] = std::nanf("");
        px[4] = INFINITY;
        px[8] = -INFINITY;
        auto out = OIIO::ImageOutput::create(p.string());
        ASSERT_TRUE(out);
        const OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
        ASSERT_TRUE(out->open(p.string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        out->close();
    }
    const render::EnvironmentLoad load = render::load_environment(p.string());
    EXPECT_FALSE(load.fallback);
    ASSERT_FALSE(load.warnings.empty());
    EXPECT_NE(load.warnings.front().find("3 texel channels are NaN or infinite"), std::string::npos)
        << load.warnings.front();
    for (float v : load.image.rgba) EXPECT_TRUE(std::isfinite(v));
    EXPECT_EQ(load.image.rgba[0], 0.0f);
    // The GPU build takes it without a validation message.
    EnvironmentGuard guard{renderer()};
    renderer().set_environment(&load.image);
    EXPECT_TRUE(renderer().resident().environment.present);
}

} // namespace
} // namespace sherpa::test
