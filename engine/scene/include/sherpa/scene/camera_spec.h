#pragma once
// The camera string used everywhere (CLI render/cull, editor):
//   eye=x,y,z:target=x,y,z[:up=x,y,z][:fov=DEG][:aspect=A][:near=N][:far=F]
// Defaults: up +Y, 60 degree vertical fov, aspect 16/9, near 0.05, far infinite.
//
// Convention (written down once, used by every layer): right-handed view space
// looking down -Z; Vulkan clip space with depth in [0, 1] and REVERSE-Z (near plane
// at depth 1, far plane or infinity at depth 0); NDC +Y up (the renderer flips Y with
// a negative viewport height).
#include <string>
#include <string_view>

#include <glm/glm.hpp>

namespace sherpa::scene {

struct CameraSpec {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_y_degrees = 60.0f;
    float aspect = 16.0f / 9.0f;
    bool aspect_given = false; // the string named an aspect (else a viewport may supply its own)
    float near_plane = 0.05f;
    float far_plane = 0.0f; // 0 = infinite

    glm::mat4 view() const;
    glm::mat4 projection() const;
    glm::mat4 view_projection() const { return projection() * view(); }
};

// Parses the camera string. Returns false and fills `error` on malformed input,
// missing eye/target, non-finite values, eye == target, up parallel to the view
// direction, fov outside (0, 180), aspect <= 0, near <= 0 or far <= near.
bool parse_camera_spec(std::string_view text, CameraSpec& out, std::string& error);

// Reverse-Z perspective (infinite when far <= 0) in the convention above.
glm::mat4 perspective_reverse_z(float fov_y_radians, float aspect, float near_plane,
                                float far_plane);
// Reverse-Z orthographic box: x in [-xmag, xmag], y in [-ymag, ymag], view depth [near, far].
glm::mat4 orthographic_reverse_z(float xmag, float ymag, float near_plane, float far_plane);

} // namespace sherpa::scene
