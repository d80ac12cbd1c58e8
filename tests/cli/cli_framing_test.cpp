// Automatic framing (`--camera auto`) fits what is drawn: the posed vertices at the
// time shown, without the built-in ground plane, to 80% of the tighter side, seen from
// the side of the file's camera; a file with cameras says how to look through them.
#include "cli/cli_run.h"
#include "reference/reference_images.h"
#include "test_support.h"

#include <sherpa/scene/animation.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene_loader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

namespace {

namespace test = sherpa::test;

struct Fill {
    double smaller_side = 0; // the object's extent along the viewport's smaller side, 0..1
    double tighter = 0;      // the larger of its width / image width and height / image height
    bool touches_border = false;
};

// Pixels unlike the background (the corner pixel) bound the object on screen. The
// images are of the normal view, whose background is one colour (a lit frame shows
// the environment behind the model).
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
    const double fx = double(x1 - x0 + 1) / img.width, fy = double(y1 - y0 + 1) / img.height;
    f.smaller_side = wide ? fy : fx;
    f.tighter = std::max(fx, fy);
    f.touches_border = x0 == 0 || y0 == 0 || x1 + 1 == img.width || y1 + 1 == img.height;
    return f;
}

Fill render_fill(const std::string& scene, const std::string& options, std::string* out = nullptr) {
    const std::string png = (std::filesystem::temp_directory_path() /
                             ("sherpa_framing_" + std::to_string(getpid()) + ".png"))
                                .string();
    const test::CliRun r = test::run_cli("render '" + scene + "' -o " + png +
                                         " --width 192 --height 128 --no-shadows --view normal "
                                         "--cache-dir '" +
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

// Automatic framing fits the drawn vertices to 80% of the viewport's width or height,
// whichever is tighter (one or two pixels of rasterisation either way at 192x128);
// fitting the bounding box's corners gave 0.49-0.59 here.
TEST(CliFraming, AutoFillsEightyPercentOfTheTighterSide) {
    for (const char* model : {"Duck", "BoxTextured", "Suzanne", "2CylinderEngine", "DamagedHelmet",
                              "OrientationTest"}) {
        const Fill f = render_fill(test::gltf_asset(model), "");
        std::printf("%-16s fill: %.3f of the tighter side, %.3f of the smaller side\n", model,
                    f.tighter, f.smaller_side);
        EXPECT_GE(f.tighter, 0.77) << model;
        EXPECT_LE(f.tighter, 0.83) << model;
        EXPECT_FALSE(f.touches_border) << model;
    }
}

// RiggedSimple's animation bends it: framed at --time T, the posed model fills the
// view as tightly as a static one, and the posed box is the exact posed bounds.
TEST(CliFraming, AutoFramesThePoseDrawn) {
    const std::string rigged = test::gltf_asset("RiggedSimple");
    for (const char* time : {"0.5", "2"}) {
        const Fill f = render_fill(rigged, std::string("--time ") + time);
        std::printf("RiggedSimple t=%s fill: %.3f of the tighter side, %.3f of the smaller side\n",
                    time, f.tighter, f.smaller_side);
        EXPECT_GE(f.tighter, 0.77) << time;
        EXPECT_LE(f.tighter, 0.83) << time;
        EXPECT_FALSE(f.touches_border) << time;
    }
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(rigged);
    ASSERT_TRUE(r) << r.error;
    const sherpa::scene::Pose pose = sherpa::scene::evaluate_pose(*r.scene, 0, 2.0);
    const sherpa::core::Aabb posed = sherpa::scene::framing_bounds(*r.scene, &pose);
    const sherpa::core::Aabb exact = sherpa::scene::posed_scene_bounds(*r.scene, pose).exact;
    EXPECT_EQ(posed.min, exact.min);
    EXPECT_EQ(posed.max, exact.max);
    sherpa::core::Aabb points;
    for (const glm::vec3& v : sherpa::scene::framing_points(*r.scene, &pose)) points.expand(v);
    EXPECT_EQ(points.min, exact.min);
    EXPECT_EQ(points.max, exact.max);
}

// The Duck's file places a camera behind and to the right of the duck (-Z, +X): the
// automatic view looks from that side (35 degrees round from it), not from +Z.
TEST(CliFraming, AutoLooksFromTheSideOfTheFilesCamera) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene(test::gltf_asset("Duck"));
    ASSERT_TRUE(r) << r.error;
    ASSERT_FALSE(r.scene->placed_cameras.empty());
    const sherpa::core::Aabb drawn = sherpa::scene::framing_bounds(*r.scene);
    const glm::vec3 file_eye = glm::vec3(r.scene->placed_cameras[0].world[3]);
    sherpa::scene::FramingOptions options;
    const sherpa::scene::CameraSpec framed = sherpa::scene::frame_scene(*r.scene, nullptr, options);
    const auto horizontal = [](glm::vec3 v) { return glm::normalize(glm::vec2(v.x, v.z)); };
    const float cosine =
        glm::dot(horizontal(framed.eye - framed.target), horizontal(file_eye - drawn.center()));
    EXPECT_GT(cosine, 0.8f); // cos 35 degrees = 0.819
    EXPECT_LT(file_eye.z, drawn.center().z);
    EXPECT_LT(framed.eye.z, framed.target.z);
}

// The built-in scene's 40 m ground plane is a stage: framing fits the objects on it.
TEST(CliFraming, GroundPlaneDoesNotCount) {
    const sherpa::scene::LoadResult r = sherpa::scene::load_scene("builtin:default");
    ASSERT_TRUE(r) << r.error;
    const sherpa::core::Aabb framed = sherpa::scene::framing_bounds(*r.scene);
    ASSERT_TRUE(framed.valid());
    EXPECT_GT(r.scene->bounds.extent().x, 39.0f);
    // The objects and the instance grid behind them: about 9.5 x 15 m.
    EXPECT_LT(framed.extent().x, 12.0f);
    EXPECT_LT(framed.extent().z, 20.0f);
    EXPECT_GT(framed.extent().x, 8.0f);
    sherpa::core::Aabb points;
    for (const glm::vec3& v : sherpa::scene::framing_points(*r.scene)) points.expand(v);
    EXPECT_LT(points.extent().x, 12.0f);
    EXPECT_GT(points.extent().x, 8.0f);
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
