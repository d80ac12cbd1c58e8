#pragma once
// The viewport camera's state: a target, a distance and a direction (yaw, pitch)
// with the lens (field of view, aspect, near plane). Plain math, no Qt: the engine's
// camera (sherpa::scene::CameraSpec, reverse-Z, looking down -Z), rays through the image and
// the camera string. OrbitCamera maps the user's input onto it.
#include <glm/glm.hpp>

#include <cstddef>
#include <string>

#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/scene.h>

namespace sherpa::editor {

struct OrbitPose {
    // Just short of straight up or down: keeps the view's `up` valid.
    static constexpr float kPitchLimit = 1.55f;

    glm::vec3 target{0.0f};
    float distance = 5.0f;
    float yaw = 0.6f, pitch = 0.35f; // radians; yaw about +Y, pitch above the horizon
    float fov_degrees = 60.0f;
    float aspect = 16.0f / 9.0f;
    float near_plane = 0.05f;

    glm::vec3 forward() const; // unit, eye -> target; yaw 0 looks down -Z
    glm::vec3 eye() const { return target - forward() * distance; }
    // The view's right and up axes (unit; up is +Y's part across the view).
    void axes(glm::vec3& right, glm::vec3& up) const;
    scene::CameraSpec spec() const;
    // World-space ray through a point in normalised device coordinates (x right, y up).
    void ray(glm::vec2 ndc, glm::vec3& origin, glm::vec3& direction) const;
    // The camera string (camera_spec.h) for --camera and settings.
    std::string toString() const;
};

// The pose that looks from `framed.eye` at `framed.target` (about which it then
// orbits), with `framed`'s near plane and `lens`' field of view and aspect.
OrbitPose orbit_pose_from(const scene::CameraSpec& framed, const OrbitPose& lens);
// The pose of the glTF camera `placed_camera` of `scene` (its eye, direction, field
// of view and near plane), orbiting about a point in front of it at the scene's
// distance; `current` where the index is out of range.
OrbitPose orbit_pose_at_camera(const scene::Scene& scene, std::size_t placed_camera,
                               const OrbitPose& current);

} // namespace sherpa::editor
