#include <sherpa/scene/camera_spec.h>

#include <charconv>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace sherpa::scene {
namespace {

bool parse_floats(std::string_view s, float* out, int n) {
    for (int i = 0; i < n; ++i) {
        const std::size_t comma = s.find(',');
        const std::string_view part = i + 1 < n ? s.substr(0, comma) : s;
        if ((i + 1 < n) == (comma == std::string_view::npos)) return false;
        const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), out[i]);
        if (ec != std::errc{} || end != part.data() + part.size() || !std::isfinite(out[i]))
            return false;
        if (i + 1 < n) s.remove_prefix(comma + 1);
    }
    return true;
}

} // namespace

glm::mat4 perspective_reverse_z(float fov_y, float aspect, float n, float f) {
    const float g = 1.0f / std::tan(0.5f * fov_y);
    glm::mat4 p(0.0f);
    p[0][0] = g / aspect;
    p[1][1] = g;
    p[2][3] = -1.0f; // w_clip = -z_view
    if (f > 0.0f && std::isfinite(f)) {
        p[2][2] = n / (f - n); // depth = 1 at -near, 0 at -far
        p[3][2] = n * f / (f - n);
    } else {
        p[2][2] = 0.0f; // depth = near / -z_view: 1 at near, -> 0 at infinity
        p[3][2] = n;
    }
    return p;
}

glm::mat4 orthographic_reverse_z(float xmag, float ymag, float n, float f) {
    glm::mat4 p(1.0f);
    p[0][0] = 1.0f / xmag;
    p[1][1] = 1.0f / ymag;
    p[2][2] = 1.0f / (f - n); // depth = (z_view + f) / (f - n): 1 at -near, 0 at -far
    p[3][2] = f / (f - n);
    return p;
}

glm::mat4 CameraSpec::view() const {
    return glm::lookAt(eye, target, up);
}

glm::mat4 CameraSpec::projection() const {
    return perspective_reverse_z(glm::radians(fov_y_degrees), aspect, near_plane, far_plane);
}

bool parse_camera_spec(std::string_view text, CameraSpec& out, std::string& error) {
    CameraSpec c;
    bool have_eye = false, have_target = false;
    while (!text.empty()) {
        const std::size_t colon = text.find(':');
        const std::string_view item = text.substr(0, colon);
        text = colon == std::string_view::npos ? std::string_view{} : text.substr(colon + 1);
        const std::size_t eq = item.find('=');
        if (eq == std::string_view::npos) {
            error = "camera: '" + std::string(item) + "' is not key=value";
            return false;
        }
        const std::string_view key = item.substr(0, eq), value = item.substr(eq + 1);
        bool ok = true;
        if (key == "eye")
            ok = have_eye = parse_floats(value, &c.eye.x, 3);
        else if (key == "target")
            ok = have_target = parse_floats(value, &c.target.x, 3);
        else if (key == "up")
            ok = parse_floats(value, &c.up.x, 3);
        else if (key == "fov")
            ok = parse_floats(value, &c.fov_y_degrees, 1);
        else if (key == "aspect")
            ok = c.aspect_given = parse_floats(value, &c.aspect, 1);
        else if (key == "near")
            ok = parse_floats(value, &c.near_plane, 1);
        else if (key == "far")
            ok = parse_floats(value, &c.far_plane, 1);
        else {
            error = "camera: unknown key '" + std::string(key) +
                    "' (eye, target, up, fov, aspect, near, far)";
            return false;
        }
        if (!ok) {
            error =
                "camera: bad value for '" + std::string(key) + "': '" + std::string(value) + "'";
            return false;
        }
    }
    if (!have_eye || !have_target)
        error = "camera: needs eye=x,y,z and target=x,y,z";
    else if (glm::length(c.target - c.eye) <= 0.0f)
        error = "camera: eye and target coincide";
    else if (glm::length(glm::cross(glm::normalize(c.target - c.eye), c.up)) < 1e-6f)
        error = "camera: up is parallel to the view direction (or zero)";
    else if (!(c.fov_y_degrees > 0.0f && c.fov_y_degrees < 180.0f))
        error = "camera: fov must be in (0, 180) degrees";
    else if (!(c.aspect > 0.0f))
        error = "camera: aspect must be > 0";
    else if (!(c.near_plane > 0.0f))
        error = "camera: near must be > 0";
    else if (c.far_plane != 0.0f && !(c.far_plane > c.near_plane))
        error = "camera: far must be > near (or 0 for infinite)";
    else {
        out = c;
        return true;
    }
    return false;
}

} // namespace sherpa::scene
