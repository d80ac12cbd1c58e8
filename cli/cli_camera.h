#pragma once
// The cameras of `render` and `cull`: automatic framing of what is drawn, and what
// they say when they frame a file that places cameras of its own.
#include <sherpa/render/camera.h>
#include <sherpa/scene/animation.h>
#include <sherpa/scene/framing.h>
#include <sherpa/scene/scene.h>

#include <string>

namespace sherpa::cli {

// Empty unless `camera` is auto and the displayed scene places cameras.
inline std::string file_camera_hint(const scene::Scene& scene, const render::CameraSpec& camera) {
    if (camera.kind != render::CameraSpec::Kind::Auto || scene.placed_cameras.empty()) return {};
    std::string names;
    for (std::size_t i = 0; i < scene.placed_cameras.size() && i < 4; ++i) {
        const std::uint32_t c = scene.placed_cameras[i].camera;
        const std::string name = c < scene.cameras.size() ? scene.cameras[c].name : "";
        names += (i ? ", " : "") + std::string("gltf:") + std::to_string(i) +
                 (name.empty() ? "" : " '" + name + "'");
    }
    if (scene.placed_cameras.size() > 4) names += ", ...";
    return "the file places " + std::to_string(scene.placed_cameras.size()) + " camera(s) (" +
           names + "): framed automatically; --camera gltf:N looks through camera N";
}

// `camera` when it is not auto; else the camera that frames what is drawn
// (frame_scene(): the drawn vertices, posed in `pose` when given, the built-in ground
// plane left out, seen from the side of the file's first camera) for a viewport of
// `aspect`, with the renderer's framing options.
inline render::CameraSpec framed_camera(const render::CameraSpec& camera, const scene::Scene& scene,
                                        const scene::Pose* pose, float aspect) {
    if (camera.kind != render::CameraSpec::Kind::Auto) return camera;
    scene::FramingOptions options;
    options.fov_y_degrees = camera.fov_degrees;
    options.aspect = aspect;
    return render::explicit_camera(scene::frame_scene(scene, pose, options));
}

} // namespace sherpa::cli
