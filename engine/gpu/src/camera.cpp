#include <sherpa/gpu/camera.h>
#include <sherpa/scene/camera_spec.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace sherpa::gpu {

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
    sherpa::CameraSpec parsed;
    std::string parse_error;
    if (!sherpa::parse_camera_spec(text, parsed, parse_error)) {
        error = "camera '" + std::string(text) + "': " + parse_error;
        return false;
    }
    spec = explicit_camera(parsed);
    return true;
}

CameraSpec explicit_camera(const sherpa::CameraSpec& camera) {
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
    return perspective_reverse_z(fov_y, aspect, n, f);
}

glm::mat4 reverse_z_orthographic(float hw, float hh, float n, float f) {
    return orthographic_reverse_z(hw, hh, n, f);
}

CascadeCamera cascade_camera(const CameraView& v) {
    CascadeCamera c;
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

CameraView resolve_camera(const CameraSpec& spec, const Scene& scene, float viewport_aspect) {
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
        if (spec.gltf_index >= scene.placed_cameras.size())
            throw std::invalid_argument("camera gltf:" + std::to_string(spec.gltf_index) +
                                        ": the scene places " +
                                        std::to_string(scene.placed_cameras.size()) + " camera(s)");
        const PlacedCamera& pc = scene.placed_cameras[spec.gltf_index];
        const Camera& cam = scene.cameras.at(pc.camera);
        // The node transform may scale; the view keeps only rotation and position.
        glm::mat4 world = pc.world;
        for (int c = 0; c < 3; ++c) world[c] = glm::vec4(glm::normalize(glm::vec3(world[c])), 0.0f);
        v.view = glm::inverse(world);
        v.position = glm::vec3(pc.world[3]);
        v.near_plane = cam.znear > 0.0f ? cam.znear : 0.05f;
        v.far_plane = cam.zfar;
        if (spec.aspect <= 0.0f && cam.aspect > 0.0f) v.aspect = cam.aspect;
        if (cam.type == CameraType::Orthographic) {
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
        // Look from the front (+Z, as glTF sample screenshots do), raised by about 17
        // degrees so ground planes do not collapse to a line; back off until all 8
        // corners of the bounds fit the frustum.
        const Aabb b =
            scene.bounds.valid() ? scene.bounds : Aabb::from_min_max(glm::vec3(-1), glm::vec3(1));
        const glm::vec3 c = b.center();
        const float r = std::max(0.5f * glm::length(b.extent()), 1e-4f);
        v.fov_y = glm::radians(spec.fov_degrees);
        const float tan_y = std::tan(0.5f * v.fov_y), tan_x = tan_y * v.aspect;
        const glm::vec3 back = glm::normalize(glm::vec3(0.0f, 0.3f, 1.0f));
        const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), back));
        const glm::vec3 up = glm::cross(back, right);
        float d = 0.0f;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 p{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                              (i & 4) ? b.max.z : b.min.z};
            const glm::vec3 rel = p - c;
            const float z = glm::dot(rel, back);
            d = std::max({d, z + std::abs(glm::dot(rel, right)) / tan_x,
                          z + std::abs(glm::dot(rel, up)) / tan_y});
        }
        d = std::max(d * 1.05f, 1e-3f);
        v.position = c + back * d;
        v.view = glm::lookAtRH(v.position, c, glm::vec3(0.0f, 1.0f, 0.0f));
        v.near_plane = std::clamp(0.5f * (d - r), 1e-4f, spec.near_plane);
        v.far_plane = 0.0f;
        break;
    }
    }
    v.proj = v.orthographic ? reverse_z_orthographic(v.ortho_half_width, v.ortho_half_height,
                                                     v.near_plane, v.far_plane)
                            : reverse_z_perspective(v.fov_y, v.aspect, v.near_plane, v.far_plane);
    return v;
}

} // namespace sherpa::gpu
