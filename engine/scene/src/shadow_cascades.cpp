#include <sherpa/scene/scene.h>
#include <sherpa/scene/shadow_cascades.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sherpa::scene {

namespace {

glm::vec3 corner(const core::Aabb& b, int i) {
    return {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
}

} // namespace

CascadeCamera cascade_camera(const CameraSpec& spec) {
    CascadeCamera c;
    c.view = spec.view();
    c.near_plane = spec.near_plane;
    c.far_plane = spec.far_plane;
    c.fov_y = glm::radians(spec.fov_y_degrees);
    c.aspect = spec.aspect;
    return c;
}

std::optional<glm::vec3> main_light_direction(const Scene& scene, glm::vec3 default_sun) {
    for (const PlacedLight& pl : scene.placed_lights)
        if (pl.light < scene.lights.size() && scene.lights[pl.light].type == LightType::Directional)
            return glm::normalize(pl.direction);
    if (scene.placed_lights.empty()) return glm::normalize(default_sun);
    return std::nullopt;
}

core::Aabb drawable_bounds(const Scene& scene) {
    core::Aabb b;
    for (const MeshInstance& inst : scene.instances)
        if (inst.mesh_id < scene.meshes.size() && !scene.meshes[inst.mesh_id].indices.empty())
            b.expand(inst.world_bounds);
    return b;
}

ShadowCascades fit_shadow_cascades(const CascadeCamera& camera, const core::Aabb& scene_bounds,
                                   glm::vec3 light_dir, std::uint32_t cascades,
                                   std::uint32_t resolution) {
    ShadowCascades out;
    if (!scene_bounds.valid() || cascades == 0 || glm::length(light_dir) == 0.0f) return out;
    light_dir = glm::normalize(light_dir);
    cascades = std::min(cascades, kMaxShadowCascades);

    // The depth range worth shadowing: where the scene is, seen from the camera.
    float scene_near = 1e30f, scene_far = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const float d = -(camera.view * glm::vec4(corner(scene_bounds, i), 1.0f)).z;
        scene_near = std::min(scene_near, d);
        scene_far = std::max(scene_far, d);
    }
    const float n = std::max(camera.near_plane, scene_near);
    float f = camera.far_plane > 0.0f ? std::min(camera.far_plane, scene_far) : scene_far;
    if (f <= n * 1.001f) f = n * 1.001f + 1e-3f;

    // One light view for every cascade keeps texel snapping consistent.
    const glm::vec3 center = scene_bounds.center();
    const float scene_radius = std::max(0.5f * glm::length(scene_bounds.extent()), 1e-4f);
    const glm::vec3 up = std::abs(light_dir.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::mat4 light_view =
        glm::lookAtRH(center - light_dir * scene_radius * 2.0f, center, up);
    float z_lo = 1e30f, z_hi = -1e30f; // light-view z of the scene (+z toward the light)
    for (int i = 0; i < 8; ++i) {
        const float z = (light_view * glm::vec4(corner(scene_bounds, i), 1.0f)).z;
        z_lo = std::min(z_lo, z);
        z_hi = std::max(z_hi, z);
    }
    const float depth_margin = 0.01f * scene_radius;

    const glm::mat4 inv_view = glm::inverse(camera.view);
    const float tan_y = std::tan(0.5f * camera.fov_y);
    float slice_near = n;
    for (std::uint32_t c = 0; c < cascades; ++c) {
        // Practical split scheme: mostly logarithmic, partly uniform.
        const float s = float(c + 1) / float(cascades);
        const float log_split = n * std::pow(f / n, s);
        const float uniform_split = n + (f - n) * s;
        const float slice_far = 0.8f * log_split + 0.2f * uniform_split;

        glm::vec3 corners[8];
        glm::vec3 mid(0.0f);
        float slice_z_lo = 1e30f; // light-view z of the slice point farthest from the light
        for (int i = 0; i < 8; ++i) {
            const float d = (i & 4) ? slice_far : slice_near;
            const float hh = camera.orthographic ? camera.ortho_half_height : tan_y * d;
            const float hw = camera.orthographic ? camera.ortho_half_width : hh * camera.aspect;
            const glm::vec4 p_view((i & 1) ? hw : -hw, (i & 2) ? hh : -hh, -d, 1.0f);
            corners[i] = glm::vec3(inv_view * p_view);
            mid += corners[i] / 8.0f;
            slice_z_lo = std::min(slice_z_lo, (light_view * glm::vec4(corners[i], 1.0f)).z);
        }
        float radius = 0.0f;
        for (const glm::vec3& p : corners) radius = std::max(radius, glm::length(p - mid));
        if (radius > scene_radius) { // never wider than the scene needs
            radius = scene_radius * 1.01f;
            mid = center;
        }
        radius = std::ceil(radius * 16.0f) / 16.0f; // stable size as the camera turns

        const float texel = 2.0f * radius / float(resolution);
        glm::vec3 lc = glm::vec3(light_view * glm::vec4(mid, 1.0f));
        lc.x = std::floor(lc.x / texel) * texel;
        lc.y = std::floor(lc.y / texel) * texel;
        const float near_z = -z_hi - depth_margin, far_z = -z_lo + depth_margin;
        const glm::mat4 proj = glm::orthoRH_ZO(lc.x - radius, lc.x + radius, lc.y - radius,
                                               lc.y + radius, near_z, far_z);
        out.view_proj[c] = proj * light_view;
        // Receivers sit in the slice; shading looks up 1.5 texels along the normal.
        const float cull_far =
            std::clamp(-slice_z_lo + depth_margin + 4.0f * texel, near_z + 1e-4f, far_z);
        out.cull_view_proj[c] = glm::orthoRH_ZO(lc.x - radius, lc.x + radius, lc.y - radius,
                                                lc.y + radius, near_z, cull_far) *
                                light_view;
        out.splits[c] = slice_far;
        out.texel[c] = texel;
        slice_near = slice_far;
    }
    out.count = cascades;
    return out;
}

} // namespace sherpa::scene
