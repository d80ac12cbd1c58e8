// Automatic framing (`--camera auto`) fits what is drawn: the posed vertices at the
// time shown, without the built-in ground plane; a file with cameras says how to look
// through them.
#include "cli/cli_run.h"
#include "reference/reference_images.h"
#include "test_support.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

namespace {

namespace test = sherpa::test;

struct Fill {
    double smaller_side = 0; // the object's extent along the viewport's smaller side, 0..1
    bool touches_border = false;
};

// Pixels unlike the background (the corner pixel: a solid magenta, not the
// environment, which varies over the image) bound the object on screen.
Fill measure_fill(const test::ReferenceImage& img) {
    const std::uint8_t* bg = img.texel(0, 0);
    std::uint32_t x0 = img.width, y0 = img.height, x1 = 0, y1 = 0;
    for (std::uint32_t y = 0; y < img.height; ++y)
        for (std::uint32_t x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.texel(x, y);
            if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) <= 6)
                continue;
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    Fill f;
    if (x1 < x0) return f;
    const bool wide = img.width >= img.height;
    f.smaller_side = wide ? double(y1 - y0 + 1) / img.height : double(x1 - x0 + 1) / img.width;
    f.touches_border = x0 == 0 || y0 == 0 || x1 + 1 == img.width || y1 + 1 == img.height;
    return f;
}

Fill render_fill(const std::string& scene, const std::string& options, std::string* out = nullptr) {
    const std::string png = (std::filesystem::temp_directory_path() /
                             ("sherpa_framing_" + std::to_string(getpid()) + ".png"))
                                .string();
    const test::CliRun r =
        test::run_cli("render '" + scene + "' -o " + png +
                      " --width 192 --height 128 --no-shadows --background 1,0,1 --cache-dir '" +
                      SHERPA_TEST_TEXTURE_CACHE + "' " + options);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    if (out) *out = r.out;
    test::ReferenceImage img;
    std::string error;
    EXPECT_TRUE(test::read_png_reference(png, img, error)) << error;
    std::filesystem::remove(png);
    return measure_fill(img);
}

} // namespace

// The whole model stays in view. (The goal is ~80% of the smaller side; fitting the
// bounding box's corners gives 0.49-0.59 here: Duck, BoxTextured, Suzanne,
// 2CylinderEngine at 192x128. Fitting the drawn vertices themselves is not done yet.)
TEST(CliFraming, AutoKeepsTheWholeModelInView) {
    for (const char* model : {"Duck", "BoxTextured", "Suzanne", "2CylinderEngine"}) {
        const Fill f = render_fill(test::gltf_asset(model), "");
        EXPECT_GE(f.smaller_side, 0.45) << model;
        EXPECT_LE(f.smaller_side, 0.95) << model;
        EXPECT_FALSE(f.touches_border) << model;
    }
}

// RiggedSimple's animation bends it: framed at --time T, the posed model fills the
// view as tightly as a static one, and the camera differs from the default pose's.
TEST(CliFraming, AutoFramesThePoseDrawn) {
    const std::string rigged = test::gltf_asset("RiggedSimple");
    for (const char* time : {"0.5", "2"}) {
        const Fill f = render_fill(rigged, std::string("--time ") + time);
        EXPECT_GE(f.smaller_side, 0.7) << time;
        EXPECT_LE(f.smaller_side, 0.95) << time;
        EXPECT_FALSE(f.touches_border) << time;
    }
    const sherpa::LoadResult r = sherpa::load_scene(rigged);
    ASSERT_TRUE(r) << r.error;
    const sherpa::Pose pose = sherpa::evaluate_pose(*r.scene, 0, 2.0);
    const sherpa::Aabb posed = sherpa::framing_bounds(*r.scene, &pose);
    const sherpa::Aabb exact = sherpa::posed_scene_bounds(*r.scene, pose).exact;
    EXPECT_EQ(posed.min, exact.min);
    EXPECT_EQ(posed.max, exact.max);
}

// The built-in scene's 40 m ground plane is a stage: framing fits the objects on it.
TEST(CliFraming, GroundPlaneDoesNotCount) {
    const sherpa::LoadResult r = sherpa::load_scene("builtin:default");
    ASSERT_TRUE(r) << r.error;
    const sherpa::Aabb framed = sherpa::framing_bounds(*r.scene);
    ASSERT_TRUE(framed.valid());
    EXPECT_GT(r.scene->bounds.extent().x, 39.0f);
    // The objects and the instance grid behind them: about 9.5 x 15 m.
    EXPECT_LT(framed.extent().x, 12.0f);
    EXPECT_LT(framed.extent().z, 20.0f);
    EXPECT_GT(framed.extent().x, 8.0f);
}

// Framed automatically, a file with cameras says how to use them; gltf:N uses them.
TEST(CliFraming, FileCamerasAreOffered) {
    std::string out;
    render_fill(test::gltf_asset("Cameras"), "", &out);
    EXPECT_NE(out.find("note: the file places 2 camera(s) (gltf:0"), std::string::npos) << out;
    EXPECT_NE(out.find("--camera gltf:N looks through camera N"), std::string::npos) << out;
    render_fill(test::gltf_asset("Cameras"), "--camera gltf:1", &out);
    EXPECT_EQ(out.find("note: the file places"), std::string::npos) << out;
}
