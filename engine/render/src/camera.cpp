#include <sherpa/render/camera.h>
#include <sherpa/scene/camera_spec.h>
#include <sherpa/scene/framing.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace sherpa::render {

bool parse_camera_spec(std::string_view text, CameraSpec& spec, std::string& error) {
    spec = CameraSpec{};
    if (text == "auto" || text.empty()) return true;
    if (text.substr(0, 5) == "gltf:") {
        const std::string_view n = text.substr(5);
        const auto r = std::from_chars(n.data(), n.data() + n.size(), spec.gltf_index);
        if (r.ec != std::errc() || r.ptr != n.data() + n.size() || n.empty()) {
            error = "camera '" + std::string(text) + "': gltf:N needs a camera index";
            return false;
        }
        spec.kind = CameraSpec::Kind::Gltf;
        return true;
    }
    // Explicit cameras: the one parser of the camera string (scene layer).
    sherpa::scene::CameraSpec parsed;
    std::string parse_error;
    if (!sherpa::scene::parse_camera_spec(text, parsed, parse_error)) {
        error = "camera '" + std::string(text) + "': " + parse_error;
        return false;
    }
    spec = explicit_camera(parsed);
    return true;
}

CameraSpec explicit_camera(const sherpa::scene::CameraSpec& camera) {
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::Explicit;
    spec.eye = camera.eye;
    spec.target = camera.target;
    spec.up = camera.up;
    spec.fov_degrees = camera.fov_y_degrees;
    spec.aspect = camera.aspect_given ? camera.aspect : 0.0f; // 0: the viewport's
    spec.near_plane = camera.near_plane;
    spec.far_plane = camera.far_plane;
    return spec;
}

// One convention for the whole engine: the scene layer's (camera_spec.h).
glm::mat4 reverse_z_perspective(float fov_y, float aspect, float n, float f) {
    return scene::perspective_reverse_z(fov_y, aspect, n, f);
}

glm::mat4 reverse_z_orthographic(float hw, float hh, float n, float f) {
    return scene::orthographic_reverse_z(hw, hh, n, f);
}

scene::CascadeCamera cascade_camera(const CameraView& v) {
    scene::CascadeCamera c;
    c.view = v.view;
    c.near_plane = v.near_plane;
    c.far_plane = v.far_plane;
    c.fov_y = v.fov_y;
    c.aspect = v.aspect;
    c.orthographic = v.orthographic;
    c.ortho_half_width = v.ortho_half_width;
    c.ortho_half_height = v.ortho_half_height;
    return c;
}

namespace {

CameraView resolve(const CameraSpec& spec, const core::Aabb& bounds,
                   const std::vector<scene::Camera>& cameras,
                   const std::vector<scene::PlacedCamera>& placed_cameras, float viewport_aspect) {
    CameraView v;
    v.aspect = spec.aspect > 0.0f ? spec.aspect : viewport_aspect;
    switch (spec.kind) {
    case CameraSpec::Kind::Explicit: {
        v.position = spec.eye;
        v.view = glm::lookAtRH(spec.eye, spec.target, spec.up);
        v.fov_y = glm::radians(spec.fov_degrees);
        v.near_plane = spec.near_plane;
        v.far_plane = spec.far_plane;
        break;
    }
    case CameraSpec::Kind::Gltf: {
        if (spec.gltf_index >= placed_cameras.size())
            throw std::invalid_argument("camera gltf:" + std::to_string(spec.gltf_index) +
                                        ": the scene places " +
                                        std::to_string(placed_cameras.size()) + " camera(s)");
        const scene::PlacedCamera& pc = placed_cameras[spec.gltf_index];
        const scene::Camera& cam = cameras.at(pc.camera);
        // The node transform may scale; the view keeps only rotation and position.
        glm::mat4 world = pc.world;
        for (int c = 0; c < 3; ++c) world[c] = glm::vec4(glm::normalize(glm::vec3(world[c])), 0.0f);
        v.view = glm::inverse(world);
        v.position = glm::vec3(pc.world[3]);
        v.near_plane = cam.znear > 0.0f ? cam.znear : 0.05f;
        v.far_plane = cam.zfar;
        if (spec.aspect <= 0.0f && cam.aspect > 0.0f) v.aspect = cam.aspect;
        if (cam.type == scene::CameraType::Orthographic) {
            v.orthographic = true;
            v.ortho_half_height = cam.ymag;
            v.ortho_half_width = cam.ymag * v.aspect; // keep the viewport undistorted
            if (v.far_plane <= v.near_plane) v.far_plane = v.near_plane + 1000.0f;
        } else {
            v.fov_y = cam.yfov;
        }
        break;
    }
    case CameraSpec::Kind::Auto: {
        // The one framing of the engine (scene layer), shared with the editor.
        scene::FramingOptions options;
        options.fov_y_degrees = spec.fov_degrees;
        options.aspect = v.aspect;
        const sherpa::scene::CameraSpec framed = scene::frame_box(bounds, options);
        v.position = framed.eye;
        v.view = framed.view();
        v.fov_y = glm::radians(framed.fov_y_degrees);
        v.near_plane = framed.near_plane;
        v.far_plane = framed.far_plane;
        break;
    }
    }
    v.proj = v.orthographic ? reverse_z_orthographic(v.ortho_half_width, v.ortho_half_height,
                                                     v.near_plane, v.far_plane)
                            : reverse_z_perspective(v.fov_y, v.aspect, v.near_plane, v.far_plane);
    return v;
}

} // namespace

CameraView resolve_camera(const CameraSpec& spec, const scene::Scene& scene,
                          float viewport_aspect) {
    return resolve(spec, scene.bounds, scene.cameras, scene.placed_cameras, viewport_aspect);
}

CameraView resolve_camera(const CameraSpec& spec, const SceneCameras& scene,
                          float viewport_aspect) {
    return resolve(spec, scene.bounds, scene.cameras, scene.placed_cameras, viewport_aspect);
}

} // namespace sherpa::render
