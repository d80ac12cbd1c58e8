#include "orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace sherpa::editor {

namespace {
constexpr float kRadiansPerPixel = 0.3f * 3.14159265f / 180.0f;
} // namespace

void OrbitCamera::orbit(float dx, float dy) {
    pose_.yaw -= dx * kRadiansPerPixel;
    pose_.pitch = std::clamp(pose_.pitch + dy * kRadiansPerPixel, -OrbitPose::kPitchLimit,
                             OrbitPose::kPitchLimit);
}

void OrbitCamera::look(float dx, float dy) {
    const glm::vec3 e = pose_.eye();
    orbit(-dx, -dy);
    pose_.target = e + pose_.forward() * pose_.distance;
}

void OrbitCamera::pan(float dx, float dy, float viewport_height) {
    glm::vec3 right, up;
    pose_.axes(right, up);
    // World units per pixel at the target's depth.
    const float scale = 2.0f * pose_.distance * std::tan(glm::radians(pose_.fov_degrees) * 0.5f) /
                        std::max(viewport_height, 1.0f);
    pose_.target += (-dx * right + dy * up) * scale;
}

void OrbitCamera::dolly(float steps) {
    pose_.distance = std::max(pose_.distance * std::pow(0.85f, steps), 1e-4f);
}

void OrbitCamera::fly(glm::vec3 ruf) {
    glm::vec3 right, up;
    pose_.axes(right, up);
    pose_.target += ruf.x * right + ruf.y * up + ruf.z * pose_.forward();
}

scene::FramingOptions OrbitCamera::framingOptions() const {
    scene::FramingOptions options;
    options.fov_y_degrees = pose_.fov_degrees;
    options.aspect = pose_.aspect;
    return options;
}

void OrbitCamera::frame(const core::Aabb& box) {
    if (box.valid())
        pose_ =
            orbit_pose_from(scene::frame_box_along(box, -pose_.forward(), framingOptions()), pose_);
}

void OrbitCamera::frameAuto(const scene::Scene& scene) {
    pose_ = orbit_pose_from(scene::frame_scene(scene, nullptr, framingOptions()), pose_);
}

void OrbitCamera::jumpTo(const scene::Scene& scene, std::size_t index) {
    pose_ = orbit_pose_at_camera(scene, index, pose_);
}

} // namespace sherpa::editor
