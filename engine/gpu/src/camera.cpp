#include <sherpa/gpu/camera.h>
#include <sherpa/scene/camera_spec.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace sherpa::gpu {

namespace {

bool parse_float(std::string_view s, float& out) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

bool parse_vec3(std::string_view s, glm::vec3& out) {
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = s.find(',');
        if ((i < 2) != (comma != std::string_view::npos)) return false;
        if (!parse_float(s.substr(0, comma), out[i])) return false;
        if (i < 2) s.remove_prefix(comma + 1);
    }
    return true;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> out;
    while (true) {
        const std::size_t at = s.find(sep);
        out.push_back(s.substr(0, at));
        if (at == std::string_view::npos) return out;
        s.remove_prefix(at + 1);
    }
}

} // namespace

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
    spec.kind = CameraSpec::Kind::Explicit;
    bool have_eye = false, have_target = false;
    for (std::string_view field : split(text, ':')) {
        const std::size_t eq = field.find('=');
        const std::string_view key = field.substr(0, eq);
        const std::string_view value =
            eq == std::string_view::npos ? std::string_view() : field.substr(eq + 1);
        bool ok = eq != std::string_view::npos;
        if (!ok) {
        } else if (key == "eye") {
            ok = parse_vec3(value, spec.eye);
            have_eye = true;
        } else if (key == "target") {
            ok = parse_vec3(value, spec.target);
            have_target = true;
        } else if (key == "up") {
            ok = parse_vec3(value, spec.up) && glm::length(spec.up) > 0.0f;
        } else if (key == "fov") {
            ok = parse_float(value, spec.fov_degrees) && spec.fov_degrees > 0.0f &&
                 spec.fov_degrees < 180.0f;
        } else if (key == "aspect") {
            ok = parse_float(value, spec.aspect) && spec.aspect > 0.0f;
        } else if (key == "near") {
            ok = parse_float(value, spec.near_plane) && spec.near_plane > 0.0f;
        } else if (key == "far") {
            ok = parse_float(value, spec.far_plane) && spec.far_plane >= 0.0f;
        } else {
            error = "camera '" + std::string(text) + "': unknown field '" + std::string(key) + "'";
            return false;
        }
        if (!ok) {
            error = "camera '" + std::string(text) + "': bad value in '" + std::string(field) + "'";
            return false;
        }
    }
    if (!have_eye || !have_target) {
        error = "camera '" + std::string(text) +
                "': needs eye=x,y,z and target=x,y,z (or auto, gltf:N)";
        return false;
    }
    if (spec.far_plane != 0.0f && spec.far_plane <= spec.near_plane) {
        error = "camera '" + std::string(text) + "': far must exceed near";
        return false;
    }
    const glm::vec3 dir = spec.target - spec.eye;
    if (glm::length(dir) == 0.0f ||
        glm::length(glm::cross(dir, spec.up)) < 1e-6f * glm::length(dir)) {
        error =
            "camera '" + std::string(text) + "': eye equals target or up is parallel to the view";
        return false;
    }
    return true;
}

// One convention for the whole engine: the scene layer's (camera_spec.h).
glm::mat4 reverse_z_perspective(float fov_y, float aspect, float n, float f) {
    return perspective_reverse_z(fov_y, aspect, n, f);
}

glm::mat4 reverse_z_orthographic(float hw, float hh, float n, float f) {
    return orthographic_reverse_z(hw, hh, n, f);
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
