#pragma once
// Cameras for rendering: auto-framing of the scene bounds, the glTF cameras, or an
// explicit spec string used the same way everywhere (CLI, tests, editor):
//   auto | gltf:N | eye=x,y,z:target=x,y,z[:up=x,y,z][:fov=DEG][:aspect=A][:near=N][:far=F]
// Defaults: up +Y, 60 degree vertical fov, near 0.05, far infinite.
//
// Depth convention: reverse-Z. Clip depth is 1 at the near plane and falls to 0 at
// the far plane (0 at infinity for the default infinite far plane). Depth buffers
// clear to 0 and test with GREATER. Clip space is right-handed (camera looks down
// -Z, +Y up); the viewport is flipped (negative height) so +Y is up on screen and
// glTF's counter-clockwise front faces stay counter-clockwise.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/scene.h>
#include <sherpa/scene/shadow_cascades.h>

namespace sherpa::render {

struct CameraSpec {
    enum class Kind { Auto, Gltf, Explicit } kind = Kind::Auto;
    std::uint32_t gltf_index = 0; // index into Scene::placed_cameras
    glm::vec3 eye{0.0f, 0.0f, 3.0f}, target{0.0f}, up{0.0f, 1.0f, 0.0f};
    float fov_degrees = 60.0f;
    float aspect = 0.0f; // 0: the viewport's
    float near_plane = 0.05f;
    float far_plane = 0.0f; // 0: infinite
};

// The renderer's camera for an explicit scene-layer camera (what the camera string
// parses to, or an editor's orbit camera); its aspect only where one was given.
CameraSpec explicit_camera(const sherpa::scene::CameraSpec& camera);

// Parses a spec string; on failure returns false and names the problem in `error`.
bool parse_camera_spec(std::string_view text, CameraSpec& spec, std::string& error);

struct CameraView {
    glm::mat4 view{1.0f}, proj{1.0f};
    glm::vec3 position{0.0f};
    float near_plane = 0.05f, far_plane = 0.0f; // far 0: infinite
    float fov_y = 1.0471976f, aspect = 1.0f;
    bool orthographic = false;
    float ortho_half_width = 1.0f, ortho_half_height = 1.0f;
};

// What the shadow-cascade fit needs of a resolved camera.
scene::CascadeCamera cascade_camera(const CameraView& view);

// What resolving a camera reads of a scene: its bounds (auto framing) and its cameras
// (gltf:N), kept by a renderer between frames without the rest of the Scene.
struct SceneCameras {
    core::Aabb bounds;
    std::vector<scene::Camera> cameras;
    std::vector<scene::PlacedCamera> placed_cameras;
};

// Resolves a spec against a scene for a viewport aspect (width / height). Throws
// std::invalid_argument for a glTF camera index the scene lacks.
CameraView resolve_camera(const CameraSpec& spec, const scene::Scene& scene, float viewport_aspect);
CameraView resolve_camera(const CameraSpec& spec, const SceneCameras& scene, float viewport_aspect);

// Reverse-Z projections (see the convention above); far 0 = infinite.
glm::mat4 reverse_z_perspective(float fov_y, float aspect, float near_plane, float far_plane);
glm::mat4 reverse_z_orthographic(float half_width, float half_height, float near_plane,
                                 float far_plane);

} // namespace sherpa::render
