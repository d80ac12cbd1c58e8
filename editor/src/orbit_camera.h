#pragma once
// The viewport camera: orbit/pan/dolly around a target, or fly (first person).
// Plain math, no Qt, so the tests can drive it directly. Produces the engine's
// camera string convention (sherpa::CameraSpec, reverse-Z, looking down -Z).
#include <glm/glm.hpp>

#include <sherpa/core/aabb.h>
#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene.h>

namespace sherpa::editor {

class OrbitCamera {
public:
    // Orbit by screen deltas in pixels; 0.3 degrees per pixel.
    void orbit(float dx_pixels, float dy_pixels);
    // Pans so the point under the cursor follows it (viewport height in pixels).
    void pan(float dx_pixels, float dy_pixels, float viewport_height);
    // Dolly towards the target; positive steps move closer (one wheel notch = 1).
    void dolly(float steps);
    // Fly: moves eye and target together along the view axes (world units).
    void fly(glm::vec3 right_up_forward);
    // Fly look: turns in place (eye fixed), same sensitivity as orbit.
    void look(float dx_pixels, float dy_pixels);

    // Frames a box so it fills the view, keeping the viewing direction (Frame
    // selection): the engine's framing (sherpa/scene/framing.h) along it.
    void frame(const Aabb& box);
    // The engine's automatic view of the scene (on load and Frame all: frame_scene(),
    // its drawn vertices seen from the side of its first camera), exactly what
    // `sherpa-cli render --camera auto` shows at the same aspect and field of view.
    void frameAuto(const Scene& scene);
    // Takes a glTF camera's pose and field of view.
    void jumpTo(const Scene& scene, std::size_t placed_camera);

    void setAspect(float aspect) { aspect_ = aspect > 0.0f ? aspect : 1.0f; }
    glm::vec3 eye() const;
    glm::vec3 forward() const; // unit, eye -> target
    glm::vec3 target() const { return target_; }
    float distance() const { return distance_; }
    float fovDegrees() const { return fov_degrees_; }
    CameraSpec spec() const;
    // World-space ray through a point in normalised device coordinates (x right, y up).
    void ray(glm::vec2 ndc, glm::vec3& origin, glm::vec3& direction) const;
    // The camera string (camera_spec.h) for --camera and settings.
    std::string toString() const;

private:
    FramingOptions framingOptions() const;
    // Orbits about the framed target, from the framed eye.
    void take(const CameraSpec& framed);

    glm::vec3 target_{0.0f};
    float distance_ = 5.0f;
    float yaw_ = 0.6f, pitch_ = 0.35f; // radians; yaw about +Y, pitch above the horizon
    float fov_degrees_ = 60.0f;
    float aspect_ = 16.0f / 9.0f;
    float near_ = 0.05f;
};

} // namespace sherpa::editor
