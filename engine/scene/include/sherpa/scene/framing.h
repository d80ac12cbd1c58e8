#pragma once
// Framing a box: where a camera looks from so that the whole box is in view. One
// function for every caller (`--camera auto` in the CLI and tests, the editor on
// load, "Frame all" and "Frame selection"), so that a scene looks the same in both.
// Math over the box; framing_bounds() says which box: what is drawn.
#include <sherpa/core/aabb.h>
#include <sherpa/scene/camera_spec.h>

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace sherpa::scene {

struct Scene;
struct Pose;

struct FramingOptions {
    float fov_y_degrees = 60.0f; // vertical field of view, in (0, 180)
    float aspect = 16.0f / 9.0f; // width / height of the viewport, > 0
    // Kept free around the box, as a fraction of its bounding radius: the eye stays at
    // least this far outside the box and every corner at least this far in front of
    // it; and as a fraction of the half field of view, left as a border on screen.
    float margin = 0.05f;
    // frame_points_along(): the fraction of the viewport's width and height the points
    // may span; the tighter axis is filled to it exactly, the other centred.
    float fill = 0.8f;
};

// Elevation and azimuth of the automatic view: looking down ~25 degrees, ~35 degrees
// round from the front, so that a box shows its top and two sides.
inline constexpr float kFramingElevationDegrees = 25.0f;
inline constexpr float kFramingAzimuthDegrees = 35.0f;

// Unit direction from the box's centre towards the eye for the automatic view. The
// front is `front_hint`'s horizontal part where it has one; otherwise the horizontal
// axis (+X or +Z) along which the box is clearly thinner (a character stands wider
// across its shoulders than deep; a panel is thinnest along its normal), +Z on a tie.
glm::vec3 auto_view_direction(const core::Aabb& box, glm::vec3 front_hint = glm::vec3(0.0f));

// Camera at `box`'s centre, looking from `to_eye` (any length > 0; towards the eye),
// backed off until all 8 corners lie inside the frustum of `options` (with the
// screen border), every corner is in front of the eye by the margin, and the eye is
// outside the box by the margin; when the view looks down (or up) by more than ~12
// degrees it also stays above the box's top (below its bottom), so the top is seen.
// Up is +Y (-Z when looking straight down or up); far is infinite. An invalid box
// frames the unit cube around the origin.
CameraSpec frame_box_along(const core::Aabb& box, glm::vec3 to_eye, const FramingOptions& options);

// The automatic view: frame_box_along(box, auto_view_direction(box, front_hint), options).
CameraSpec frame_box(const core::Aabb& box, const FramingOptions& options,
                     glm::vec3 front_hint = glm::vec3(0.0f));

// Camera looking from `to_eye` (any length > 0) that fits `points` (non-finite ones
// ignored) tightly: their perspective projection spans `options.fill` of the
// viewport's width or height, whichever is tighter, centred on the other axis (the
// target is moved across the view to centre them, not fixed on the box's centre),
// and every point lies at least options.margin x their bounding radius in front of
// the eye. For fixed orientation the distance is closed-form per axis (the least d
// with max(x + t z) - t d <= min(x - t z) + t d over the points: x across, z towards
// the eye, t the half-angle tangent times `fill`); the sideways offsets that centre
// the points' projection are found by bisection (O(points) per step).
// No finite points: frame_box_along() of the unit cube.
CameraSpec frame_points_along(std::span<const glm::vec3> points, glm::vec3 to_eye,
                              const FramingOptions& options);

// The box automatic framing fits: the world bounds of what is drawn, in `pose` when
// one is given (exact: every posed vertex, as `info --time` reports them) else as
// loaded; without Scene::backdrop_nodes (the built-in ground plane), unless nothing
// else is drawn. Invalid when nothing is drawn.
core::Aabb framing_bounds(const Scene& scene, const Pose* pose = nullptr);

// The world positions of the same vertices (every instance, instancing rows
// included), posed in `pose` when given; non-finite ones left out.
std::vector<glm::vec3> framing_points(const Scene& scene, const Pose* pose = nullptr);

// The front automatic framing looks from: towards the file's first placed camera
// (its horizontal direction from `drawn`'s centre, else the horizontal part of the
// direction it looks back along), so that a file that places a camera is seen from
// the side its author chose; zero (no hint) when the file places none.
glm::vec3 framing_front_hint(const Scene& scene, const core::Aabb& drawn);

// The automatic view of a scene (CLI `--camera auto`, the editor on load and on Frame
// all): frame_points_along(framing_points(), auto_view_direction(framing_bounds(),
// framing_front_hint()), options). Falls back to frame_box(scene.bounds) when
// nothing is drawn.
CameraSpec frame_scene(const Scene& scene, const Pose* pose, const FramingOptions& options);

} // namespace sherpa::scene
