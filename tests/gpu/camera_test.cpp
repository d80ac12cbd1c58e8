// Camera specs, reverse-Z projections and auto-framing (no GPU needed).
#include <gtest/gtest.h>

#include <sherpa/render/camera.h>

namespace sherpa::test {
namespace camera_test {

using render::CameraSpec;

TEST(CameraSpecTest, ParsesAutoGltfAndExplicit) {
    CameraSpec s;
    std::string error;
    ASSERT_TRUE(render::parse_camera_spec("auto", s, error));
    EXPECT_EQ(s.kind, CameraSpec::Kind::Auto);
    ASSERT_TRUE(render::parse_camera_spec("gltf:2", s, error));
    EXPECT_EQ(s.kind, CameraSpec::Kind::Gltf);
    EXPECT_EQ(s.gltf_index, 2u);
    ASSERT_TRUE(render::parse_camera_spec("eye=1,2,3:target=0,0.5,0", s, error)) << error;
    EXPECT_EQ(s.kind, CameraSpec::Kind::Explicit);
    EXPECT_EQ(s.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(s.target, glm::vec3(0, 0.5f, 0));
    EXPECT_EQ(s.up, glm::vec3(0, 1, 0)); // defaults
    EXPECT_FLOAT_EQ(s.fov_degrees, 60.0f);
    EXPECT_FLOAT_EQ(s.near_plane, 0.05f);
    EXPECT_FLOAT_EQ(s.far_plane, 0.0f);
    ASSERT_TRUE(render::parse_camera_spec(
        "eye=0,0,5:target=0,0,0:up=1,0,0:fov=35:aspect=2:near=0.1:far=100", s, error))
        << error;
    EXPECT_EQ(s.up, glm::vec3(1, 0, 0));
    EXPECT_FLOAT_EQ(s.fov_degrees, 35.0f);
    EXPECT_FLOAT_EQ(s.aspect, 2.0f);
    EXPECT_FLOAT_EQ(s.far_plane, 100.0f);
}

TEST(CameraSpecTest, RejectsMalformedSpecsWithAReason) {
    CameraSpec s;
    for (const char* bad :
         {"eye=1,2:target=0,0,0", "eye=0,0,1", "gltf:", "gltf:x", "eye=0,0,1:target=0,0,1",
          "eye=0,0,1:target=0,0,0:fov=0", "eye=0,0,1:target=0,0,0:bogus=1",
          "eye=0,0,1:target=0,0,0:near=1:far=0.5", "eye=0,1,0:target=0,0,0"}) {
        std::string error;
        EXPECT_FALSE(render::parse_camera_spec(bad, s, error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
    }
}

TEST(ReverseZTest, NearMapsToOneAndInfinityToZero) {
    const glm::mat4 p = render::reverse_z_perspective(glm::radians(60.0f), 1.5f, 0.1f, 0.0f);
    auto depth = [&](float z) {
        const glm::vec4 c = p * glm::vec4(0, 0, z, 1);
        return c.z / c.w;
    };
    EXPECT_NEAR(depth(-0.1f), 1.0f, 1e-6f);
    EXPECT_NEAR(depth(-1e7f), 0.0f, 1e-6f);
    EXPECT_GT(depth(-1.0f), depth(-2.0f)); // nearer is larger
    const glm::mat4 f = render::reverse_z_perspective(glm::radians(60.0f), 1.5f, 0.1f, 10.0f);
    const glm::vec4 far_point = f * glm::vec4(0, 0, -10.0f, 1);
    EXPECT_NEAR(far_point.z / far_point.w, 0.0f, 1e-6f);
}

TEST(AutoFrameTest, EveryBoundsCornerIsInsideTheFrustum) {
    scene::Scene scene;
    scene.bounds = core::Aabb::from_min_max(glm::vec3(-3, 0, -1), glm::vec3(5, 2, 1));
    const render::CameraView v = render::resolve_camera(CameraSpec{}, scene, 16.0f / 9.0f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p{(i & 1) ? 5.0f : -3.0f, (i & 2) ? 2.0f : 0.0f, (i & 4) ? 1.0f : -1.0f};
        const glm::vec4 c = v.proj * v.view * glm::vec4(p, 1.0f);
        EXPECT_LE(std::abs(c.x / c.w), 1.0f) << i;
        EXPECT_LE(std::abs(c.y / c.w), 1.0f) << i;
        EXPECT_GT(c.z / c.w, 0.0f) << i;
        EXPECT_LE(c.z / c.w, 1.0f) << i;
    }
}

TEST(GltfCameraTest, UnknownIndexIsAnError) {
    scene::Scene scene;
    CameraSpec s;
    s.kind = CameraSpec::Kind::Gltf;
    s.gltf_index = 0;
    EXPECT_THROW(render::resolve_camera(s, scene, 1.0f), std::invalid_argument);
}

} // namespace camera_test
} // namespace sherpa::test
