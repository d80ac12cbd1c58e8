#include "orbit_pose.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sherpa::editor {

glm::vec3 OrbitPose::forward() const {
    // yaw 0 looks down -Z (glTF's default camera), pitch > 0 looks down onto the target.
    return glm::normalize(glm::vec3(-std::sin(yaw) * std::cos(pitch), -std::sin(pitch),
                                    -std::cos(yaw) * std::cos(pitch)));
}

void OrbitPose::axes(glm::vec3& right, glm::vec3& up) const {
    const glm::vec3 f = forward();
    right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
    up = glm::cross(right, f);
}

scene::CameraSpec OrbitPose::spec() const {
    scene::CameraSpec s;
    s.eye = eye();
    s.target = target;
    s.up = {0.0f, 1.0f, 0.0f};
    s.fov_y_degrees = fov_degrees;
    s.aspect = aspect;
    s.near_plane = near_plane;
    s.far_plane = 0.0f;
    return s;
}

void OrbitPose::ray(glm::vec2 ndc, glm::vec3& origin, glm::vec3& direction) const {
    glm::vec3 right, up;
    axes(right, up);
    const float t = std::tan(glm::radians(fov_degrees) * 0.5f);
    origin = eye();
    direction = glm::normalize(forward() + right * (ndc.x * t * aspect) + up * (ndc.y * t));
}

std::string OrbitPose::toString() const {
    const glm::vec3 e = eye();
    char buf[256];
    std::snprintf(buf, sizeof buf, "eye=%g,%g,%g:target=%g,%g,%g:fov=%g:near=%g", e.x, e.y, e.z,
                  target.x, target.y, target.z, fov_degrees, near_plane);
    return buf;
}

OrbitPose orbit_pose_from(const scene::CameraSpec& framed, const OrbitPose& lens) {
    OrbitPose pose = lens;
    const glm::vec3 to_target = framed.target - framed.eye;
    pose.target = framed.target;
    pose.distance = std::max(glm::length(to_target), 1e-6f);
    const glm::vec3 f = to_target / pose.distance;
    pose.pitch = std::clamp(std::asin(std::clamp(-f.y, -1.0f, 1.0f)), -OrbitPose::kPitchLimit,
                            OrbitPose::kPitchLimit);
    pose.yaw = std::atan2(-f.x, -f.z);
    pose.near_plane = framed.near_plane;
    return pose;
}

OrbitPose orbit_pose_at_camera(const scene::Scene& scene, std::size_t index,
                               const OrbitPose& current) {
    if (index >= scene.placed_cameras.size()) return current;
    OrbitPose pose = current;
    const scene::PlacedCamera& placed = scene.placed_cameras[index];
    const scene::Camera& cam = scene.cameras[placed.camera];
    const glm::vec3 e = glm::vec3(placed.world[3]);
    const glm::vec3 f = glm::normalize(-glm::vec3(placed.world[2]));
    // Orbit about a point in front of the camera at the scene's distance.
    pose.distance =
        scene.bounds.valid() ? std::max(glm::length(scene.bounds.center() - e), 0.1f) : 5.0f;
    pose.pitch = std::asin(std::clamp(-f.y, -1.0f, 1.0f));
    pose.yaw = std::atan2(-f.x, -f.z);
    pose.target = e + pose.forward() * pose.distance;
    if (cam.type == scene::CameraType::Perspective) pose.fov_degrees = glm::degrees(cam.yfov);
    pose.near_plane = std::max(cam.znear, 1e-4f);
    return pose;
}

} // namespace sherpa::editor
