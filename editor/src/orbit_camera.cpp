#include "orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sherpa::editor {

namespace {
constexpr float kRadiansPerPixel = 0.3f * 3.14159265f / 180.0f;
constexpr float kPitchLimit = 1.55f; // just short of straight up/down: keeps `up` valid
} // namespace

glm::vec3 OrbitCamera::forward() const {
    // yaw 0 looks down -Z (glTF's default camera), pitch > 0 looks down onto the target.
    return glm::normalize(glm::vec3(-std::sin(yaw_) * std::cos(pitch_), -std::sin(pitch_),
                                    -std::cos(yaw_) * std::cos(pitch_)));
}

glm::vec3 OrbitCamera::eye() const {
    return target_ - forward() * distance_;
}

void OrbitCamera::orbit(float dx, float dy) {
    yaw_ -= dx * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ + dy * kRadiansPerPixel, -kPitchLimit, kPitchLimit);
}

void OrbitCamera::look(float dx, float dy) {
    const glm::vec3 e = eye();
    orbit(-dx, -dy);
    target_ = e + forward() * distance_;
}

void OrbitCamera::pan(float dx, float dy, float viewport_height) {
    const glm::vec3 f = forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, f);
    // World units per pixel at the target's depth.
    const float scale = 2.0f * distance_ * std::tan(glm::radians(fov_degrees_) * 0.5f) /
                        std::max(viewport_height, 1.0f);
    target_ += (-dx * right + dy * up) * scale;
}

void OrbitCamera::dolly(float steps) {
    distance_ = std::max(distance_ * std::pow(0.85f, steps), 1e-4f);
}

void OrbitCamera::fly(glm::vec3 ruf) {
    const glm::vec3 f = forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, f);
    target_ += ruf.x * right + ruf.y * up + ruf.z * f;
}

FramingOptions OrbitCamera::framingOptions() const {
    FramingOptions options;
    options.fov_y_degrees = fov_degrees_;
    options.aspect = aspect_;
    return options;
}

void OrbitCamera::take(const CameraSpec& framed) {
    const glm::vec3 to_target = framed.target - framed.eye;
    target_ = framed.target;
    distance_ = std::max(glm::length(to_target), 1e-6f);
    const glm::vec3 f = to_target / distance_;
    pitch_ = std::clamp(std::asin(std::clamp(-f.y, -1.0f, 1.0f)), -kPitchLimit, kPitchLimit);
    yaw_ = std::atan2(-f.x, -f.z);
    near_ = framed.near_plane;
}

void OrbitCamera::frame(const Aabb& box) {
    if (box.valid()) take(frame_box_along(box, -forward(), framingOptions()));
}

void OrbitCamera::frameAuto(const Scene& scene) {
    take(frame_scene(scene, nullptr, framingOptions()));
}

void OrbitCamera::jumpTo(const Scene& scene, std::size_t index) {
    if (index >= scene.placed_cameras.size()) return;
    const PlacedCamera& placed = scene.placed_cameras[index];
    const Camera& cam = scene.cameras[placed.camera];
    const glm::vec3 e = glm::vec3(placed.world[3]);
    const glm::vec3 f = glm::normalize(-glm::vec3(placed.world[2]));
    // Orbit about a point in front of the camera at the scene's distance.
    distance_ =
        scene.bounds.valid() ? std::max(glm::length(scene.bounds.center() - e), 0.1f) : 5.0f;
    pitch_ = std::asin(std::clamp(-f.y, -1.0f, 1.0f));
    yaw_ = std::atan2(-f.x, -f.z);
    target_ = e + forward() * distance_;
    if (cam.type == CameraType::Perspective) fov_degrees_ = glm::degrees(cam.yfov);
    near_ = std::max(cam.znear, 1e-4f);
}

CameraSpec OrbitCamera::spec() const {
    CameraSpec s;
    s.eye = eye();
    s.target = target_;
    s.up = {0.0f, 1.0f, 0.0f};
    s.fov_y_degrees = fov_degrees_;
    s.aspect = aspect_;
    s.near_plane = near_;
    s.far_plane = 0.0f;
    return s;
}

void OrbitCamera::ray(glm::vec2 ndc, glm::vec3& origin, glm::vec3& direction) const {
    const glm::vec3 f = forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, f);
    const float t = std::tan(glm::radians(fov_degrees_) * 0.5f);
    origin = eye();
    direction = glm::normalize(f + right * (ndc.x * t * aspect_) + up * (ndc.y * t));
}

std::string OrbitCamera::toString() const {
    const glm::vec3 e = eye();
    char buf[256];
    std::snprintf(buf, sizeof buf, "eye=%g,%g,%g:target=%g,%g,%g:fov=%g:near=%g", e.x, e.y, e.z,
                  target_.x, target_.y, target_.z, fov_degrees_, near_);
    return buf;
}

} // namespace sherpa::editor
