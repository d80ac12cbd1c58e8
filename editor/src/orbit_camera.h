#pragma once
// The viewport camera's input mapping: mouse, wheel and fly keys turned into moves
// of its OrbitPose (orbit/pan/dolly around a target, or fly first person), and the
// placements the editor asks for (frame a box, the engine's automatic view, a glTF
// camera). No Qt, so the tests can drive it directly.
#include <glm/glm.hpp>

#include <sherpa/core/aabb.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene.h>

#include "orbit_pose.h"

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
    void frame(const core::Aabb& box);
    // The engine's automatic view of the scene (on load and Frame all: frame_scene(),
    // its drawn vertices seen from the side of its first camera), exactly what
    // `sherpa-cli render --camera auto` shows at the same aspect and field of view.
    void frameAuto(const scene::Scene& scene);
    // Takes a glTF camera's pose and field of view.
    void jumpTo(const scene::Scene& scene, std::size_t placed_camera);

    void setAspect(float aspect) { pose_.aspect = aspect > 0.0f ? aspect : 1.0f; }
    const OrbitPose& pose() const { return pose_; }

private:
    scene::FramingOptions framingOptions() const;

    OrbitPose pose_;
};

} // namespace sherpa::editor
